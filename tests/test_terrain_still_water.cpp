// Still water over a terrain (walls[].type: terrain, cases/terrain_layers.hpp) stays at rest: a 15 degree slope in a
// 0.3 m x 0.1 m tank, water to 0.2 m, dp 0.02, settled 3 s at 3 /s, then 1 s. Issue 31 asks still water to keep its
// largest speed under 1 % of sqrt(g H) over 1 s (as tests/test_hydrostatic_3d.cpp asks of the flat tank).
// Measured: 0.027 %. With the terrain's layers laid along its surface as fcc (111) planes (before stop 44) this test
// measured 3.72 % (and the same tank at dp 0.01 5.8 %; on the water's own lattice 0.027 %: docs/three-d.md).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>

#include "cases/scene.hpp"
#include "tests/scene_runner.hpp"

namespace slide::testing {
namespace {

TEST(Terrain3D, StillWaterOverASlopeStaysAtRest) {
  const auto dir = fresh_directory("terrain_still_water");
  const double slope = std::tan(15.0 * M_PI / 180.0);
  write_file(dir / "slope.csv", fmt::format("y\\x,0,0.3\n0,{0},0.02\n0.1,{0},0.02\n", 0.02 + 0.3 * slope));
  write_file(dir / "s.yaml", R"(dimension: 3
particle_spacing: 0.02
end_time: 1.0
fluid:
  phases: [{name: water, density: 1000, rheology: {model: newtonian, viscosity: 1.0e-3}}]
  regions: [{type: below_level, level: 0.2}]
method: {surface_pressure: half_layer, settling_time: 3.0, settling_damping: 3.0}
walls:
  - {name: tank, type: tank, min: [0, 0, 0], max: [0.3, 0.1, 0.3]}
  - {name: slope, type: terrain, file: slope.csv}
)");
  auto scene = cases::build_scene<3>(cases::load_scene(dir / "s.yaml", {}), "s", dir);
  const double sqrt_gh = std::sqrt(g * 0.18);  // the deepest water, at the slope's foot
  double largest_speed = 0.0;
  std::size_t under = 0;
  ASSERT_TRUE(run_scene<3>(*scene, [&](const Simulation<3>& sim) {
    const auto& P = sim.particles();
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (P.kind[i] != Kind::fluid) continue;
      largest_speed = std::max(largest_speed, P.velocity[i].norm() / sqrt_gh);
      under += P.position[i][2] < 0.02 + slope * (0.3 - P.position[i][0]) - 0.25 * 0.02;  // through the terrain
    }
  }));
  std::printf("still water over a 15 degree terrain (dp 0.02), 1 s: largest speed %.3f %% of sqrt(g H)\n",
              100 * largest_speed);
  EXPECT_LT(largest_speed, 0.01);  // issue 31
  EXPECT_EQ(under, 0u);
}

}  // namespace
}  // namespace slide::testing
