// Floating block (cases/floating_block_2d.yaml): a 0.2 m x 0.1 m box of 500 kg/m^3 placed at its exact draft, which
// floats with the water while the water settles. Draft and force balance against Archimedes; a block of water density
// stays where it is put.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/free_surface_gauge.hpp"
#include "coupling/rigid_bodies.hpp"
#include "tests/scene_runner.hpp"

namespace slide::testing {
namespace {

struct FloatResult {
  double mean_force_y = 0.0;      // N/m, fluid force on the block, time mean over the run
  double weight = 0.0;            // N/m
  double draft = 0.0;             // m: mean water level at the gauges minus the block's bottom face, time mean
  double max_displacement = 0.0;  // m, of the centre of mass from where the scene puts it, settling included
};

// Runs the floating-block case with overrides; `placed` is the block's centre as the scene puts it (before settling).
FloatResult run_block(const std::vector<std::string>& overrides, const Vec<2>& placed) {
  auto scene = load_shipped_scene("floating_block_2d.yaml", overrides);
  auto& sim = *scene->simulation;
  auto& bodies = *sim.bodies();
  const double g = -sim.options.gravity[1], height = 0.1;
  FloatResult r;
  r.weight = bodies.world.mass(0) * g;
  const auto displacement = [&] {
    const auto p = bodies.state(0).position;
    return (Vec<2>(p[0], p[1]) - placed).norm();
  };
  r.max_displacement = displacement();
  double force_sum = 0.0, draft_sum = 0.0, time_sum = 0.0;
  run_scene(*scene, [&](const Simulation<2>& s) {
    const auto st = bodies.state(0);
    r.max_displacement = std::max(r.max_displacement, displacement());
    // A step's force acts over its dt: weight the samples by dt (the step is variable).
    const double dt = s.time() - time_sum;
    time_sum += dt;
    force_sum += dt * bodies.force[0].total()[1];
    double level = 0.0;
    for (const auto& gauge : scene->gauges) level += free_surface_elevation<2>(s, Vec<2>(gauge.x, 0.0));
    level /= scene->gauges.size();
    draft_sum += dt * (level - (st.position[1] - 0.5 * height));
  });
  r.mean_force_y = force_sum / time_sum;
  r.draft = draft_sum / time_sum;
  return r;
}

// The targets: draft within 1 % of rho_body / rho_water * height, and the mean fluid force within 1 % of the
// weight. The shipped case (dp = 0.005 m, 10 spacings of draft), 1 s after the settled start.
TEST(FloatingBlock, FloatsAtItsDraftWithTheFluidForceBalancingItsWeight) {
  const FloatResult r = run_block({"end_time=1.0"}, Vec<2>(0.5, 0.3));
  const double exact_draft = 500.0 / 1000.0 * 0.1;
  std::printf("floating block, 0-1 s: fluid force / weight - 1 = %+.3f %%, draft %.5f m (exact %.5f, %+.2f %%), "
              "largest displacement from where it was put %.2f mm\n",
              100 * (r.mean_force_y / r.weight - 1), r.draft, exact_draft, 100 * (r.draft / exact_draft - 1),
              1000 * r.max_displacement);
  EXPECT_NEAR(r.mean_force_y, r.weight, 0.01 * r.weight);
  EXPECT_NEAR(r.draft, exact_draft, 0.01 * exact_draft);
}

TEST(FloatingBlock, WaterDensityBlockStaysWhereItIsPut) {
  // Fully submerged, centre 0.15 m below the surface; dp = 0.01 m to keep the test short.
  const FloatResult r = run_block({"particle_spacing=0.01", "bodies[0].density=1000",
                                   "bodies[0].shape.center=[0.5, 0.15]", "end_time=1.0"},
                                  Vec<2>(0.5, 0.15));
  std::printf("neutral block, settling and 1 s: largest displacement %.2f mm, fluid force / weight - 1 = %+.3f %%\n",
              1000 * r.max_displacement, 100 * (r.mean_force_y / r.weight - 1));
  EXPECT_LT(r.max_displacement, 0.5 * 0.01);  // half a particle spacing
  EXPECT_NEAR(r.mean_force_y, r.weight, 0.01 * r.weight);
}

}  // namespace
}  // namespace slide::testing
