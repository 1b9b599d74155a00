// The boundary particles of a 3-D tank (fluid/box_walls.hpp): counts, layers, normals and depths by hand, on the cubic
// and the fcc lattice.
#include <gtest/gtest.h>

#include <cmath>

#include "fluid/box_walls.hpp"

namespace slide {
namespace {

// A 0.1 m cube inside, dp 0.01, 3 layers on the cubic lattice: the floor is 16 x 16 points 3 deep, the sides a 16 x 16
// ring around the 10 x 10 inside, 10 rows high (the sides end at the top, z = 0.1).
TEST(BoxWalls, CubicTankCountsLayersAndCornerNormals) {
  const double dp = 0.01;
  const Vec<3> lo(0, 0, 0), hi(0.1, 0.1, 0.1);
  const auto pts = tank_boundary(LatticeKind::square, lo, hi, dp, 3, 0.0);
  EXPECT_EQ(pts.size(), std::size_t(16 * 16 * 3 + (16 * 16 - 10 * 10) * 10));
  int wall_layer = 0;
  for (const auto& p : pts) {
    if (p.layer == 0) ++wall_layer;
    EXPECT_FALSE(inside_tank(p.position, lo, hi, 1e-12));
    // Every point's mirror image (x + 2 depth normal) is a fluid lattice point inside the tank.
    const Vec<3> image = p.position + 2.0 * p.depth * p.normal;
    EXPECT_TRUE(inside_tank(image, lo, hi, 1e-12)) << p.position.transpose();
    for (int a = 0; a < 3; ++a) EXPECT_NEAR(std::fmod(image[a] / dp + 100.0, 1.0), 0.5, 1e-9);
  }
  EXPECT_EQ(wall_layer, 12 * 12 + (12 * 12 - 10 * 10) * 10);  // the floor 12 x 12; the sides a ring of 44, 10 high
  // The floor's corner point below the origin: along the diagonal, sqrt(3) dp / 2 from the corner.
  for (const auto& p : pts)
    if ((p.position - Vec<3>(-0.005, -0.005, -0.005)).norm() < 1e-12) {
      EXPECT_NEAR((p.normal - Vec<3>(1, 1, 1) / std::sqrt(3.0)).norm(), 0.0, 1e-12);
      EXPECT_NEAR(p.depth, 0.005 * std::sqrt(3.0), 1e-12);
      EXPECT_EQ(p.layer, 0);
    }
  EXPECT_THROW(tank_boundary(LatticeKind::square, hi, lo, dp, 3, 0.0), std::invalid_argument);
}

// On the fcc lattice the walls are every lattice point on or behind the faces to the depth re: behind the floor, the
// planes at -s/2, -3s/2, ... down to re; a point of plane k is in layer k.
TEST(BoxWalls, FccTankIsCutFromTheLatticeToTheDepthRe) {
  const double dp = 0.01, re = 2.1 * dp, s = row_spacing(LatticeKind::fcc, dp);
  const Vec<3> lo(0, 0, 0), hi(0.1, 0.1, 0.1);
  const auto pts = tank_boundary(LatticeKind::fcc, lo, hi, dp, 0, re);
  int deepest_layer = 0;
  for (const auto& p : pts) {
    EXPECT_FALSE(inside_tank(p.position, lo, hi, 1e-12));
    EXPECT_LE(p.depth, std::sqrt(3.0) * re + 1e-12);
    deepest_layer = std::max(deepest_layer, p.layer);
    if (p.position[0] > 0 && p.position[0] < 0.1 && p.position[1] > 0 && p.position[1] < 0.1) {  // under the floor
      EXPECT_NEAR((p.normal - Vec<3>(0, 0, 1)).norm(), 0.0, 1e-12);
      EXPECT_NEAR(p.depth, -p.position[2], 1e-12);
      EXPECT_EQ(p.layer, static_cast<int>(std::floor(-p.position[2] / s)));
    }
  }
  EXPECT_EQ(deepest_layer, static_cast<int>(std::floor(re / s)));
}

// A tank whose faces lie on the fcc lattice's planes (min = s/2: the plane i = 0): the points on a face are the wall's,
// with depth 0 and the face's inward normal (on an edge, the sum of its two faces' normals, normalised).
TEST(BoxWalls, FccPointsOnAFaceAreTheWallsWithDepthZero) {
  const double dp = 0.01, re = 2.1 * dp, s = row_spacing(LatticeKind::fcc, dp);
  const Vec<3> lo = Vec<3>::Constant(0.5 * s), hi(0.5 * s + 12 * s, 0.5 * s + 12 * s, 0.1);
  const auto pts = tank_boundary(LatticeKind::fcc, lo, hi, dp, 0, re);
  int on_floor = 0, on_edge = 0;
  for (const auto& p : pts) {
    if (p.depth > 1e-12) continue;
    EXPECT_EQ(p.layer, 0);
    const bool floor = std::abs(p.position[2] - lo[2]) < 1e-12;
    const bool side_x = std::abs(p.position[0] - lo[0]) < 1e-12 || std::abs(p.position[0] - hi[0]) < 1e-12;
    const bool side_y = std::abs(p.position[1] - lo[1]) < 1e-12 || std::abs(p.position[1] - hi[1]) < 1e-12;
    EXPECT_TRUE(floor || side_x || side_y) << p.position.transpose();
    EXPECT_NEAR(p.normal.norm(), 1.0, 1e-12);
    if (floor && !side_x && !side_y) {
      ++on_floor;
      EXPECT_NEAR((p.normal - Vec<3>(0, 0, 1)).norm(), 0.0, 1e-12);
    }
    if (floor && side_x && !side_y) {
      ++on_edge;
      const double nx = p.position[0] < 0.05 ? 1.0 : -1.0;
      EXPECT_NEAR((p.normal - Vec<3>(nx, 0, 1) / std::sqrt(2.0)).norm(), 0.0, 1e-12);
    }
  }
  // The floor's plane inside the edges: i, j from 1 to 11 with i + j even (k = 0): 61 points; each x edge holds the
  // even j from 1 to 11 with i = 0 or 12: 5 + 5 points.
  EXPECT_EQ(on_floor, 61);
  EXPECT_EQ(on_edge, 10);
}

}  // namespace
}  // namespace slide
