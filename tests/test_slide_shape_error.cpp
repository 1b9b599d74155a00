// A slide's shape against a measured one (coupling/slide_shape_error.hpp) and a rigid outline's upper surface
// (coupling/slide_front.hpp): exact values on shapes made by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "coupling/slide_front.hpp"
#include "coupling/slide_shape_error.hpp"

namespace slide::testing {
namespace {

TEST(SlideShapeError, UpperEnvelopeSortsAndKeepsTheHighestPointAtEachX) {
  // Digitized in two strokes, doubling back, with a vertical front (two points at x = 0.4).
  const std::vector<Vec<2>> points{{0.2, 0.3}, {0.4, 0.25}, {0.1, 0.3}, {0.4, 0.1}, {0.3, 0.28}};
  const auto e = upper_envelope(points);
  ASSERT_EQ(e.size(), 4u);
  EXPECT_EQ(e[0], Vec<2>(0.1, 0.3));
  EXPECT_EQ(e[3], Vec<2>(0.4, 0.25));
  EXPECT_DOUBLE_EQ(envelope_at(e, 0.25), 0.29);
  EXPECT_DOUBLE_EQ(envelope_at(e, 0.1), 0.3);
  EXPECT_TRUE(std::isnan(envelope_at(e, 0.45)));
}

// Measured: a surface from (0, 0.2) to (1, 0) (a straight line y = 0.2 - 0.2 x), its front at 1, which started at
// 0.6: travel 0.4. Model: the same line 0.01 higher at three columns, front at 1.1: +25 % of the travel, rms 0.01.
TEST(SlideShapeError, FrontErrorInPerCentOfTheTravelAndRmsDistance) {
  const std::vector<Vec<2>> measured{{0.0, 0.2}, {0.5, 0.1}, {1.0, 0.0}};
  const std::vector<Vec<2>> model{{0.25, 0.16}, {0.5, 0.11}, {0.75, 0.06}, {1.05, 0.0}};  // the last beyond 1: left out
  const SlideShapeError e = slide_shape_error(measured, 0.6, model, 1.1);
  EXPECT_DOUBLE_EQ(e.front_measured, 1.0);
  EXPECT_DOUBLE_EQ(e.front_model, 1.1);
  EXPECT_NEAR(e.travel_measured, 0.4, 1e-15);
  EXPECT_NEAR(e.front_error_percent, 25.0, 1e-12);
  EXPECT_EQ(e.compared, 3u);
  EXPECT_NEAR(e.surface_rms_m, 0.01, 1e-12);
}

// A right triangle's upper surface: the hypotenuse where it is on top, sampled at the column centres inside.
TEST(SlideShapeError, PolygonUpperSurface) {
  // Triangle (0, 0.3), (0.4, 0.3), (0.4, 0): its top is the horizontal edge at 0.3 everywhere over [0, 0.4].
  const std::vector<Vec<2>> flat_top{{0.0, 0.3}, {0.4, 0.0}, {0.4, 0.3}};
  const auto s = polygon_upper_surface(flat_top, 0.1);
  ASSERT_EQ(s.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(s[k][0], 0.05 + 0.1 * k, 1e-12);
    EXPECT_NEAR(s[k][1], 0.3, 1e-12);
  }
  // Triangle (0, 0), (0.4, 0), (0, 0.4): its top is the hypotenuse y = 0.4 - x.
  const std::vector<Vec<2>> sloped{{0.0, 0.0}, {0.4, 0.0}, {0.0, 0.4}};
  const auto t = polygon_upper_surface(sloped, 0.1);
  ASSERT_EQ(t.size(), 4u);
  for (const auto& p : t) EXPECT_NEAR(p[1], 0.4 - p[0], 1e-12);
}

}  // namespace
}  // namespace slide::testing
