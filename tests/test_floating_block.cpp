// Floating block (cases/floating_block_2d.yaml): a 0.2 m x 0.1 m box of 500 kg/m^3 released at its exact draft.
// Force balance and draft against Archimedes; a block of water density stays where it is put.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/free_surface_gauge.hpp"
#include "coupling/rigid_bodies.hpp"
#include "tests/scene_runner.hpp"

namespace slide::testing {
namespace {

struct FloatResult {
  double mean_force_y = 0.0;    // N/m, fluid force on the block, mean over the averaging window
  double weight = 0.0;          // N/m
  double draft = 0.0;           // m: mean water level at the gauges minus the block's bottom face, same window
  double max_displacement = 0.0;  // m, of the centre of mass from its start
  double height = 0.0;
};

// Runs the floating-block case with overrides, averaging from t_average on.
FloatResult run_block(const std::vector<std::string>& overrides, double t_average) {
  auto scene = load_shipped_scene("floating_block_2d.yaml", overrides);
  auto& sim = *scene->simulation;
  auto& bodies = *sim.bodies;
  const double g = -sim.options.gravity[1];
  FloatResult r;
  r.weight = bodies.world.mass(0) * g;
  r.height = 0.1;
  const auto start = bodies.state(0).position;
  double force_sum = 0.0, draft_sum = 0.0, time_sum = 0.0;
  run_scene(*scene, [&](const Simulation<2>& s) {
    const auto st = bodies.state(0);
    r.max_displacement = std::max(r.max_displacement, (st.position - start).norm());
    if (s.time < t_average) return;
    // A step's force acts over its dt: weight the samples by dt (the step is variable).
    const double dt = s.time - time_sum - t_average;
    time_sum += dt;
    force_sum += dt * bodies.force[0].total()[1];
    double level = 0.0;
    for (const auto& gauge : scene->gauges) level += free_surface_elevation<2>(s, Vec<2>(gauge.x, 0.0));
    level /= scene->gauges.size();
    draft_sum += dt * (level - (st.position[1] - 0.5 * r.height));
  });
  r.mean_force_y = force_sum / time_sum;
  r.draft = draft_sum / time_sum;
  return r;
}

TEST(FloatingBlock, FluidForceBalancesWeight) {
  const FloatResult r = run_block({}, 1.0);
  const double exact_draft = 500.0 / 1000.0 * r.height;
  std::printf("floating block, 1-2 s: fluid force / weight - 1 = %+.3f %%, draft %.5f m (exact %.5f, %+.2f %%), "
              "largest displacement %.2f mm\n",
              100 * (r.mean_force_y / r.weight - 1), r.draft, exact_draft, 100 * (r.draft / exact_draft - 1),
              1000 * r.max_displacement);
  EXPECT_NEAR(r.mean_force_y, r.weight, 0.01 * r.weight);
  // The block stays afloat near its draft (the 1 % target on the draft itself is DISABLED_DraftWithinOnePercent).
  EXPECT_NEAR(r.draft, exact_draft, 0.1 * exact_draft);
}

// The draft target. Not met: against the water's edge at the gauges the block floats 3.9 mm high (-7.9 %).
// The pressure field of the settled square-lattice water reads as if the surface stood about half a spacing above
// that edge (floor pressure / rho g + y: 0.3023 m; edge: 0.2963 m), and the block floats on that pressure. Giving the
// surface particles the hydrostatic pressure of their centres' depth instead of 0 made that offset larger, not
// smaller (issue 4's closing note): where it comes from in the (p_i + p_j) force balance of the top rows is still
// open. (The gauge's earlier threshold, n0 / 2, read the edge 0.3 dp high and hid most of it: -1.9 %.)
// Kept, disabled, so that it stays visible.
TEST(FloatingBlock, DISABLED_DraftWithinOnePercent) {
  const FloatResult r = run_block({}, 1.0);
  EXPECT_NEAR(r.draft, 0.05, 0.0005);
}

TEST(FloatingBlock, WaterDensityBlockStaysWhereItIsPut) {
  // Fully submerged, centre 0.15 m below the surface, released at once.
  const FloatResult r = run_block({"bodies[0].density=1000", "bodies[0].shape.center=[0.5, 0.15]",
                                   "end_time=1.0"},
                                  0.5);
  std::printf("neutral block, 1 s: largest displacement %.2f mm, fluid force / weight - 1 = %+.3f %%\n",
              1000 * r.max_displacement, 100 * (r.mean_force_y / r.weight - 1));
  EXPECT_LT(r.max_displacement, 0.5 * 0.01);  // half a particle spacing
  EXPECT_NEAR(r.mean_force_y, r.weight, 0.01 * r.weight);
}

}  // namespace
}  // namespace slide::testing
