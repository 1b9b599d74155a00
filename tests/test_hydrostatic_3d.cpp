// Still water in a 3-D tank (cases/hydrostatic_3d.yaml, the fcc lattice), 1 s: the floor's pressure against the exact
// hydrostatic value, and how far the water strays from rest. Label `long` (suite Long*): 6 s of settling and 1 s of run
// take several minutes on one thread.
// Issue 31 asks for the floor pressure within 1 % of rho g (h - z) and the largest speed under 1 % of sqrt(g H).
// With the top plane at the head of its half layer (surface_pressure: half_layer) and the 3-D default sound speed
// (c0 = 20 sqrt(g H)) both hold: floor pressure -0.282 %, largest speed 0.000 % of sqrt(g H) (stop 47). At c0 = 10 the
// floor pressure was -1.17 % (the water compressed g H / c0^2 = 1 % at its bottom, 0.25 % at 20) and the speed
// 0.001 % (with zero surface pressure, 1.07 % at 1 s, the surface planes stirring). The displacement bound is the 2-D
// still tank's.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/scene_runner.hpp"

namespace slide::testing {
namespace {

// The width the water fills across [0, L] on the fcc lattice: the lattice points strictly inside are the planes
// (k + 1/2) s below L, and the interface with the wall's points lies half a plane beyond the last of them.
double filled_width(double L, double s) { return std::ceil(L / s - 0.5) * s; }

TEST(LongHydrostatic3D, StillTankStaysNearRestWithHydrostaticPressure) {
  auto scene = load_shipped_scene<3>("hydrostatic_3d.yaml");
  const auto& opt = scene->simulation->options;
  ASSERT_EQ(opt.lattice, LatticeKind::fcc);
  const double dp = opt.dp, s = row_spacing(LatticeKind::fcc, dp), rho = 1000.0;
  // The level the water's mass gives at its reference density over the area it fills (the tank is 0.2 m x 0.1 m).
  const double area = filled_width(0.2, s) * filled_width(0.1, s);
  const double level = double(scene->fluid_count) * dp * dp * dp / area, sqrt_gh = std::sqrt(g * level);
  const auto& P0 = scene->simulation->particles();
  std::vector<Vec<3>> start(P0.size());
  for (std::size_t i = 0; i < P0.size(); ++i) start[P0.id[i]] = P0.position[i];
  double largest_speed = 0.0, largest_shift = 0.0, pressure_sum = 0.0, exact_sum = 0.0;
  ASSERT_TRUE(run_scene<3>(*scene, [&](const Simulation<3>& sim) {
    const auto& P = sim.particles();
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (P.kind[i] != Kind::fluid) continue;
      largest_speed = std::max(largest_speed, P.velocity[i].norm() / sqrt_gh);
      largest_shift = std::max(largest_shift, (P.position[i] - start[P.id[i]]).norm() / dp);
    }
    if (sim.time() < 0.7) return;
    for (std::size_t i = 0; i < P.size(); ++i)  // the floor's wall layer under the water
      if (P.kind[i] == Kind::wall && P.wall_normal[i][2] > 1.0 - 1e-9 && P.position[i][0] > 0 &&
          P.position[i][0] < 0.2 && P.position[i][1] > 0 && P.position[i][1] < 0.1) {
        pressure_sum += P.pressure[i];
        exact_sum += rho * g * (level - P.position[i][2]);
      }
  }));
  const double pressure_error = (pressure_sum - exact_sum) / exact_sum;
  std::printf("still tank 3-D (fcc), 1 s: floor pressure error %+.3f %% (last 0.3 s), largest displacement %.3f dp, "
              "largest speed %.3f %% of sqrt(g H)\n",
              100 * pressure_error, largest_shift, 100 * largest_speed);
  EXPECT_LT(std::abs(pressure_error), 0.01);  // issue 31
  EXPECT_LT(largest_speed, 0.01);  // issue 31
  EXPECT_LT(largest_shift, 1.0);
}

}  // namespace
}  // namespace slide::testing
