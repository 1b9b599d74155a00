// Effective stress under water (fluid/pore_pressure.hpp, fluid/water_surface.hpp) and the water under a body resting on
// a wall (coupling/dry_face_pressure.hpp): each against exact values.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "coupling/dry_face_pressure.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/pore_pressure.hpp"
#include "fluid/water_surface.hpp"
#include "tests/scene_runner.hpp"

namespace slide::testing {
namespace {

const double none = -std::numeric_limits<double>::infinity();

// Water particles (phase 0) on a square lattice of spacing dp filling [x0, x1] x [y0, y1] at their centres.
Particles<2> water_block(double dp, double x0, double x1, double y0, double y1) {
  Particles<2> P;
  for (double x = x0 + 0.5 * dp; x < x1; x += dp)
    for (double y = y0 + 0.5 * dp; y < y1; y += dp) P.add(Vec<2>(x, y), Kind::fluid, 0, 1000.0, 1e-3);
  return P;
}

TEST(PorePressure, HydrostaticAndEffectivePressureAreExact) {
  EXPECT_DOUBLE_EQ(hydrostatic_pore_pressure(1000.0, 9.81, 0.25), 2452.5);
  EXPECT_EQ(hydrostatic_pore_pressure(1000.0, 9.81, -0.1), 0.0);  // above the surface: dry
  EXPECT_DOUBLE_EQ(effective_pressure(5000.0, 2000.0), 3000.0);
  EXPECT_DOUBLE_EQ(effective_pressure(1000.0, 2000.0), -1000.0);  // tension: no frictional strength (the rheology's)
  const PorePressureField<2> dry;
  EXPECT_EQ(dry.at(Vec<2>(0.3, -5.0)), 0.0);
}

// A flat water layer 0.5 m deep, x in [0, 1]: the surface is the top row's centre plus dp / 2, i.e. 0.5 m, above every
// point inside the layer's columns and beside them (one column of margin); dry beyond.
TEST(PorePressure, WaterSurfaceOfAFlatLayer) {
  const double dp = 0.05;
  const Particles<2> P = water_block(dp, 0.0, 1.0, 0.0, 0.5);
  WaterSurface<2> s;
  s.build(P, Vec<2>(0.0, -g), dp, [&](std::size_t i) { return P.phase[i] == 0; });
  EXPECT_NEAR(s.surface_above(Vec<2>(0.5, 0.1)), 0.5, 1e-12);
  EXPECT_NEAR(s.surface_above(Vec<2>(0.01, 3.0)), 0.5, 1e-12);  // a point above the water: its surface, and dry
  EXPECT_EQ(s.depth_below_surface(Vec<2>(0.01, 3.0)), 0.0);
  EXPECT_NEAR(s.depth_below_surface(Vec<2>(0.5, 0.1)), 0.4, 1e-12);
  EXPECT_NEAR(s.surface_above(Vec<2>(1.04, 0.0)), 0.5, 1e-12);  // the column beside the last
  EXPECT_EQ(s.surface_above(Vec<2>(1.3, 0.0)), none);           // far beside: no water above
  const PorePressureField<2> field{1000.0, g, &s};
  EXPECT_NEAR(field.at(Vec<2>(0.5, 0.1)), 1000.0 * g * 0.4, 1e-9);
}

// Gravity tilted by 30 degrees (a slope made of a flat floor, as the slope tests do): heights and columns are taken
// along up = -g / |g|, so a point on the layer's top lies at the surface's height to within the columns' width.
TEST(PorePressure, WaterSurfaceFollowsTiltedGravity) {
  const double dp = 0.02, a = 30.0 * M_PI / 180.0;
  const Particles<2> P = water_block(dp, 0.0, 2.0, 0.0, 0.5);
  WaterSurface<2> s;
  const Vec<2> gravity(g * std::sin(a), -g * std::cos(a));
  s.build(P, gravity, dp, [](std::size_t) { return true; });
  EXPECT_NEAR(s.up().dot(gravity.normalized()), -1.0, 1e-15);  // up is against g
  // At the middle of the layer's top, the surface above is the highest water in the 3 columns across up around it:
  // the top row's centre plus dp / 2 at most about 1.5 columns up-slope, i.e. within 1.5 dp tan 30 + dp.
  const Vec<2> top(1.0, 0.5);
  EXPECT_NEAR(s.surface_above(top), s.height(top), 1.5 * dp * std::tan(a) + dp);
  EXPECT_GT(s.depth_below_surface(Vec<2>(1.0, 0.1)), 0.0);
}

// A 3-D water block: the same surface from a grid of columns.
TEST(PorePressure, WaterSurfaceIn3D) {
  const double dp = 0.1;
  Particles<3> P;
  for (double x = 0.05; x < 1.0; x += dp)
    for (double y = 0.05; y < 0.6; y += dp)
      for (double z = 0.05; z < 0.4; z += dp) P.add(Vec<3>(x, y, z), Kind::fluid, 0, 1000.0, 1e-3);
  WaterSurface<3> s;
  s.build(P, Vec<3>(0.0, -g, 0.0), dp, [](std::size_t) { return true; });
  EXPECT_NEAR(s.surface_above(Vec<3>(0.5, 0.0, 0.2)), 0.6, 1e-12);
  EXPECT_EQ(s.surface_above(Vec<3>(0.5, 0.0, 3.0)), none);
}

// Wall particles (Kind::wall, no body) along a closed outline, dp / 2 outside it and dp apart: a mould the outline
// rests in on every side.
void add_mould(Particles<2>& P, const std::vector<Vec<2>>& outline, double dp) {
  for (std::size_t k = 0; k < outline.size(); ++k) {
    const Vec<2> a = outline[k], b = outline[(k + 1) % outline.size()];
    const Vec<2> t = (b - a).normalized(), n(t[1], -t[0]);
    for (double s = 0.0; s < (b - a).norm(); s += dp) P.add(a + s * t + 0.5 * dp * n, Kind::wall, 0, 1000.0, 0.0);
  }
}

// A box with no fluid particle near it, deep under water, resting in a mould: every face is a contact face, so the
// dry-face pressure is the whole surface integral of -p n, which for a pressure linear in depth is rho g A up,
// Archimedes, exactly (the midpoint rule is exact for a linear integrand on each edge), with no torque about the box's
// centroid.
TEST(DryFacePressure, ABoxInAMouldUnderWaterFeelsItsBuoyancyExactly) {
  const double dp = 0.02;
  Particles<2> P = water_block(dp, 0.0, 1.0, 1.0, 1.5);  // surface at 1.5 m, far above the box
  const std::vector<Vec<2>> box{{0.3, 0.2}, {0.7, 0.2}, {0.7, 0.35}, {0.3, 0.35}};  // ccw, 0.4 x 0.15 m
  const std::vector<Vec<2>> wedge{{0.2, 0.1}, {0.6, 0.3}, {0.25, 0.5}};
  WaterSurface<2> s;
  s.build(P, Vec<2>(0.0, -g), dp, [](std::size_t) { return true; });
  const PorePressureField<2> pore{1000.0, g, &s};
  for (const auto& outline : {box, wedge}) {
    Particles<2> Q = P;
    add_mould(Q, outline, dp);
    NeighborGrid<2> grid(Vec<2>(-0.5, -0.5), Vec<2>(1.5, 2.0), 2.4 * dp);
    grid.bin(Q.position);
    Vec<2> c = Vec<2>::Zero();
    for (const auto& v : outline) c += v / outline.size();
    const ForceAndTorque f = dry_face_pressure(outline, 0, c, Q, grid, pore, dp);
    double area = 0.0;
    for (std::size_t k = 0; k < outline.size(); ++k) {
      const Vec<2>& a = outline[k];
      const Vec<2>& b = outline[(k + 1) % outline.size()];
      area += 0.5 * (a[0] * b[1] - b[0] * a[1]);
    }
    EXPECT_NEAR(f.force[0], 0.0, 1e-9);
    EXPECT_NEAR(f.force[1], 1000.0 * g * area, 1e-9);
  }
  // Without the mould the same box borders neither water nor a wall: air, a cavity behind a body moving through the
  // water, which carries no water pressure.
  NeighborGrid<2> grid(Vec<2>(-0.5, -0.5), Vec<2>(1.5, 2.0), 2.4 * dp);
  grid.bin(P.position);
  const ForceAndTorque f = dry_face_pressure(box, 0, Vec<2>(0.5, 0.275), P, grid, pore, dp);
  EXPECT_EQ(f.force[0], 0.0);
  EXPECT_EQ(f.force[1], 0.0);
}

// A face with water in front of it is wet (its pair terms carry the water's pressure): the dry-face pressure leaves
// it out. A box in air is left alone.
TEST(DryFacePressure, WetFacesAndFacesInAirGetNothing) {
  const double dp = 0.02;
  // Water fills [0, 1] x [0, 0.5] except a box-shaped hole [0.4, 0.6] x [0, 0.2] on the floor, where the box rests;
  // the floor's wall particles lie dp / 2 below y = 0.
  Particles<2> P;
  for (double x = 0.5 * dp; x < 1.0; x += dp)
    for (double y = 0.5 * dp; y < 0.5; y += dp)
      if (!(x > 0.4 && x < 0.6 && y < 0.2)) P.add(Vec<2>(x, y), Kind::fluid, 0, 1000.0, 1e-3);
  for (double x = 0.5 * dp; x < 1.0; x += dp) P.add(Vec<2>(x, -0.5 * dp), Kind::wall, 0, 1000.0, 0.0);
  NeighborGrid<2> grid(Vec<2>(-0.5, -0.5), Vec<2>(1.5, 1.0), 2.4 * dp);
  grid.bin(P.position);
  WaterSurface<2> s;
  s.build(P, Vec<2>(0.0, -g), dp, [](std::size_t) { return true; });
  const PorePressureField<2> pore{1000.0, g, &s};
  const std::vector<Vec<2>> box{{0.4, 0.0}, {0.6, 0.0}, {0.6, 0.2}, {0.4, 0.2}};
  const ForceAndTorque f = dry_face_pressure(box, 0, Vec<2>(0.5, 0.1), P, grid, pore, dp);
  // Only the base is dry: it carries the water's pressure at the floor, 0.5 m deep, over 0.2 m, upwards.
  EXPECT_NEAR(f.force[0], 0.0, 1e-9);
  EXPECT_NEAR(f.force[1], 1000.0 * g * 0.5 * 0.2, 1e-9);
  // The same box lifted into the air above the water: nothing.
  const std::vector<Vec<2>> high{{0.4, 0.8}, {0.6, 0.8}, {0.6, 1.0}, {0.4, 1.0}};
  const ForceAndTorque h = dry_face_pressure(high, 0, Vec<2>(0.5, 0.9), P, grid, pore, dp);
  EXPECT_EQ(h.force[0], 0.0);
  EXPECT_EQ(h.force[1], 0.0);
}

}  // namespace
}  // namespace slide::testing
