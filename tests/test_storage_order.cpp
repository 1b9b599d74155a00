// Results do not depend on where the particles are stored (DESIGN.md, "One domain seam"; issue 32): a shipped scene run
// with its owned particles stored in a random order after every re-sort (Simulation::shuffle_storage_after_sorting),
// as one process's share of them is stored in its own order, ends in the same state to the bit as the run stored in
// cell order: every particle's position, velocity, pressure and number density, by id, and every body's pose and
// velocity. Each neighbour sum runs in cell-then-id order (fluid/neighbor_grid.hpp, bin with a key), sums over
// particles are exact (fluid/exact_sum.hpp), and the implicit viscous solve numbers its unknowns by id.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "coupling/rigid_bodies.hpp"
#include "tests/bit_pattern.hpp"
#include "tests/scene_runner.hpp"
#include "tools/run_outputs.hpp"

namespace slide::testing {
namespace {

// Every body's pose and velocity, as numbers.
template <int D>
std::vector<double> body_numbers(const Simulation<D>& sim) {
  std::vector<double> v;
  if (!sim.bodies()) return v;
  for (std::size_t b = 0; b < sim.bodies()->size(); ++b) {
    const auto s = sim.bodies()->state(static_cast<int>(b));
    v.insert(v.end(), s.position.data(), s.position.data() + s.position.size());
    v.insert(v.end(), s.velocity.data(), s.velocity.data() + s.velocity.size());
    if constexpr (D == 2) {
      v.push_back(s.angle);
      v.push_back(s.angular_velocity);
    } else {
      v.insert(v.end(), s.orientation.coeffs().data(), s.orientation.coeffs().data() + 4);
      v.insert(v.end(), s.angular_velocity.data(), s.angular_velocity.data() + 3);
    }
  }
  return v;
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

template <int D>
void expect_storage_order_changes_nothing(const std::string& scene_file, const std::vector<std::string>& overrides,
                                          double end_time, bool expect_bodies = false, bool expect_solves = false) {
  struct Result {
    tools::IdOrdered<D> particles;
    std::vector<double> bodies;
    long steps = 0, rebuilds = 0, solves = 0;
  };
  auto run = [&](bool shuffled) {
    auto scene = load_shipped_scene<D>(scene_file, overrides);
    if (shuffled) scene->simulation->shuffle_storage_after_sorting(17);
    EXPECT_TRUE(run_scene<D>(*scene, [](const Simulation<D>&) {}, end_time));
    const Simulation<D>& sim = *scene->simulation;
    return Result{tools::IdOrdered<D>(sim.particles()), body_numbers(sim), sim.step_count(), sim.neighbor_rebuilds(),
                  sim.viscous_solves().solves};
  };
  const Result sorted = run(false), shuffled = run(true);
  EXPECT_GE(sorted.rebuilds, 2) << scene_file;  // each re-sort shuffles: at the start and at least once more
  EXPECT_EQ(sorted.steps, shuffled.steps) << scene_file;
  EXPECT_EQ(sorted.particles.id, shuffled.particles.id) << scene_file;
  EXPECT_TRUE(same_bits(sorted.particles.position, shuffled.particles.position)) << scene_file;
  EXPECT_TRUE(same_bits(sorted.particles.velocity, shuffled.particles.velocity)) << scene_file;
  EXPECT_TRUE(same_bits(sorted.particles.pressure, shuffled.particles.pressure)) << scene_file;
  EXPECT_TRUE(same_bits(sorted.particles.number_density, shuffled.particles.number_density)) << scene_file;
  EXPECT_EQ(!sorted.bodies.empty(), expect_bodies) << scene_file;
  EXPECT_TRUE(same_bits(sorted.bodies, shuffled.bodies)) << scene_file;
  if (expect_solves) EXPECT_GT(sorted.solves, 0) << scene_file;
}

const std::vector<std::string> short_start{"method.settling_time=0.02", "output.snapshots=false"};

std::vector<std::string> with(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

TEST(StorageOrder, DamBreakIsTheSameWhateverTheStorageOrder) {
  expect_storage_order_changes_nothing<2>("dam_break_2d.yaml", with(short_start, {"particle_spacing=0.005"}), 0.08);
}

// A body: its force and torque are sums over its boundary particles.
TEST(StorageOrder, FloatingBlockIsTheSameWhateverTheStorageOrder) {
  expect_storage_order_changes_nothing<2>("floating_block_2d.yaml", with(short_start, {"particle_spacing=0.02"}), 0.05,
                                          true);
}

// A Herschel-Bulkley slide: the implicit viscous solve.
TEST(StorageOrder, SedimentSlideWithTheImplicitSolveIsTheSameWhateverTheStorageOrder) {
  expect_storage_order_changes_nothing<2>("rzadkiewicz_slide_2d.yaml", with(short_start, {"particle_spacing=0.02"}),
                                          0.03, false, true);
}

// Periodic images (a channel periodic in x).
TEST(StorageOrder, PeriodicChannelIsTheSameWhateverTheStorageOrder) {
  expect_storage_order_changes_nothing<2>("hb_poiseuille_2d.yaml", {"output.snapshots=false"}, 0.3);
}

// 3-D: a floating sphere between two planes of symmetry (mirror images), a rigid body.
TEST(StorageOrder, Sphere3DBetweenMirrorsIsTheSameWhateverTheStorageOrder) {
  expect_storage_order_changes_nothing<3>("kramer2021_sphere_3d.yaml", with(short_start, {"particle_spacing=0.05"}), 0.08,
                                          true);
}

// 3-D: a sediment slide between two planes of symmetry: the implicit solve with mirror images of its unknowns.
TEST(StorageOrder, SedimentSlide3DBetweenMirrorsIsTheSameWhateverTheStorageOrder) {
  expect_storage_order_changes_nothing<3>(
      "rzadkiewicz_slide_3d.yaml",
      {"particle_spacing=0.03", "method.settling_time=0.004", "output.snapshots=false"}, 0.004, false, true);
}

}  // namespace
}  // namespace slide::testing
