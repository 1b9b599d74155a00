// A column of still water between four planes of symmetry (7 x 7 lattice planes across, 0.159 m deep, fcc, dp 0.01,
// settled 2 s at 3 /s, then 1 s): the smallest scene that holds the water column's vertical acoustic mode, which a
// still 3-D tank wider than 0.1 m rang in at c0 = 10 sqrt(g H) (docs/three-d.md, "The stirring is the column's
// vertical acoustic mode"). The four planes make it an endless sheet of water, so nothing but the depth is left to
// ring. At the 3-D default sound speed (20 sqrt(g H), cases/scene_schema.cpp) the column stays at rest; at the 2-D
// default (10) the same column rings, which is why 3-D scenes take 20. Both halves asserted, so the test fails if the
// mode comes back at the default or if the column stops showing it (the scene no longer a test of it).
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "fluid/lattice.hpp"
#include "tests/scene_runner.hpp"

namespace slide::testing {
namespace {

std::string column_scene() {
  // Whole planes across, so that each plane of symmetry meets the lattice.
  const double side = 7 * row_spacing(LatticeKind::fcc, 0.01);
  return fmt::format(R"(dimension: 3
particle_spacing: 0.01
end_time: 1.0
fluid:
  phases:
    - {{name: water, density: 1000, rheology: {{model: newtonian, viscosity: 1.0e-3}}}}
  regions:
    - {{type: below_level, level: 0.159}}
method: {{surface_pressure: half_layer, settling_time: 2.0, settling_damping: 3.0}}
walls:
  - {{name: tank, type: tank, symmetry: [x_min, x_max, y_min, y_max], min: [0, 0, 0], max: [{0:.17g}, {0:.17g}, 0.3]}}
)",
                     side);
}

// The largest fluid speed over the run after the settling, as a share of sqrt(g H) (H = 0.159 m).
double largest_speed(const std::vector<std::string>& overrides) {
  auto scene = build_scene_text<3>("still_column_3d", column_scene(), overrides);
  const double sqrt_gh = std::sqrt(g * 0.159);
  double largest = 0.0;
  EXPECT_TRUE(run_scene<3>(*scene, [&](const Simulation<3>& sim) {
    const auto& P = sim.particles();
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.kind[i] == Kind::fluid) largest = std::max(largest, P.velocity[i].norm() / sqrt_gh);
  }));
  return largest;
}

TEST(StillColumn3D, TheDefaultSoundSpeedHoldsTheAcousticModeThatTenTimesSqrtGHRingsIn) {
  const double at_default = largest_speed({}), at_ten = largest_speed({"method.sound_speed_factor=10"});
  std::printf("still column 3-D, 1 s: largest speed %.4f %% of sqrt(g H) at the default sound speed, %.2f %% at "
              "c0 = 10 sqrt(g H)\n",
              100 * at_default, 100 * at_ten);
  EXPECT_LT(at_default, 0.001);  // the 3-D still tank's 1 % (issue 31), with room to spare
  EXPECT_GT(at_ten, 0.01);
}

}  // namespace
}  // namespace slide::testing
