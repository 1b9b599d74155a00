// The wall-pressure models (method.wall_pressure: mirror, extrapolated; fluid/wall_pressure.hpp)
// against exact answers (issue 12, item 2): a still tank, a tank accelerated sideways at a constant rate (in its frame,
// tilted gravity), and a water column at the instant it is released.
//
// What they found (figures with each test below): extrapolated, on the hexagonal lattice the still water needs,
// passes all three at both spacings. mirror runs only on the square lattice, where the tanks fail (pressure noise
// 3-5 % of rho g L and side walls 2-3 %, not shrinking with dp) for lack of the stable packing, as extrapolated does
// there too; on the released column it equals extrapolated. A third model, classic MPS's number_density, failed all
// three (walls 8-11 % off in the tanks, not converging; the column's wall force 6-15 % low) and was removed; its
// figures are kept below.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "coupling/free_surface_gauge.hpp"
#include "coupling/released_column_pressure.hpp"
#include "coupling/tilted_hydrostatic.hpp"
#include "tests/cli_helpers.hpp"
#include "tests/scene_runner.hpp"

namespace slide::testing {
namespace {

constexpr double rho = 1000.0;

std::string num(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.10g", v);
  return b;
}

// ---------------------------------------------------------------------------------------------------------------
// The exact answers themselves.

// The released column's series (coupling/released_column_pressure.hpp) satisfies its boundary conditions and
// Laplace's equation, checked by finite differences on the sum.
TEST(ReleasedColumnPressure, MeetsItsBoundaryConditionsAndIsHarmonic) {
  const double a = 0.1, h = 0.2, scale = rho * g * a;
  auto p = [&](double x, double y) { return released_column_pressure(x, y, a, h, rho, g); };
  for (const double y : {0.0, 0.05, 0.1, 0.19}) EXPECT_NEAR(p(a, y), 0.0, 1e-9 * scale) << y;  // free face
  for (const double x : {0.0, 0.03, 0.07}) EXPECT_NEAR(p(x, h), 0.0, 1e-9 * scale) << x;       // free surface
  const double e = 1e-5;
  for (const double y : {0.02, 0.1, 0.18}) EXPECT_NEAR((p(e, y) - p(0.0, y)) / e, 0.0, 1e-3 * rho * g) << y;
  // On the floor dp/dy = -rho g (one-sided difference; the derivative's series converges like the Fourier series
  // of a step, 1/n, so off the corner x = a).
  for (const double x : {0.0, 0.01, 0.05, 0.08})
    EXPECT_NEAR((p(x, e) - p(x, 0.0)) / e, -rho * g, 0.005 * rho * g) << x;
  const double d = 1e-3;
  for (const auto& [x, y] : std::vector<std::pair<double, double>>{{0.02, 0.05}, {0.05, 0.1}, {0.08, 0.15}}) {
    const double lap = (p(x + d, y) + p(x - d, y) + p(x, y + d) + p(x, y - d) - 4 * p(x, y)) / (d * d);
    EXPECT_NEAR(lap, 0.0, 1e-3 * rho * g / a) << x << " " << y;
  }
  // Below the hydrostatic value everywhere (the released column pushes less on its wall), and even in x.
  EXPECT_LT(p(0.0, 0.0), rho * g * h);
  EXPECT_GT(p(0.0, 0.0), 0.0);
  EXPECT_NEAR(p(-0.03, 0.07), p(0.03, 0.07), 1e-12 * scale);
  // An independent value: for a column much taller than wide, the pressure in the corner of wall and floor is
  // rho g a (8 / pi^2) sum (-1)^(n+1) / (2n - 1)^2 = rho g a 8 G / pi^2 (G = 0.9159655942 Catalan's constant).
  const double catalan = 0.915965594177219, pi = 3.14159265358979323846;
  EXPECT_NEAR(released_column_pressure(0.0, 0.0, a, 20 * a, rho, g), scale * 8 * catalan / (pi * pi), 1e-6 * scale);
}

// Tilted hydrostatics (coupling/tilted_hydrostatic.hpp): zero pressure on the surface, the gradient rho G, and the
// water under the tilted surface as much as under the level one.
TEST(TiltedHydrostatic, SurfaceIsANormalPlaneAndKeepsTheWatersArea) {
  const TiltedHydrostatic t{Vec<2>(-0.2 * g, -g), 0.0, 0.4, 0.2, rho};
  EXPECT_NEAR(t.surface_slope(), -0.2, 1e-15);  // the water piles up at the rear (left) wall
  for (const double x : {0.0, 0.1, 0.37}) EXPECT_NEAR(t.pressure(Vec<2>(x, t.surface_y(x))), 0.0, 1e-9);
  const Vec<2> q(0.13, 0.07);
  EXPECT_NEAR(t.pressure(q + Vec<2>(1e-3, 0)) - t.pressure(q), rho * (-0.2 * g) * 1e-3, 1e-9);
  EXPECT_NEAR(t.pressure(q + Vec<2>(0, 1e-3)) - t.pressure(q), rho * (-g) * 1e-3, 1e-9);
  const double area = 0.5 * (t.surface_y(0.0) + t.surface_y(0.4)) * 0.4;  // trapezoid
  EXPECT_NEAR(area, 0.2 * 0.4, 1e-15);
  const TiltedHydrostatic still{Vec<2>(0.0, -g), 0.0, 1.0, 0.5, rho};
  EXPECT_NEAR(still.pressure(Vec<2>(0.3, 0.1)), rho * g * 0.4, 1e-9);
}

// ---------------------------------------------------------------------------------------------------------------
// Tanks at rest in their own frame: a still tank (gx = 0) and a tank accelerated sideways at a = -gx.
//
// The tank is 0.4 m wide with 0.2 m of water (the shipped still tank, cases/hydrostatic_2d.yaml, is 1 m x 0.5 m and
// settles 6 s: minutes on one core at dp 0.01), with the shipped case's method: variational gradient, settled start
// at the gentle damping 3 /s (here 2 s: some 20 acoustic periods of the depth and 10 damping times). The water is
// placed under the tilted surface already (a polygon), so settling only compresses it. Lattice: hexagonal for
// extrapolated (the stable packing), square for mirror (its images assume the square lattice;
// the hexagonal lattice refuses it).
constexpr double tank_width = 0.4, tank_depth = 0.2;

struct TankFigures {
  double bottom_error = 0.0;      // sum of the floor's wall-layer pressures over their exact sum, less 1
  double side_rms = 0.0;          // rms over the side walls' wall-layer particles below the surface, / (rho g L)
  double fluid_rms = 0.0;         // rms over fluid particles of (p - exact) / (rho g L)
  double zero_offset_dp = 0.0;    // where the fitted pressure plane is zero, above the exact surface, in dp
  double fitted_gradient = 0.0;   // |grad p| of the fitted plane / (rho |G|), less 1
  double tilt_error = 0.0;        // gauged surface slope over the exact one, less 1 (0 for the still tank)
  double slope = 0.0;             // gauged surface slope
  double surface_offset_dp = 0.0; // gauged surface at the tank's middle above the mass level, in dp
};

// The lattice a model runs on by default here: square for mirror (the only one it accepts), hexagonal otherwise.
std::string lattice_for(const std::string& model) { return model == "mirror" ? "square" : "hexagonal"; }

std::string tank_scene(const std::string& model, double dp, double gx, const std::string& lattice) {
  const double s = -gx / g, W = tank_width, e = 1e-6;
  const double yl = tank_depth - s * (0 - 0.5 * W), yr = tank_depth - s * (W - 0.5 * W);
  return "particle_spacing: " + num(dp) + "\nlattice: " + lattice + "\nend_time: 0.5\ngravity: [" + num(gx) + ", " +
         num(-g) + "]\n" + R"(fluid:
  phases:
    - {name: water, density: 1000, rheology: {model: newtonian, viscosity: 1.0e-3}}
  regions:
    - {type: polygon, points: [[)" +
         num(e) + ", " + num(e) + "], [" + num(W - e) + ", " + num(e) + "], [" + num(W - e) + ", " + num(yr) + "], [" +
         num(e) + ", " + num(yl) + "]]}\nmethod:\n  gradient: variational\n  wall_pressure: " + model +
         R"(
  initial_state: settled
  settling_time: 2.0
  settling_damping: 3.0
walls:
  - {name: tank, points: [[0, 0.35], [0, 0], [0.4, 0], [0.4, 0.35]]}
)";
}

// Least squares of p = c0 + c1 x + c2 y.
struct PlaneFit {
  double s[3][3] = {}, r[3] = {};
  void add(double x, double y, double p) {
    const double v[3] = {1.0, x, y};
    for (int i = 0; i < 3; ++i) {
      r[i] += v[i] * p;
      for (int j = 0; j < 3; ++j) s[i][j] += v[i] * v[j];
    }
  }
  Eigen::Vector3d solve() const {
    Eigen::Matrix3d m;
    Eigen::Vector3d b;
    for (int i = 0; i < 3; ++i) {
      b[i] = r[i];
      for (int j = 0; j < 3; ++j) m(i, j) = s[i][j];
    }
    return m.ldlt().solve(b);
  }
};

TankFigures run_tank(const std::string& model, double dp, double a_over_g, std::string lattice = "") {
  if (lattice.empty()) lattice = lattice_for(model);
  auto scene = build_scene_text("wall_tank", tank_scene(model, dp, -a_over_g * g, lattice));
  const double L = scene->fluid_count * dp * dp / tank_width;
  const TiltedHydrostatic exact{Vec<2>(-a_over_g * g, -g), 0.0, tank_width, L, rho};
  const double scale = rho * g * L;
  std::vector<double> gauge_x;
  for (int k = 1; k <= 7; ++k) gauge_x.push_back(tank_width * k / 8.0);
  double bottom_p = 0.0, bottom_exact = 0.0, side2 = 0.0, fluid2 = 0.0, slope_sum = 0.0, middle_sum = 0.0;
  long side_n = 0, fluid_n = 0, samples = 0;
  PlaneFit fit;
  double next_sample = 0.1;  // the first 0.1 s after the settled start are left out
  run_scene(*scene, [&](const Simulation<2>& sim) {
    if (sim.time() < next_sample) return;
    next_sample += 0.01;
    ++samples;
    const auto& P = sim.particles();
    for (std::size_t i = 0; i < P.size(); ++i) {
      const Vec<2>& x = P.position[i];
      const double p_exact = exact.pressure(x);
      if (P.kind[i] == Kind::fluid) {
        fluid2 += std::pow((P.pressure[i] - p_exact) / scale, 2);
        ++fluid_n;
        // The plane is fitted where the field is smooth: more than 3 dp below the surface.
        if (x[1] < exact.surface_y(x[0]) - 3 * dp) fit.add(x[0], x[1], P.pressure[i]);
      } else if (P.kind[i] == Kind::wall) {
        if (P.wall_normal[i][1] > 1.0 - 1e-9 && x[0] > 0 && x[0] < tank_width) {
          bottom_p += P.pressure[i];
          bottom_exact += p_exact;
        } else if (std::abs(P.wall_normal[i][0]) > 1.0 - 1e-9 && x[1] > 0 && x[1] < exact.surface_y(x[0]) - dp) {
          side2 += std::pow((P.pressure[i] - p_exact) / scale, 2);
          ++side_n;
        }
      }
    }
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    for (const double x : gauge_x) {
      const double eta = free_surface_elevation(sim, Vec<2>(x, 0.0));
      sx += x, sy += eta, sxx += x * x, sxy += x * eta;
    }
    const double n = gauge_x.size();
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    slope_sum += slope;
    middle_sum += (sy - slope * sx) / n + slope * exact.centre_x();
  });
  TankFigures f;
  f.bottom_error = bottom_p / bottom_exact - 1.0;
  f.side_rms = std::sqrt(side2 / std::max(side_n, 1L));
  f.fluid_rms = std::sqrt(fluid2 / std::max(fluid_n, 1L));
  const Eigen::Vector3d c = fit.solve();
  const double grad = std::hypot(c[1], c[2]);
  f.fitted_gradient = grad / (rho * exact.gravity.norm()) - 1.0;
  f.zero_offset_dp = (c[0] + c[1] * exact.centre_x() + c[2] * L) / grad / dp;
  f.slope = slope_sum / samples;
  f.tilt_error = a_over_g > 0 ? f.slope / exact.surface_slope() - 1.0 : 0.0;
  f.surface_offset_dp = (middle_sum / samples - L) / dp;
  std::printf("tank %-14s %-9s dp %.4f a/g %.2f: bottom %+.3f %%, side rms %.3f %%, fluid rms %.3f %%, zero plane %+.2f dp, "
              "fitted |grad p| %+.3f %%, slope %.4f (tilt error %+.2f %%), surface at the middle %+.2f dp\n",
              model.c_str(), lattice.c_str(), dp, a_over_g, 100 * f.bottom_error, 100 * f.side_rms, 100 * f.fluid_rms,
              f.zero_offset_dp, 100 * f.fitted_gradient, f.slope, 100 * f.tilt_error, f.surface_offset_dp);
  std::fflush(stdout);
  return f;
}

// ---------------------------------------------------------------------------------------------------------------
// The released column at t = 0+. A column a = 0.1 m wide and h = 0.2 m high against the wall x = 0 on the floor
// y = 0 (Martin & Moyce's a x 2a, as cases/dam_break_2d.yaml; square lattice, variational gradient), released at
// t = 0. The wall pressure is compared with the series at the wall layer's mirror point (p is even in x).
//
// A weakly compressible run reaches the incompressible answer only as the mean of its acoustic ringing, which
// nothing damps: the column rings in its modes (closed at the wall and floor, open at the free faces; the slowest
// has the period 2 pi / (c0 sqrt((pi / 2a)^2 + (pi / 2h)^2)) = 1.79 h / c0 here). Departures from the defaults,
// each measured (extrapolated model unless said):
// * clamp_negative_pressure off: with the clamp the ringing's negative half is cut off, the column cavitates at
//   p = 0, and the mean wall force comes out 50-63 % low for mirror and extrapolated alike (a/20 to a/80, from the
//   hydrostatic start with c0 = 50 sqrt(g h) and T = 0.1 sqrt(h / g)).
// * initial_state lattice (p = 0 at t = 0; the water compresses under gravity as it is released): the hydrostatic
//   start puts the bottom row 0.5 % denser than n0 (0.494 dp above the floor), a compression that does not depend
//   on c0, so its pressure grows as c0^2: 13 rho g h at c0 = 50 sqrt(g h), 195 rho g h at 200 sqrt(g h) (1.56 rho g
//   H in the shipped dam break at the default c0), and its release rings at 2-4 rho g h near the wall.
// * c0 = 200 sqrt(g h) (slowest period 0.009 sqrt(h / g); compressibility g h / c0^2 = 2.5e-5), and the pressure
//   is the Hann-weighted mean, w(t) = sin^2(pi t / T), over T = 0.05 sqrt(h / g): 5.5 periods of the slowest mode,
//   whose share of the mean the window cuts to 2e-3 of its amplitude (faster modes less).
// T is a compromise between the water's motion, which makes the mean drift from the t = 0+ field (the corner
// at the floor is singular and moves at once), and the start, when the water first falls freely until its pressure
// builds. At a/40 (c0 = 200 sqrt(g h), and 400 and 800 for the two shortest T) the wall-layer rms and force errors:
//   T / sqrt(h / g)   0.2      0.1      0.05     0.025    0.0125
//   rms / (rho g h)   1.17 %   0.39 %   0.16 %   0.16 %   0.31 %
//   force             +9.0 %   -3.3 %   -1.3 %   +1.1 %   +2.2 %
// so a measurement of the wall pressure to better than about 0.3 % of rho g h (2 % of the force) is not to be had
// this way; the tolerances below are set from that and the measured spread between spacings.
constexpr double column_a = 0.1, column_h = 0.2;

struct ColumnFigures {
  double wall_rms = 0.0;    // rms over the wall's first layer (0 < y < h) of (p_w - p(0+, |x_w|, y_w)) / (rho g h)
  double wall_force = 0.0;  // the first layer's sum p_w dp over the exact integral of p(0, y), less 1
  double wall_max = 0.0;    // largest |p_w - exact| / (rho g h) there
  double fluid_rms = 0.0;   // rms over fluid particles of (mean p - exact at the start position) / (rho g h)
  std::vector<std::pair<double, double>> profile;  // (y / h, p_w / (rho g h)) of the first layer
};

ColumnFigures run_column(const std::string& model, double dp, const std::string& gradient = "variational") {
  const double t_end = 0.05 * std::sqrt(column_h / g), c0 = 200 * std::sqrt(g * column_h);
  const std::string yaml = "particle_spacing: " + num(dp) + "\nend_time: " + num(t_end) + R"(
fluid:
  phases:
    - {name: water, density: 1000, rheology: {model: newtonian, viscosity: 1.0e-3}}
  regions:
    - {type: rectangle, min: [0, 0], max: [0.1, 0.2]}
method:
  gradient: )" + gradient + "\n  wall_pressure: " + model + "\n  sound_speed: " + num(c0) + R"(
  clamp_negative_pressure: false
  initial_state: lattice
lattice: square
walls:
  - {name: tank, points: [[0, 0.3], [0, 0], [0.3, 0], [0.3, 0.3]]}
)";
  auto scene = build_scene_text("wall_column", yaml);
  const double scale = rho * g * column_h;
  const auto& P0 = scene->simulation->particles();
  std::map<std::uint32_t, Vec<2>> start;
  std::map<std::uint32_t, double> mean_p;
  for (std::size_t i = 0; i < P0.size(); ++i) start[P0.id[i]] = P0.position[i];
  double weight_sum = 0.0, last_t = 0.0;
  run_scene(*scene, [&](const Simulation<2>& sim) {
    const double t = sim.time(), dt = t - last_t;
    last_t = t;
    const double w = std::pow(std::sin(3.14159265358979323846 * t / t_end), 2) * dt;
    weight_sum += w;
    const auto& P = sim.particles();
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.kind[i] != Kind::dummy) mean_p[P.id[i]] += w * P.pressure[i];
  });
  ColumnFigures f;
  double wall2 = 0.0, force = 0.0, fluid2 = 0.0;
  long wall_n = 0, fluid_n = 0;
  const auto& P = scene->simulation->particles();
  double first_layer_x = -1e9;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::wall && P.wall_normal[i][0] > 1.0 - 1e-9) first_layer_x = std::max(first_layer_x, start[P.id[i]][0]);
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Vec<2>& x = start[P.id[i]];
    const double p = mean_p[P.id[i]] / weight_sum;
    if (P.kind[i] == Kind::fluid) {
      fluid2 += std::pow((p - released_column_pressure(x[0], x[1], column_a, column_h, rho, g)) / scale, 2);
      ++fluid_n;
    } else if (P.kind[i] == Kind::wall && P.wall_normal[i][0] > 1.0 - 1e-9 && x[0] > first_layer_x - 1e-9 &&
               x[1] > 0 && x[1] < column_h) {
      const double err = (p - released_column_pressure(-x[0], x[1], column_a, column_h, rho, g)) / scale;
      wall2 += err * err;
      ++wall_n;
      f.wall_max = std::max(f.wall_max, std::abs(err));
      force += p * dp;
      f.profile.emplace_back(x[1] / column_h, p / scale);
    }
  }
  // The exact force on the wall, integral_0^h p(0, y) dy, by the midpoint rule on a fine grid.
  double exact_force = 0.0;
  const int m = 4000;
  for (int k = 0; k < m; ++k)
    exact_force += released_column_pressure(0.0, (k + 0.5) * column_h / m, column_a, column_h, rho, g) * column_h / m;
  f.wall_rms = std::sqrt(wall2 / std::max(wall_n, 1L));
  f.wall_force = force / exact_force - 1.0;
  f.fluid_rms = std::sqrt(fluid2 / std::max(fluid_n, 1L));
  std::sort(f.profile.begin(), f.profile.end());
  std::printf("column %-14s %-11s dp a/%.0f: wall rms %.3f %%, wall max %.3f %%, wall force %+.3f %%, fluid rms "
              "%.3f %% (of rho g h)\n",
              model.c_str(), gradient.c_str(), column_a / dp, 100 * f.wall_rms, 100 * f.wall_max, 100 * f.wall_force,
              100 * f.fluid_rms);
  std::fflush(stdout);
  return f;
}

// ---------------------------------------------------------------------------------------------------------------
// The model that passes: extrapolated (hexagonal lattice, variational gradient). Tolerances from the measured
// errors (the report of issue 12's wall tests) and what each measure can resolve; figures at dp 0.01 / 0.005 m
// (tanks) and a/20 / a/40 / a/80 (column).

// Tank checks shared by the still and the accelerated tank. dp 0.01: the default set; dp 0.005 (Long): converging.
// The fluid's rms error converges (1.1-1.3 % at 0.01, 0.40-0.47 % at 0.005); the floor's pressure (-0.2 to -0.55 %),
// the fitted plane's gradient (-0.9 to -1.25 %) and its zero (0.13-0.22 dp above the exact surface) do not shrink
// with dp: the settled lattice's discrete equilibrium, whose pair forces balance the weight with a pressure
// gradient 1 % below rho g (fluid/gradient.hpp's variational form on a compressed, slightly disordered lattice).
void expect_tank_passes(const TankFigures& f, double dp) {
  EXPECT_LT(std::abs(f.bottom_error), 0.01);
  EXPECT_LT(f.side_rms, 0.01);
  EXPECT_LT(f.fluid_rms, dp > 0.0075 ? 0.02 : 0.0075);
  EXPECT_LT(std::abs(f.zero_offset_dp), 0.5);
  EXPECT_LT(std::abs(f.fitted_gradient), 0.02);
}

// Measured: bottom -0.55 %, side rms 0.56 %, fluid rms 1.30 %, zero plane +0.13 dp, gradient -1.25 %, gauged
// surface at the middle +0.00 dp of the mass level.
TEST(WallModels, ExtrapolatedHoldsAStillTankHydrostatic) {
  const TankFigures f = run_tank("extrapolated", 0.01, 0.0);
  expect_tank_passes(f, 0.01);
  EXPECT_LT(std::abs(f.surface_offset_dp), 0.25);
}

// a/g = 0.2, measured: tilt -0.67 % (a/g = 0.1: -1.06 %), bottom -0.22 %, side rms 0.46 %, fluid rms 1.11 %, zero
// plane +0.15 dp, gradient -1.0 %. The gauges (x = W/8 ... 7W/8) read the surface to about 0.03 dp
// (coupling/free_surface_gauge.hpp), 1 % of the 3 dp rise over their span at a/g = 0.1: the tilt's tolerance.
TEST(WallModels, ExtrapolatedTiltsAnAcceleratedTanksSurface) {
  const TankFigures f = run_tank("extrapolated", 0.01, 0.2);
  expect_tank_passes(f, 0.01);
  EXPECT_LT(std::abs(f.tilt_error), 0.02);
}

// Column checks. Measured (wall rms, wall max, force, fluid rms; % of rho g h):
//   a/20: 0.38, 0.61, +2.4, 0.60;  a/40: 0.16, 0.33, -1.3, 0.32;  a/80: 0.30, 0.37, -2.6, 0.22.
// The wall figures wander within the measurement's own limit (about 0.3 % of rho g h, 2 % of the force: above);
// the fluid's error converges.
void expect_column_passes(const ColumnFigures& f, double dp) {
  EXPECT_LT(f.wall_rms, 0.006);
  EXPECT_LT(f.wall_max, 0.01);
  EXPECT_LT(std::abs(f.wall_force), 0.04);
  EXPECT_LT(f.fluid_rms, dp > 0.004 ? 0.01 : dp > 0.002 ? 0.005 : 0.003);
}

TEST(WallModels, ExtrapolatedGivesTheReleasedColumnsWallPressure) {
  for (const double dp : {0.005, 0.0025}) expect_column_passes(run_column("extrapolated", dp), dp);
}

TEST(LongWallModels, ExtrapolatedAtHalfTheSpacing) {
  expect_tank_passes(run_tank("extrapolated", 0.005, 0.0), 0.005);
  for (const double a : {0.1, 0.2}) {
    const TankFigures f = run_tank("extrapolated", 0.005, a);
    expect_tank_passes(f, 0.005);
    EXPECT_LT(std::abs(f.tilt_error), 0.01);  // -0.89 % and +0.11 %
  }
  expect_column_passes(run_column("extrapolated", 0.00125), 0.00125);
}

// ---------------------------------------------------------------------------------------------------------------
// The other two models.
//
// mirror runs only on the square lattice, and there the tanks fail: still tank (dp 0.01 / 0.005) bottom -0.24 / +0.22
// %, side walls rms 2.3 / 2.2 %, fluid rms 4.0 / 3.3 %, zero plane -0.13 / -0.30 dp, gradient +0.5 / +0.7 %;
// accelerated a/g = 0.1: bottom +0.50 / +0.56 %, side 2.4 / 2.4 %, fluid 3.2 / 4.8 %, tilt -2.6 / -1.3 %; a/g = 0.2:
// bottom +1.07 / +1.32 %, side 2.9 / 2.7 %, fluid 4.5 / 4.6 %, tilt -1.9 / -0.7 % (side and fluid errors not
// shrinking with dp). That is the square lattice's doing, not the model's: extrapolated on the square lattice
// (DISABLED_ExtrapolatedOnTheSquareLattice below) does the same. Where mirror is useful: flows on the square lattice
// (the dam break's and the Poiseuille channel's), where its wall pressure at a released column's wall is the extrapolated
// model's within 0.03 % of rho g h (measured a/20 to a/80: wall rms 0.39 / 0.16 / 0.30 %, force +2.7 / -1.2 / -2.6 %,
// fluid rms 0.60 / 0.33 / 0.23 %).
TEST(WallModels, MirrorGivesTheReleasedColumnsWallPressure) {
  for (const double dp : {0.005, 0.0025}) expect_column_passes(run_column("mirror", dp), dp);
}

// The runs behind mirror's tank figures above, and its column at a/80.
TEST(LongWallModels, DISABLED_MirrorFigures) {
  for (const double a : {0.0, 0.1, 0.2})
    for (const double dp : {0.01, 0.005}) run_tank("mirror", dp, a);
  run_column("mirror", 0.00125);
}

// The removed number_density model (the wall layer's pressure from its own number density, dummies none: classic
// MPS; issue 12) failed the wall tests; its tank errors did not shrink with dp (the wall layer sees water on one side
// only), the column's shrank at first order. Measured at stop 18, dp 0.01 / 0.005 m:
//   still tank       bottom -8.4 / -9.2 %, side rms 9.6 / 10.8 %, fluid rms 4.5 / 3.5 %, zero plane -0.06 / +0.06 dp
//   a/g = 0.1        bottom -8.1 / -8.9 %, side rms 10.0 / 11.1 %, fluid rms 4.5 / 3.5 %, tilt -2.0 / +1.1 %
//   a/g = 0.2        bottom -7.7 / -8.7 %, side rms 10.0 / 11.5 %, fluid rms 4.6 / 3.6 %, tilt +0.5 / +0.1 %
//   column a/20, a/40, a/80: wall rms 2.6 / 1.8 / 0.9 %, wall max 7.0 / 4.9 / 3.6 %, force -15 / -10 / -5.9 %,
//                    fluid rms 2.6 / 1.6 / 0.6 % (of rho g h)
// (its fluid's fitted gradient and the surface's tilt were right: what it got wrong was the wall's own pressure).

// The control: extrapolated on the square lattice (dp 0.01 / 0.005): still tank bottom -0.75 / -0.02 %, side rms
// 2.4 / 2.0 %, fluid rms 4.0 / 3.2 %; a/g = 0.1: bottom +0.13 / +0.34 %, side 2.6 / 1.6 %, fluid 3.9 / 4.4 %, tilt
// -2.5 / +0.7 %; a/g = 0.2: bottom +0.85 / +1.19 %, side 3.2 / 2.0 %, fluid 4.3 / 5.2 %, tilt +1.6 / +0.2 %.
TEST(LongWallModels, DISABLED_ExtrapolatedOnTheSquareLattice) {
  for (const double a : {0.0, 0.1, 0.2})
    for (const double dp : {0.01, 0.005}) run_tank("extrapolated", dp, a, "square");
}

}  // namespace
}  // namespace slide::testing
