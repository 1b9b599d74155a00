// The confining pressure of a pressure-dependent yield stress (fluid/confining_pressure.hpp) against exact answers:
// p_i in the bulk for a pressure linear in space, and the hand-computed mean of the midplane pressures for a
// particle of the free surface.
#include <gtest/gtest.h>

#include <cmath>

#include "fluid/confining_pressure.hpp"
#include "tests/lattice_block.hpp"

namespace slide {
namespace {

// p = a + b . x on the block: every interior particle (its whole kernel inside the block, a symmetric neighbourhood)
// gets p_i exactly, on both 2-D lattices and the cubic one.
template <int D>
void expect_linear_pressure_exact(LatticeKind kind) {
  testing::Lattice<D> block(kind);
  auto& P = block.particles;
  Vec<D> b = Vec<D>::Zero();
  b[0] = 300.0, b[D - 1] = -1900.0;
  for (std::size_t i = 0; i < P.size(); ++i) P.pressure[i] = 5000.0 + b.dot(P.position[i]);
  int checked = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!block.interior(i)) continue;
    EXPECT_NEAR(confining_pressure<D>(i, P, block.list, block.re), P.pressure[i], 1e-9 * P.pressure[i]) << i;
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

TEST(ConfiningPressure, LinearPressureExactInTheBulkSquare) { expect_linear_pressure_exact<2>(LatticeKind::square); }
TEST(ConfiningPressure, LinearPressureExactInTheBulkHexagonal) {
  expect_linear_pressure_exact<2>(LatticeKind::hexagonal);
}
TEST(ConfiningPressure, LinearPressureExactInTheBulkCubic) { expect_linear_pressure_exact<3>(LatticeKind::square); }

// A particle of the top row of the square block (free-surface condition: p = 0 on the whole top row) over a
// hydrostatic column p = rho g (depth): with re = 2.1 dp its fluid neighbours are 4 in its own row (p = 0, at dp and
// 2 dp), 3 one row down (p = rho g dp; at dp and sqrt(2) dp) and 1 two rows down (p = 2 rho g dp, at 2 dp; those at
// sqrt(5) dp lie beyond re): p_c = 0 / 2 + sum W p / (2 sum W), by hand below.
TEST(ConfiningPressure, FreeSurfaceParticleGetsItsNeighboursMidplanePressures) {
  testing::Lattice<2> block;
  auto& P = block.particles;
  const double dp = block.dp, re = block.re, rho_g_dp = 1950.0 * 9.81 * dp;
  const double top = P.position[0][1] + (testing::Lattice<2>::side - 1) * dp;
  for (std::size_t i = 0; i < P.size(); ++i) P.pressure[i] = rho_g_dp * std::round((top - P.position[i][1]) / dp);
  const std::size_t i = P.size() - 1 - testing::Lattice<2>::side / 2;  // the top row's middle particle
  ASSERT_NEAR(P.position[i][1], top, 1e-12);
  ASSERT_EQ(P.pressure[i], 0.0);
  auto w = [&](double r_over_dp) { return kernel_weight(r_over_dp * dp, re); };
  const double same_row = 2 * w(1) + 2 * w(2);
  const double one_down = w(1) + 2 * w(std::sqrt(2.0));
  const double two_down = w(2);
  const double mean = (one_down * rho_g_dp + two_down * 2 * rho_g_dp) / (same_row + one_down + two_down);
  EXPECT_NEAR(confining_pressure<2>(i, P, block.list, re), 0.5 * mean, 1e-12 * rho_g_dp);
  EXPECT_GT(confining_pressure<2>(i, P, block.list, re), 0.0);
}

}  // namespace
}  // namespace slide
