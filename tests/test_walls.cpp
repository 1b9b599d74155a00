// Boundary particles from wall polylines.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "fluid/walls.hpp"

namespace slide {
namespace {

TEST(Walls, LayersCoverTheKernel) {
  EXPECT_EQ(boundary_layers(2.1), 3);
  EXPECT_EQ(boundary_layers(3.0), 3);
  EXPECT_EQ(boundary_layers(3.1), 4);
}

// A U-shaped tank whose sides are multiples of dp continues the fluid's lattice (i + 1/2) dp exactly.
TEST(Walls, RectangularTankIsALattice) {
  const double dp = 0.1;
  const auto pts = polyline_boundary({Vec<2>(0, 1.0), Vec<2>(0, 0), Vec<2>(2.0, 0), Vec<2>(2.0, 1.0)}, true, dp, 3);
  std::set<std::pair<long, long>> seen;
  for (const auto& b : pts) {
    const double i = b.position[0] / dp - 0.5, j = b.position[1] / dp - 0.5;
    EXPECT_NEAR(i, std::round(i), 1e-9);
    EXPECT_NEAR(j, std::round(j), 1e-9);
    EXPECT_TRUE(seen.insert({std::lround(i), std::lround(j)}).second) << "duplicate at " << b.position.transpose();
    // Depth: layer k lies (k + 1/2) dp behind the face; corners measure to the face's vertex.
    EXPECT_GT(b.depth, 0.0);
    // The normal points into the tank.
    EXPECT_NEAR(b.normal.norm(), 1.0, 1e-12);
  }
  // Layer 0 along the bottom at y = -dp/2 spans x = -dp/2 .. 2 + dp/2: 22 points, normal +y.
  int bottom = 0;
  for (const auto& b : pts)
    if (b.layer == 0 && std::abs(b.position[1] + 0.05) < 1e-9) {
      ++bottom;
      if (b.position[0] > 0 && b.position[0] < 2.0) {
        EXPECT_NEAR(b.normal[1], 1.0, 1e-12);
      }
    }
  EXPECT_EQ(bottom, 22);
  // Corner particle of layer 1: (-0.15, -0.15), its image through the corner is the fluid site (0.15, 0.15).
  for (const auto& b : pts)
    if ((b.position - Vec<2>(-0.15, -0.15)).norm() < 1e-9) {
      const Vec<2> image = b.position + 2 * b.depth * b.normal;
      EXPECT_NEAR(image[0], 0.15, 1e-12);
      EXPECT_NEAR(image[1], 0.15, 1e-12);
    }
}

TEST(Walls, ClosedPolygonHasCornersEverywhere) {
  const double dp = 0.1;
  const auto pts =
      polyline_boundary({Vec<2>(0, 0), Vec<2>(1, 0), Vec<2>(1, 1), Vec<2>(0, 1), Vec<2>(0, 0)}, true, dp, 1);
  // Layer 0 is the square of side 1.1 at -0.05 .. 1.05: 4 * 11 points, no duplicates.
  EXPECT_EQ(pts.size(), 44u);
  std::set<std::pair<long, long>> seen;
  for (const auto& b : pts) EXPECT_TRUE(seen.insert({std::lround(b.position[0] * 100), std::lround(b.position[1] * 100)}).second);
}

TEST(Walls, RejectsDegenerateInput) {
  EXPECT_THROW(polyline_boundary({Vec<2>(0, 0)}, true, 0.1, 1), std::invalid_argument);
  EXPECT_THROW(polyline_boundary({Vec<2>(0, 0), Vec<2>(0, 0)}, true, 0.1, 1), std::invalid_argument);
}

// On the hexagonal lattice the walls are the lattice points on or behind the face, to the depth re, against a brute-force
// classification of a U-shaped tank; with the water (every lattice point in front) they form one unbroken lattice.
TEST(Walls, HexagonalWallsAreTheLatticeBehindTheFace) {
  const double dp = 0.1, re = 2.1 * dp, width = 1.0, height = 0.8;
  const LatticeKind hex = LatticeKind::hexagonal;
  const double a = nearest_spacing(hex, dp), h = row_spacing(hex, dp);
  const auto pts = lattice_boundary({Vec<2>(0, height), Vec<2>(0, 0), Vec<2>(width, 0), Vec<2>(width, height)}, true,
                                    dp, re, hex);
  // Brute force: distance behind the tank's faces (negative in front), for points no higher than the walls' tops.
  auto behind = [&](const Vec<2>& p) {
    const double dx = std::max(-p[0], p[0] - width), dy = -p[1];
    if (dx <= 0 && dy <= 0) return -std::min(-dx, -dy);
    return std::hypot(std::max(dx, 0.0), std::max(dy, 0.0));
  };
  std::set<std::pair<long, long>> expected;
  for_each_lattice_point(hex, dp, Vec<2>(-1, -1), Vec<2>(2, 2), [&](const Vec<2>& p) {
    const double d = behind(p);
    if (d >= -1e-12 && d <= re + 1e-12 && p[1] <= height + 1e-12)
      expected.insert({std::lround(p[0] / dp * 1e6), std::lround(p[1] / dp * 1e6)});
  });
  std::set<std::pair<long, long>> got;
  for (const auto& b : pts) {
    EXPECT_TRUE(got.insert({std::lround(b.position[0] / dp * 1e6), std::lround(b.position[1] / dp * 1e6)}).second)
        << "duplicate at " << b.position.transpose();
    EXPECT_NEAR(b.depth, behind(b.position), 1e-12) << b.position.transpose();
    EXPECT_NEAR(b.normal.norm(), 1.0, 1e-12);
    EXPECT_EQ(b.layer, b.depth < h - 1e-9 * dp ? 0 : 1);
    // Beside a side wall or under the floor the normal is the face's; behind a corner it points at the vertex.
    if (b.position[1] > 0 && b.position[0] < 0) {
      EXPECT_NEAR(b.normal[0], 1.0, 1e-12);
    }
    if (b.position[0] > 0 && b.position[0] < width && b.position[1] < 0) {
      EXPECT_NEAR(b.normal[1], 1.0, 1e-12);
    }
    if (b.position[0] < 0 && b.position[1] < 0) {
      EXPECT_NEAR((b.position + b.depth * b.normal).norm(), 0.0, 1e-12);
    }
  }
  EXPECT_EQ(got, expected);
  // Water and walls together: no two points closer than the lattice's nearest spacing.
  std::vector<Vec<2>> all;
  for (const auto& b : pts) all.push_back(b.position);
  for_each_lattice_point(hex, dp, Vec<2>(0, 0), Vec<2>(width, 0.5), [&](const Vec<2>& p) {
    if (behind(p) < 0 && p[1] < 0.5) all.push_back(p);
  });
  for (std::size_t i = 0; i < all.size(); ++i)
    for (std::size_t j = i + 1; j < all.size(); ++j) ASSERT_GT((all[i] - all[j]).norm(), a * (1 - 1e-9));
}

// A closed outline (a body's shape) has no open ends: every lattice point on or inside it to the depth re.
TEST(Walls, HexagonalClosedOutlineHasNoOpenEnds) {
  const double dp = 0.1, re = 2.1 * dp;
  const LatticeKind hex = LatticeKind::hexagonal;
  const Vec<2> lo(0.2, 0.3), hi(1.4, 1.0);
  const auto pts = lattice_boundary({lo, Vec<2>(hi[0], lo[1]), hi, Vec<2>(lo[0], hi[1]), lo}, false, dp, re, hex);
  std::size_t expected = 0;
  for_each_lattice_point(hex, dp, lo, hi, [&](const Vec<2>& p) {
    const double inside = std::min({p[0] - lo[0], hi[0] - p[0], p[1] - lo[1], hi[1] - p[1]});
    if (inside >= -1e-12 && inside <= re + 1e-12) ++expected;
  });
  EXPECT_EQ(pts.size(), expected);
  for (const auto& b : pts) {
    const double inside = std::min({b.position[0] - lo[0], hi[0] - b.position[0], b.position[1] - lo[1],
                                    hi[1] - b.position[1]});
    EXPECT_NEAR(b.depth, inside, 1e-12);
    // The normal points out of the body, into the fluid.
    EXPECT_GT((b.position + 0.5 * dp * b.normal - 0.5 * (lo + hi)).norm(), (b.position - 0.5 * (lo + hi)).norm());
  }
}

// A face along no lattice axis (a 35 degree slope meeting a floor) gets rows of its own on the hexagonal lattice: its
// points lie on rows parallel to it at h / 2 and 3 h / 2 behind it, a apart along each row, odd rows shifted by a / 2
// (face_lattice_point), while the floor keeps the lattice's own points. A slide laid on the same rows in front of the
// face (k >= 0) continues them: no point of the slope's rows and a slide's first row closer than a.
TEST(Walls, HexagonalSlopeHasRowsAlongItsFace) {
  const double dp = 0.1, re = 2.1 * dp;
  const LatticeKind hex = LatticeKind::hexagonal;
  const double a = nearest_spacing(hex, dp), h = row_spacing(hex, dp);
  const double beta = 35.0 * M_PI / 180.0;
  const Vec<2> top(0.0, 2.0), toe(2.0 / std::tan(beta), 0.0), end(toe[0] + 1.0, 0.0);
  EXPECT_FALSE(along_lattice_axes(top, toe));
  EXPECT_TRUE(along_lattice_axes(toe, end));
  EXPECT_DOUBLE_EQ(water_clearance(hex, dp, top, toe), 0.5 * h);
  EXPECT_DOUBLE_EQ(water_clearance(hex, dp, toe, end), 0.0);
  EXPECT_DOUBLE_EQ(water_clearance(LatticeKind::square, dp, top, toe), 0.5 * dp);
  const auto pts = lattice_boundary({top, toe, end}, true, dp, re, hex);
  const Vec<2> along = (toe - top).normalized(), out(-along[1], along[0]);  // out of the wall, into the fluid
  std::vector<Vec<2>> slope_rows;
  for (const auto& b : pts) {
    const double s = (b.position - top).dot(along);
    if (s < re || s > (toe - top).norm() - re) continue;  // clear of both ends: the slope's own points
    slope_rows.push_back(b.position);
    // On row k = -1 or -2 of the face's lattice: depth (|k| - 1/2) h, along-position (i + shift) a.
    const double depth = -(b.position - top).dot(out);
    const long k = depth < h ? -1 : -2;
    EXPECT_NEAR(depth, (-k - 0.5) * h, 1e-9 * dp);
    EXPECT_NEAR(b.depth, depth, 1e-9 * dp);
    EXPECT_NEAR((b.normal - out).norm(), 0.0, 1e-12);
    EXPECT_EQ(b.layer, k == -1 ? 0 : 1);
    const double shift = k == -1 ? 0.5 : 0.0;
    const double i = s / a - shift;
    EXPECT_NEAR(i, std::round(i), 1e-9) << b.position.transpose();
  }
  EXPECT_GT(slope_rows.size(), 30u);
  // Under the floor, away from the toe, the lattice's own points.
  for (const auto& b : pts)
    if (b.position[0] > toe[0] + re && b.position[1] < 0) {
      const double j = b.position[1] / h - 0.5, odd = std::fmod(std::abs(std::round(j)), 2.0);
      EXPECT_NEAR(j, std::round(j), 1e-9);
      EXPECT_NEAR(b.position[0] / a - 0.5 - 0.5 * odd, std::round(b.position[0] / a - 0.5 - 0.5 * odd), 1e-9);
    }
  // The slide's first row in front of the face continues the rows: the nearest distance is a.
  double nearest = 1e9;
  for (long i = 5; i < 15; ++i) {
    const Vec<2> p = face_lattice_point(hex, dp, top, along, out, i, 0);
    EXPECT_NEAR((p - top).dot(out), 0.5 * h, 1e-12);
    for (const auto& q : slope_rows) nearest = std::min(nearest, (p - q).norm());
  }
  EXPECT_NEAR(nearest, a, 1e-9);
}

// row_offset_to_meet moves the lattice by less than half a row spacing so that a row lies at the given height, and
// for_each_lattice_point with that offset visits exactly the moved points.
TEST(Walls, LatticeOffsetPutsARowAtAGivenHeight) {
  for (const LatticeKind kind : {LatticeKind::square, LatticeKind::hexagonal}) {
    const double dp = 0.01, h = row_spacing(kind, dp);
    for (const double y : {0.245, -0.0371, 0.5 * h, 0.3333}) {
      const double off = row_offset_to_meet(kind, dp, y);
      EXPECT_LE(std::abs(off), 0.5 * h + 1e-15) << y;
      const Vec<2> offset(0.0, off);
      int on_row = 0, visited = 0;
      for_each_lattice_point(kind, dp, Vec<2>(0.0, y - 0.05), Vec<2>(0.1, y + 0.05), [&](const Vec<2>& p) {
        ++visited;
        if (std::abs(p[1] - y) < 1e-12) ++on_row;
        // Every visited point is a moved lattice point: its row index is a whole number.
        const double j = (p[1] - off) / h - 0.5;
        EXPECT_NEAR(j, std::round(j), 1e-9);
      }, offset);
      EXPECT_GT(visited, 0);
      EXPECT_GE(on_row, static_cast<int>(0.1 / nearest_spacing(kind, dp))) << y;
    }
  }
}

}  // namespace
}  // namespace slide
