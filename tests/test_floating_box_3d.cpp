// Floating box in 3-D (cases/floating_box_3d.yaml): a 0.16 m x 0.16 m x 0.1 m box of 500 kg/m^3 placed at its
// Archimedes draft, floating with the water while it settles, then 1 s at rest. Draft and force balance against
// Archimedes: a Bullet solid in six degrees of freedom coupled with the 3-D fluid.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/free_surface_gauge.hpp"
#include "coupling/rigid_bodies.hpp"
#include "tests/scene_runner.hpp"

namespace slide::testing {
namespace {

struct FloatResult3D {
  double mean_force_z = 0.0;      // N, fluid force on the box, time mean over the run
  double weight = 0.0;            // N
  double draft = 0.0;             // m: mean water level at the gauges minus the box's bottom face, time mean
  double largest_tilt = 0.0;      // rad, the largest rotation from upright
  double largest_drift = 0.0;     // m, the largest horizontal displacement of the centre of mass
};

FloatResult3D run_box(const std::vector<std::string>& overrides) {
  auto scene = load_shipped_scene<3>("floating_box_3d.yaml", overrides);
  auto& sim = *scene->simulation;
  auto& bodies = *sim.bodies();
  const double g = -sim.options.gravity[2], height = 0.1;
  FloatResult3D r;
  r.weight = bodies.world.mass(0) * g;
  const Vec<3> start = bodies.state(0).position;
  double force_sum = 0.0, draft_sum = 0.0, time_sum = 0.0;
  EXPECT_TRUE(run_scene<3>(*scene, [&](const Simulation<3>& s) {
    const auto st = bodies.state(0);
    const double dt = s.time() - time_sum;  // a step's force acts over its dt
    time_sum += dt;
    force_sum += dt * bodies.force[0].total()[2];
    double level = 0.0;
    for (const auto& gauge : scene->gauges) level += free_surface_elevation<3>(s, Vec<3>(gauge.x, gauge.y, 0.0));
    level /= double(scene->gauges.size());
    draft_sum += dt * (level - (st.position[2] - 0.5 * height));
    r.largest_tilt = std::max(r.largest_tilt, st.orientation.angularDistance(rigid::Quat::Identity()));
    r.largest_drift = std::max(r.largest_drift, Vec<2>(st.position[0] - start[0], st.position[1] - start[1]).norm());
  }));
  r.mean_force_z = force_sum / time_sum;
  r.draft = draft_sum / time_sum;
  return r;
}

// The targets: the draft within 1 % of rho_body / rho_water x height, the fluid force within 0.5 % of the
// weight. The shipped case at dp 0.01 m (5 spacings of draft).
TEST(LongFloatingBox3D, FloatsAtItsDraftWithTheFluidForceBalancingItsWeight) {
  const FloatResult3D r = run_box({});
  const double exact_draft = 500.0 / 1000.0 * 0.1;
  std::printf("floating box 3-D, 0-1 s: fluid force / weight - 1 = %+.3f %%, draft %.5f m (exact %.5f, %+.2f %%), "
              "largest tilt %.4f rad, largest drift %.2f mm\n",
              100 * (r.mean_force_z / r.weight - 1), r.draft, exact_draft, 100 * (r.draft / exact_draft - 1),
              r.largest_tilt, 1000 * r.largest_drift);
  EXPECT_NEAR(r.mean_force_z, r.weight, 0.005 * r.weight);
  EXPECT_NEAR(r.draft, exact_draft, 0.01 * exact_draft);
  EXPECT_LT(r.largest_tilt, 0.02);
}

}  // namespace
}  // namespace slide::testing
