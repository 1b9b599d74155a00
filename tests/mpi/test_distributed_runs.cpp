// One scene on several processes ends in the same state, to the bit, as on one (issue 32; fluid/domain.hpp): every
// particle's position, velocity, pressure and number density by id, and the step count and time. Each process owns
// the particles of its cells (fluid/cell_partition.hpp) and holds the others within reach as ghosts
// (fluid/process_halo.hpp); neighbour sums run in id order and sums over particles are exact, so the split does not
// show. Run by Mpi.OnProcesses1..4 (CMakeLists.txt): on one process the same calls take the single-process path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <numeric>
#include <tuple>
#include <string>
#include <vector>

#include "tests/mpi/world.hpp"
#include "tests/scene_runner.hpp"

namespace slide::testing {
namespace {

// The owned particles' state, by id, gathered on process 0 (empty elsewhere).
template <int D>
struct Gathered {
  std::vector<ParticleId> id;
  std::vector<double> numbers;  // per particle: position, velocity, pressure, number density
};

template <int D>
Gathered<D> gather_by_id(const Simulation<D>& sim, const Communicator& comm) {
  const auto& P = sim.particles();
  constexpr std::size_t per = 1 + 2 * D + 2;  // id's bits, then the numbers
  std::vector<double> mine;
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    double id_bits;
    std::memcpy(&id_bits, &P.id[i], sizeof(double));
    mine.push_back(id_bits);
    mine.insert(mine.end(), P.position[i].data(), P.position[i].data() + D);
    mine.insert(mine.end(), P.velocity[i].data(), P.velocity[i].data() + D);
    mine.push_back(P.pressure[i]);
    mine.push_back(P.number_density[i]);
  }
  const std::vector<double> all = gather_on_first(comm, mine);
  const std::size_t n = all.size() / per;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  const auto id_of = [&](std::size_t k) {
    ParticleId id;
    std::memcpy(&id, &all[k * per], sizeof(id));
    return id;
  };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return id_of(a) < id_of(b); });
  Gathered<D> g;
  for (const std::size_t k : order) {
    g.id.push_back(id_of(k));
    g.numbers.insert(g.numbers.end(), all.begin() + static_cast<std::ptrdiff_t>(k * per + 1),
                     all.begin() + static_cast<std::ptrdiff_t>((k + 1) * per));
  }
  return g;
}

template <int D>
void expect_split_changes_nothing(const std::string& scene_file, const std::vector<std::string>& overrides,
                                  double end_time) {
  const Communicator& comm = *world();
  const auto run = [&](std::shared_ptr<const Communicator> processes) {
    auto scene = load_shipped_scene<D>(scene_file, overrides);
    Simulation<D>& sim = *scene->simulation;
    sim.set_communicator(processes);
    sim.initialise();  // each process keeps its share
    EXPECT_TRUE(run_scene<D>(*scene, [](const Simulation<D>&) {}, end_time)) << scene_file;
    const double imbalance = sim.domain().imbalance();
    std::int64_t left = static_cast<std::int64_t>(sim.left_the_domain().size());  // each process's own leavers
    processes->sum(&left, 1);
    return std::tuple{gather_by_id<D>(sim, *processes), sim.step_count(), sim.time(), sim.neighbor_rebuilds(), imbalance,
                      left};
  };
  // The reference: the whole scene on each process alone; only process 0's is compared.
  const auto [one, one_steps, one_time, one_rebuilds, one_imbalance, one_left] =
      run(std::make_shared<SerialCommunicator>());
  const auto [split, steps, time, rebuilds, imbalance, left] = run(world());
  EXPECT_EQ(left, one_left) << scene_file;
  EXPECT_EQ(steps, one_steps) << scene_file;
  EXPECT_EQ(time, one_time) << scene_file;
  EXPECT_GE(rebuilds, 3) << scene_file;  // particles moved between processes' cells, not only at the start
  EXPECT_LT(imbalance, 1.6) << scene_file;
  if (comm.rank() != 0) return;
  ASSERT_EQ(split.id, one.id) << scene_file;  // no particle lost or doubled
  EXPECT_EQ(0, std::memcmp(split.numbers.data(), one.numbers.data(), one.numbers.size() * sizeof(double)))
      << scene_file << " on " << comm.size() << " processes";
}

TEST(Processes, DamBreakIsTheSameOnAnyNumberOfProcesses) {
  expect_split_changes_nothing<2>("dam_break_2d.yaml", {"output.snapshots=false"}, 0.05);
}

// A thin layer of water on the floor of a low tank in a tall domain: the cells are cut across y, and most of the
// particles lie in the first cells above and below the floor, so the first cut runs a cell or two above it, where the
// mirror images of the floor's boundary particles (fluid/wall_pressure.hpp) lie in the other process's cells (the
// halo's reach: Simulation::prepare_processes). Gravity tilted, so that the water sloshes.
TEST(Processes, WaterOnAFloorCutJustAboveItIsTheSame) {
  expect_split_changes_nothing<2>("hydrostatic_2d.yaml",
                                  {"output.snapshots=false", "method.initial_state=lattice", "lattice=square",
                                   "method.wall_pressure=mirror", "walls[0].points=[[0,0.1],[0,0],[0.1,0],[0.1,0.1]]",
                                   "fluid.regions[0].level=0.05", "gauges=[]", "domain.min=[-0.05,-0.05]",
                                   "domain.max=[0.15,1.0]", "gravity=[3,-9.81]", "method.sound_speed_factor=10"},
                                  0.1);
}

// The dam break's floor ends at x = 2a, the domain at 0.14 m with no wall: from t = 0.097 s water runs off the end and
// leaves the run (111 particles by 0.15 s, measured on one process), on whichever process holds it.
TEST(Processes, WaterLeavingThroughAnOpenEndIsTheSame) {
  expect_split_changes_nothing<2>("dam_break_2d.yaml",
                                  {"output.snapshots=false", "walls[0].points=[[0,0.17145],[0,0],[0.1143,0]]",
                                   "domain.min=[-0.02,-0.02]", "domain.max=[0.14,0.2]", "gauges=[]",
                                   "diagnostics.surge_front.enabled=false"},
                                  0.15);
}

TEST(Processes, PeriodicChannelCutAcrossItsSeamIsTheSame) {
  // Water (the explicit scheme's time step under the HB's viscosity at rest would be thousands of steps), driven
  // fast enough to cross the period's seam and re-sort several times; ten times as long (0.4 m) as it is high, so
  // that the processes' cells are cut across x and the seam joins the last process's cells to the first's.
  expect_split_changes_nothing<2>("hb_poiseuille_2d.yaml",
                                  {"output.snapshots=false", "method.viscous_scheme=explicit", "domain.max=[0.4,0.15]",
                                   "fluid.regions[0].max=[0.4,0.1]", "walls[0].points=[[0.0025,0.0],[0.3975,0.0]]",
                                   "walls[1].points=[[0.3975,0.1],[0.0025,0.1]]",
                                   "fluid.phases[0].rheology={model: newtonian, viscosity: 0.001}", "gravity=[5,0]",
                                   "method.sound_speed=10"},
                                  0.1);
}

TEST(Processes, DamBreakIn3DIsTheSame) {
  expect_split_changes_nothing<3>("dam_break_3d.yaml", {"output.snapshots=false", "particle_spacing=0.005715"}, 0.03);
}

TEST(Processes, DamBreakBetweenPlanesOfSymmetryIn3DIsTheSame) {
  expect_split_changes_nothing<3>("dam_break_bench_3d.yaml", {"output.snapshots=false", "particle_spacing=0.02"},
                                  0.02);
}

}  // namespace
}  // namespace slide::testing
