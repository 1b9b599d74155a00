// The pair stages' lane-wise helpers (fluid/listed_pairs.hpp) against the one-pair-at-a-time formulas, bit for bit:
// every list length from 0 to past several lanes (so full lanes and the remainder both), pairs on the kernel
// radius, just inside and just beyond it, and a neighbour on top of the particle.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "fluid/kernel.hpp"
#include "fluid/listed_pairs.hpp"

namespace slide {
namespace {

template <int D>
std::vector<Vec<D>> scattered_points(std::size_t n, double re, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.3 * re, 1.3 * re);
  std::vector<Vec<D>> x(n);
  for (auto& p : x)
    for (int c = 0; c < D; ++c) p[c] = u(rng);
  return x;
}

template <int D>
void expect_weights_match_the_kernel() {
  const double re = 0.021;
  std::vector<Vec<D>> x = scattered_points<D>(40, re, 7);
  const Vec<D> xi = x[0];
  // Neighbours exactly on re, a rounding inside and beyond it, and on top of xi.
  Vec<D> e = Vec<D>::Zero();
  e[0] = 1.0;
  x.push_back(xi + re * e);
  x.push_back(xi + std::nextafter(re, 0.0) * e);
  x.push_back(xi + std::nextafter(re, 1.0) * e);
  x.push_back(xi);
  std::vector<std::uint32_t> nb;
  for (std::uint32_t j = static_cast<std::uint32_t>(x.size()) - 1; j >= 1; --j) nb.push_back(j);
  std::size_t zero = 0, inside = 0;
  for (std::size_t count = 0; count <= nb.size(); ++count) {
    std::vector<double> w(count + 1, -1.0), w_over_r2(count + 1, -1.0);
    listed_kernel_weights<D>(xi, x, nb.data(), count, re, w.data(), w_over_r2.data());
    for (std::size_t k = 0; k < count; ++k) {
      const double r2 = distance_squared<D>(x[nb[k]], xi);
      const double expected = kernel_weight(std::sqrt(r2), re);
      ASSERT_EQ(w[k], expected) << "count " << count << " pair " << k;
      if (r2 > 0.0) {
        ASSERT_EQ(w_over_r2[k], expected / r2) << "count " << count << " pair " << k;
      } else {
        ASSERT_TRUE(std::isinf(w_over_r2[k]));
      }
      zero += expected == 0.0;
      inside += expected > 0.0;
    }
    ASSERT_EQ(w[count], -1.0) << "wrote past the list";
    ASSERT_EQ(w_over_r2[count], -1.0) << "wrote past the list";
    // Without the W / r^2 output, the same weights.
    std::vector<double> alone(count);
    listed_kernel_weights<D>(xi, x, nb.data(), count, re, alone.data());
    for (std::size_t k = 0; k < count; ++k) ASSERT_EQ(alone[k], w[k]);
  }
  EXPECT_GT(zero, 0u);
  EXPECT_GT(inside, 0u);
}

TEST(ListedPairs, WeightsAreTheKernelsToTheBit2D) { expect_weights_match_the_kernel<2>(); }
TEST(ListedPairs, WeightsAreTheKernelsToTheBit3D) { expect_weights_match_the_kernel<3>(); }

// The weight just inside re is positive and the one on re is 0, as kernel_weight has them.
TEST(ListedPairs, WeightOnTheRadiusIsZero) {
  const double re = 0.021;
  const std::vector<Vec<2>> x = {Vec<2>(0.0, 0.0), Vec<2>(re, 0.0), Vec<2>(0.0, std::nextafter(re, 0.0)),
                                 Vec<2>(-2.0 * re, 0.0), Vec<2>(0.0, -0.5 * re)};
  const std::vector<std::uint32_t> nb = {1, 2, 3, 4};
  std::vector<double> w(4);
  listed_kernel_weights<2>(x[0], x, nb.data(), nb.size(), re, w.data());
  EXPECT_EQ(w[0], 0.0);
  EXPECT_GT(w[1], 0.0);
  EXPECT_EQ(w[2], 0.0);
  EXPECT_EQ(w[3], 0.125);
}

// any_listed_closer agrees with a pair-by-pair test for every list length and a close neighbour at every place.
TEST(ListedPairs, AnyCloserFindsTheOneCloseNeighbourWhereverItIsListed) {
  const double dp = 0.01, distance2 = 0.25 * dp * dp;
  std::vector<Vec<2>> x = {Vec<2>(0.0, 0.0)};
  for (int k = 0; k < 11; ++k) x.push_back(Vec<2>(dp * std::cos(k), dp * std::sin(k)));  // all at dp: not closer
  std::vector<std::uint32_t> nb;
  for (std::uint32_t j = 1; j < x.size(); ++j) nb.push_back(j);
  for (std::size_t count = 0; count <= nb.size(); ++count) {
    ASSERT_FALSE(any_listed_closer<2>(x[0], x, nb.data(), count, distance2)) << count;
    for (std::size_t at = 0; at < count; ++at) {
      std::vector<Vec<2>> y = x;
      y[nb[at]] = Vec<2>(0.49 * dp, 0.0);
      ASSERT_TRUE(any_listed_closer<2>(y[0], y, nb.data(), count, distance2)) << count << " " << at;
      y[nb[at]] = Vec<2>(0.5 * dp, 0.0);  // on the distance: not closer (r2 < distance2 is the test)
      ASSERT_EQ(any_listed_closer<2>(y[0], y, nb.data(), count, distance2),
                distance_squared<2>(y[nb[at]], y[0]) < distance2);
    }
  }
}

}  // namespace
}  // namespace slide
