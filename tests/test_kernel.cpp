// Kernel, n0, lambda and kappa against brute-force lattice sums and their continuum limits.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

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

// The fcc lattice with one particle per dp^3: planes s = 2^(-1/3) dp = 0.7937 dp apart, nearest spacing s sqrt(2) =
// 1.1225 dp. With re = 2.1 dp its neighbours within re are 12 at s sqrt(2), 6 at 2 s = 1.587 dp and 24 at s sqrt(6) =
// 1.944 dp (the next, 12 at s sqrt(8) = 2.245 dp, lie beyond).
TEST(Kernel, FccLatticeConstantsByHand) {
  const double dp = 0.01, re = 2.1 * dp, s = dp * std::pow(2.0, -1.0 / 3.0);
  EXPECT_NEAR(nearest_spacing(LatticeKind::fcc, dp), std::sqrt(2.0) * s, 1e-15);
  EXPECT_NEAR(row_spacing(LatticeKind::fcc, dp), s, 1e-15);
  ASSERT_GT(std::sqrt(8.0) * s, re);
  const double r[] = {std::sqrt(2.0) * s, 2.0 * s, std::sqrt(6.0) * s};
  const int count[] = {12, 6, 24};
  double n0 = 0.0, wr2 = 0.0, dwr = 0.0;
  for (int k = 0; k < 3; ++k) {
    n0 += count[k] * kernel_weight(r[k], re);
    wr2 += count[k] * kernel_weight(r[k], re) * r[k] * r[k];
    dwr += count[k] * -kernel_derivative(r[k], re) * r[k];
  }
  const LatticeConstants c = lattice_constants<3>(dp, re, LatticeKind::fcc);
  EXPECT_NEAR(c.n0, n0, 1e-14);
  EXPECT_NEAR(c.lambda, wr2 / n0, 1e-18);
  EXPECT_NEAR(c.kappa, dwr / (3 * n0), 1e-12);
  EXPECT_THROW(lattice_constants<2>(dp, re, LatticeKind::fcc), std::invalid_argument);
}

// One particle per dp^3, so it tends to the same continuum values as the cubic lattice.
TEST(Kernel, FccContinuumLimit) {
  const double re = 1.0;
  double previous_error = 1e9;
  for (double ratio : {4.0, 8.0, 16.0}) {
    const double dp = re / ratio;
    const LatticeConstants c = lattice_constants<3>(dp, re, LatticeKind::fcc);
    const double error = std::abs((c.n0 + 1.0) * std::pow(dp, 3) - kernel_volume_integral<3>(re)) /
                         kernel_volume_integral<3>(re);
    EXPECT_LT(error, previous_error) << "ratio " << ratio;
    previous_error = error;
  }
  EXPECT_LT(previous_error, 1e-2);
  const LatticeConstants fine = lattice_constants<3>(re / 16.0, re, LatticeKind::fcc);
  EXPECT_NEAR(fine.lambda, continuum_lambda<3>(re), 0.01 * continuum_lambda<3>(re));
  EXPECT_NEAR(fine.kappa, 1.0, 0.02);
}

// The points for_each_lattice_point lays in 3-D: one per dp^3 on either lattice, and on the fcc lattice every point's
// twelve nearest neighbours at 2^(1/6) dp.
TEST(Kernel, LatticePointsIn3DHoldOnePerDpCubed) {
  const double dp = 0.01;
  for (const LatticeKind kind : {LatticeKind::square, LatticeKind::fcc}) {
    // A cube of a whole number of the lattice's periods along each axis: dp, or two planes of the fcc lattice.
    const double side = kind == LatticeKind::fcc ? 24 * row_spacing(kind, dp) : 20 * dp;
    const Vec<3> lo(0.0, 0.0, 0.0), hi(side, side, side);
    std::vector<Vec<3>> inside;
    for_each_lattice_point(kind, dp, lo, hi, [&](const Vec<3>& p) {
      if ((p.array() >= lo.array()).all() && (p.array() < hi.array()).all()) inside.push_back(p);
    });
    EXPECT_NEAR(double(inside.size()) * std::pow(dp, 3) / std::pow(side, 3), 1.0, 1e-12) << to_string(kind);
    Vec<3> centre = inside[0];  // the point nearest the cube's centre
    for (const auto& q : inside)
      if ((q - hi / 2).norm() < (centre - hi / 2).norm()) centre = q;
    int nearest = 0;
    double closest = 1e9;
    for (const auto& q : inside)
      if (q != centre) closest = std::min(closest, (q - centre).norm());
    for (const auto& q : inside)
      if (q != centre && (q - centre).norm() < closest * (1 + 1e-9)) ++nearest;
    EXPECT_NEAR(closest, nearest_spacing(kind, dp), 1e-12) << to_string(kind);
    EXPECT_EQ(nearest, kind == LatticeKind::fcc ? 12 : 6) << to_string(kind);
  }
  EXPECT_THROW(for_each_lattice_point(LatticeKind::hexagonal, dp, Vec<3>(Vec<3>::Zero()), Vec<3>(Vec<3>::Ones()),
                                      [](const Vec<3>&) {}),
               std::invalid_argument);
}

TEST(Kernel, ContinuumLimit2D) { expect_continuum_limit<2>(); }
TEST(Kernel, ContinuumLimit3D) { expect_continuum_limit<3>(); }

}  // namespace
}  // namespace slide
