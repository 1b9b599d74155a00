// The hydrostatic start (fluid/hydrostatic_start.hpp) beside a convex corner: still water over a step on the tank's
// floor. Each column of water is compressed up from what it stands on; the step's top must stay where the water on
// it starts, or the water there starts with a number-density deficit (zero pressure at t = 0).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cases/scene.hpp"
#include "tests/cli_helpers.hpp"

namespace slide::testing {
namespace {

// 0.5 m of water in a 1 m tank with a 0.2 m x 0.2 m step in the middle of its floor; square lattice, dp = 0.01.
std::unique_ptr<cases::Scene<2>> step_scene() {
  const auto dir = fresh_directory("hydrostatic_step");
  write_file(dir / "step.yaml", R"(description: still water over a step
particle_spacing: 0.01
end_time: 0.1
fluid:
  phases:
    - name: water
      density: 1000
      rheology: {model: newtonian, viscosity: 1.0e-3}
  regions:
    - type: below_level
      level: 0.5
walls:
  - name: tank
    points: [[0, 0.9], [0, 0], [0.4, 0], [0.4, 0.2], [0.6, 0.2], [0.6, 0], [1.0, 0], [1.0, 0.9]]
lattice: square
method:
  initial_state: hydrostatic
)");
  return cases::build_scene<2>(cases::load_scene(dir / "step.yaml", {}), "step", dir);
}

// Measured before the support rule: the water on the step's top, beside its corners, started at n / n0 = 0.943
// (the step's top rows had taken the shift of the deeper column beside the corner, 0.9 mm down) and at zero
// pressure. Now: within 0.1 % of the water at the same height away from the step.
TEST(HydrostaticStart, WaterOnAStepStartsWithTheNumberDensityOfItsDepth) {
  const auto scene = step_scene();
  const auto& sim = *scene->simulation;
  const auto& P = sim.particles();
  const double dp = 0.01, n0 = sim.lattice.n0;
  // The first row on the step's top, and the same row over the deep water beside the step (same depth below the
  // surface, so the same compression).
  double worst_on_step = 1.0, deep = 0.0;
  int on_step = 0, beside = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::fluid || std::abs(P.position[i][1] - 0.205) > 0.3 * dp) continue;
    const double x = P.position[i][0], ratio = P.number_density[i] / n0;
    if (x > 0.4 && x < 0.6) {
      worst_on_step = std::abs(ratio - 1.0) > std::abs(worst_on_step - 1.0) ? ratio : worst_on_step;
      ++on_step;
    } else if (x > 0.1 && x < 0.3) {
      deep += ratio;
      ++beside;
    }
  }
  ASSERT_EQ(on_step, 20);
  ASSERT_GT(beside, 0);
  deep /= beside;
  std::printf("hydrostatic start over a step: n / n0 on the step's top row %.5f at worst, beside it %.5f\n",
              worst_on_step, deep);
  EXPECT_NEAR(worst_on_step, deep, 1e-3);
  // The step's top face particles (normal up, under the water on the step) keep their places: half a spacing,
  // one and a half, two and a half below the face.
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] != Kind::fluid && P.wall_normal[i][1] > 0.99 && P.position[i][0] > 0.4 && P.position[i][0] < 0.6 &&
        P.position[i][1] > 0.17) {
      const double below_face = 0.2 - P.position[i][1];
      EXPECT_NEAR(below_face, (std::round(below_face / dp - 0.5) + 0.5) * dp, 1e-12) << "x = " << P.position[i][0];
    }
}

}  // namespace
}  // namespace slide::testing
