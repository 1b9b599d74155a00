// The slide measures (coupling/slide_front.hpp) on shapes with exact answers.
#include <gtest/gtest.h>

#include "coupling/slide_front.hpp"
#include "fluid/ghosts.hpp"
#include "fluid/lattice.hpp"

namespace slide {
namespace {

// A 0.3 m x 0.1 m block of phase 1 on the square lattice (dp = 0.01, corner at the origin) beside water of phase 0.
Particles<2> block_beside_water() {
  Particles<2> P;
  const double dp = 0.01;
  for (int j = 0; j < 10; ++j)
    for (int i = 0; i < 30; ++i) P.add(lattice_point(LatticeKind::square, dp, i, j), Kind::fluid, 1, 1950.0, 1.0);
  for (int j = 0; j < 20; ++j)
    for (int i = 30; i < 50; ++i) P.add(lattice_point(LatticeKind::square, dp, i, j), Kind::fluid, 0, 1000.0, 1e-3);
  P.add(Vec<2>(1.0, 0.05), Kind::wall, 1, 1000.0, 0.0);  // a boundary particle of the same phase index: not slide
  return P;
}

TEST(SlideFront, BlockFrontThicknessAndSurface) {
  const Particles<2> P = block_beside_water();
  const SlideFront f = measure_slide_front(P, 1, Vec<2>(1.0, 0.0), 0.01, 0.02);
  EXPECT_EQ(f.particles, 300u);
  EXPECT_NEAR(f.front[0], 0.295, 1e-12);  // the right-most column's centre
  EXPECT_NEAR(f.front[1], 0.005, 1e-12);  // the lowest id among that column's particles: the bottom row
  EXPECT_NEAR(f.thickness_max, 0.1, 1e-12);
  const auto top = slide_upper_surface(P, 1, 0.01, 0.02);
  ASSERT_EQ(top.size(), 15u);
  for (std::size_t k = 0; k < top.size(); ++k) {
    EXPECT_NEAR(top[k][0], 0.01 + 0.02 * k, 1e-12);
    EXPECT_NEAR(top[k][1], 0.1, 1e-12);
  }
}

// A right triangle (legs 0.2 m, hypotenuse facing down-right) measured down a 45 degree slope: the front is the
// particle furthest along (1, -1) / sqrt 2, its thickest column the vertical leg.
TEST(SlideFront, TriangleDownASlope) {
  Particles<2> P;
  const double dp = 0.01;
  for (int j = 0; j < 20; ++j)
    for (int i = 0; i < 20; ++i) {
      const Vec<2> x = lattice_point(LatticeKind::square, dp, i, j);
      if (x[1] > x[0]) P.add(x, Kind::fluid, 2, 1950.0, 1.0);  // above the diagonal y = x
    }
  const SlideFront f = measure_slide_front(P, 2, Vec<2>(1.0, -1.0).normalized(), dp, dp);
  // Along (1, -1): x - y is largest on the row of points next to the diagonal, (i + 1/2, i + 3/2) dp, x - y = -dp.
  EXPECT_NEAR(f.front[0] - f.front[1], -dp, 1e-12);
  EXPECT_NEAR(f.thickness_max, 0.19, 1e-12);  // column 0: rows 1 to 19
}


// In 3-D: a 0.2 m x 0.1 m x 0.05 m block of phase 1 (dp = 0.01, cubic, corner at the origin); its columns are 2 dp
// squares in (x, y), its thickness along z; a mirror image of it (a ghost) is not measured.
TEST(SlideFront, BlockIn3DIsMeasuredInColumnsOverXAndYWithoutItsImages) {
  Particles<3> P;
  const double dp = 0.01;
  for (int k = 0; k < 5; ++k)
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 20; ++i)
        P.add(Vec<3>((i + 0.5) * dp, (j + 0.5) * dp, (k + 0.5) * dp), Kind::fluid, 1, 1950.0, 1.0);
  P.add(Vec<3>(0.5, 0.05, 0.3), Kind::wall, 0, 1000.0, 0.0);  // a body's wall particle: not slide
  // A plane of symmetry at y = 0: the rows near it get images beyond it (fluid/ghosts.hpp), which are not measured.
  add_ghosts(P, GhostLayout{std::nullopt, {MirrorPlane{1, 0.0, true}}}, 0.03);
  ASSERT_EQ(P.ghost_count(), 300u);  // rows j = 0, 1, 2
  const SlideFrontOf<3> f = measure_slide_front(P, 1, Vec<3>(1.0, 0.0, 0.0), dp, 2.0 * dp);
  EXPECT_EQ(f.particles, 1000u);
  EXPECT_NEAR(f.front[0], 0.195, 1e-12);
  EXPECT_NEAR(f.thickness_max, 0.05, 1e-12);
  const auto top = slide_upper_surface(P, 1, dp, 2.0 * dp);
  ASSERT_EQ(top.size(), 50u);  // 10 x 5 columns
  for (std::size_t c = 0; c < top.size(); ++c) {
    EXPECT_NEAR(top[c][0], 0.01 + 0.02 * (c / 5), 1e-12);  // increasing x, then y
    EXPECT_NEAR(top[c][1], 0.01 + 0.02 * (c % 5), 1e-12);
    EXPECT_NEAR(top[c][2], 0.05, 1e-12);
  }
}

}  // namespace
}  // namespace slide
