// Kernel, n0, lambda and kappa against brute-force lattice sums and their continuum limits.
#include <gtest/gtest.h>

#include <cmath>

#include "fluid/kernel.hpp"
#include "fluid/lattice.hpp"

namespace slide {
namespace {

TEST(Kernel, SeedFormula) {
  EXPECT_DOUBLE_EQ(kernel_weight(0.0, 2.0), 1.0);
  EXPECT_DOUBLE_EQ(kernel_weight(1.0, 2.0), 0.125);
  EXPECT_DOUBLE_EQ(kernel_weight(2.0, 2.0), 0.0);
  EXPECT_DOUBLE_EQ(kernel_weight(3.0, 2.0), 0.0);
  // The derivative agrees with a central difference.
  for (double r : {0.1, 0.7, 1.3, 1.9}) {
    const double h = 1e-6;
    EXPECT_NEAR(kernel_derivative(r, 2.0), (kernel_weight(r + h, 2.0) - kernel_weight(r - h, 2.0)) / (2 * h), 1e-8);
  }
}

// The derivative gradients' pair factor -W'(r) / r = 3 (1 - r/re)^2 / (re r): exact values, and +0 (not -0) from re on,
// so that a kept factor beyond re adds nothing to a sum.
TEST(Kernel, DerivativeOverR) {
  EXPECT_EQ(derivative_over_r(1.0, 2.0), 0.375);   // 3 (1/2)^2 / (2 * 1)
  EXPECT_EQ(derivative_over_r(0.5, 2.0), 1.6875);  // 3 (3/4)^2 / (2 * 0.5)
  for (double r : {2.0, 2.5}) {
    EXPECT_EQ(derivative_over_r(r, 2.0), 0.0);
    EXPECT_FALSE(std::signbit(derivative_over_r(r, 2.0)));
  }
  EXPECT_TRUE(std::isinf(derivative_over_r(0.0, 2.0)));
}

// Lattice sums written out by hand for re = 2.1 dp in 2-D: neighbours at 1 (4), sqrt 2 (4) and 2 (4) spacings.
TEST(Kernel, LatticeConstants2DByHand) {
  const double dp = 0.01, re = 2.1 * dp;
  const double w1 = std::pow(1 - 1 / 2.1, 3), w2 = std::pow(1 - std::sqrt(2.0) / 2.1, 3), w3 = std::pow(1 - 2 / 2.1, 3);
  const double n0 = 4 * (w1 + w2 + w3);
  const double lambda = 4 * (w1 * 1 + w2 * 2 + w3 * 4) * dp * dp / n0;
  const LatticeConstants c = lattice_constants<2>(dp, re);
  EXPECT_NEAR(c.n0, n0, 1e-14);
  EXPECT_NEAR(c.lambda, lambda, 1e-18);
}

// 3-D, re = 1.5 dp: neighbours at 1 (6) and sqrt 2 (12) spacings.
TEST(Kernel, LatticeConstants3DByHand) {
  const double dp = 1.0, re = 1.5;
  const double w1 = std::pow(1 - 1 / 1.5, 3), w2 = std::pow(1 - std::sqrt(2.0) / 1.5, 3);
  const LatticeConstants c = lattice_constants<3>(dp, re);
  EXPECT_NEAR(c.n0, 6 * w1 + 12 * w2, 1e-14);
  EXPECT_NEAR(c.lambda, (6 * w1 + 12 * w2 * 2) / (6 * w1 + 12 * w2), 1e-14);
}

// As dp -> 0 with re fixed, n0 dp^d tends to the integral of W and lambda to its continuum value.
template <int D>
void expect_continuum_limit() {
  const double re = 1.0;
  double previous_error = 1e9;
  for (double ratio : {4.0, 8.0, 16.0, 32.0}) {
    const double dp = re / ratio;
    const LatticeConstants c = lattice_constants<D>(dp, re);
    // n0 excludes the origin's W(0) = 1; the integral includes the whole support.
    const double integral = (c.n0 + 1.0) * std::pow(dp, D);
    const double error = std::abs(integral - kernel_volume_integral<D>(re)) / kernel_volume_integral<D>(re);
    EXPECT_LT(error, previous_error) << "ratio " << ratio;
    previous_error = error;
  }
  EXPECT_LT(previous_error, 2e-3);
  const LatticeConstants fine = lattice_constants<D>(re / 32.0, re);
  EXPECT_NEAR(fine.lambda, continuum_lambda<D>(re), 0.01 * continuum_lambda<D>(re));
  EXPECT_NEAR(fine.kappa, 1.0, 0.01);
}

// The hexagonal lattice with one particle per dp^2 has nearest spacing a = 1.0746 dp; with re = 2.1 dp its
// neighbours within re are 6 at a and 6 at sqrt(3) a = 1.861 dp (the next, 6 at 2 a = 2.149 dp, lie beyond).
TEST(Kernel, HexagonalLatticeConstantsByHand) {
  const double dp = 0.01, re = 2.1 * dp;
  const double a = nearest_spacing(LatticeKind::hexagonal, dp), b = std::sqrt(3.0) * a;
  EXPECT_NEAR(a * row_spacing(LatticeKind::hexagonal, dp), dp * dp, 1e-18);  // one particle per dp^2
  ASSERT_GT(2 * a, re);
  const double w1 = kernel_weight(a, re), w2 = kernel_weight(b, re);
  const double n0 = 6 * (w1 + w2);
  const LatticeConstants c = lattice_constants<2>(dp, re, LatticeKind::hexagonal);
  EXPECT_NEAR(c.n0, n0, 1e-14);
  EXPECT_NEAR(c.lambda, 6 * (w1 * a * a + w2 * b * b) / n0, 1e-18);
  EXPECT_NEAR(c.kappa, 6 * (-kernel_derivative(a, re) * a - kernel_derivative(b, re) * b) / (2 * n0), 1e-12);
  // The square lattice is what the two-argument form gives.
  const LatticeConstants s = lattice_constants<2>(dp, re, LatticeKind::square), s2 = lattice_constants<2>(dp, re);
  EXPECT_EQ(s.n0, s2.n0);
  EXPECT_EQ(s.lambda, s2.lambda);
  EXPECT_THROW(lattice_constants<3>(dp, re, LatticeKind::hexagonal), std::invalid_argument);
}

// Both lattices hold one particle per dp^2, so both tend to the same continuum values.
TEST(Kernel, HexagonalContinuumLimit) {
  const double re = 1.0;
  double previous_error = 1e9;
  for (double ratio : {4.0, 8.0, 16.0, 32.0}) {
    const double dp = re / ratio;
    const LatticeConstants c = lattice_constants<2>(dp, re, LatticeKind::hexagonal);
    const double error = std::abs((c.n0 + 1.0) * dp * dp - kernel_volume_integral<2>(re)) / kernel_volume_integral<2>(re);
    EXPECT_LT(error, previous_error) << "ratio " << ratio;
    previous_error = error;
  }
  EXPECT_LT(previous_error, 2e-3);
  const LatticeConstants fine = lattice_constants<2>(re / 32.0, re, LatticeKind::hexagonal);
  EXPECT_NEAR(fine.lambda, continuum_lambda<2>(re), 0.01 * continuum_lambda<2>(re));
  EXPECT_NEAR(fine.kappa, 1.0, 0.01);
}

TEST(Kernel, ContinuumLimit2D) { expect_continuum_limit<2>(); }
TEST(Kernel, ContinuumLimit3D) { expect_continuum_limit<3>(); }

}  // namespace
}  // namespace slide
