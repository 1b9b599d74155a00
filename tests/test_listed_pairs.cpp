// The pair stages' lane-wise helpers (fluid/listed_pairs.hpp) against the one-pair-at-a-time formulas, bit for bit:
// every list length from 0 to past several lanes (so full lanes and the remainder both), pairs on the kernel
// radius, just inside and just beyond it, and a neighbour on top of the particle.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "fluid/kernel.hpp"
#include "fluid/listed_pairs.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"
#include "tests/bit_pattern.hpp"
#include "fluid/viscosity.hpp"

namespace slide {
namespace {

using testing::bits;

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
  x[0] = Vec<D>::Zero();  // so that the points below lie exactly where they say
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
      ASSERT_EQ(bits(w[k]), bits(expected)) << "count " << count << " pair " << k;
      if (r2 > 0.0) {
        ASSERT_EQ(bits(w_over_r2[k]), bits(expected / r2)) << "count " << count << " pair " << k;
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
    for (std::size_t k = 0; k < count; ++k) ASSERT_EQ(bits(alone[k]), bits(w[k]));
    // The derivative models' factor -W'(r) / r instead: the same weights, and the factor derivative_over_r gives
    // (+0 from re on), 3 / (re 0) = +inf on top of xi.
    std::vector<double> w_d(count + 1, -1.0), derivative(count + 1, -1.0);
    listed_kernel_weights<D, PairFactor::derivative_over_r>(xi, x, nb.data(), count, re, w_d.data(), derivative.data());
    for (std::size_t k = 0; k < count; ++k) {
      const double r = std::sqrt(distance_squared<D>(x[nb[k]], xi));
      ASSERT_EQ(bits(w_d[k]), bits(w[k])) << "count " << count << " pair " << k;
      if (r > 0.0) {
        ASSERT_EQ(bits(derivative[k]), bits(derivative_over_r(r, re))) << "count " << count << " pair " << k;
      } else {
        ASSERT_EQ(bits(derivative[k]), bits(derivative_over_r(0.0, re)));  // +inf
      }
    }
    ASSERT_EQ(derivative[count], -1.0) << "wrote past the list";
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

// The viscous acceleration, which takes its weights in lanes and adds zero terms of fluid neighbours beyond re, is
// the pair-by-pair sum over the neighbours within re to the bit: disordered fluid with a no-slip wall row, a list
// with a skin, unequal viscosities.
TEST(ListedPairs, ViscousAccelerationIsThePairByPairSumToTheBit) {
  const double dp = 0.01, re = 2.1 * dp, skin = 0.3 * dp;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> jitter(-0.2 * dp, 0.2 * dp), speed(-0.5, 0.5), mu(1e-3, 5e-3);
  Particles<2> P;
  for (int j = -1; j < 12; ++j)
    for (int i = 0; i < 12; ++i) {
      const bool wall = j < 0;
      const std::size_t p = P.add(Vec<2>((i + 0.5) * dp + (wall ? 0.0 : jitter(rng)), (j + 0.5) * dp + (wall ? 0.0 : jitter(rng))),
                                  wall ? Kind::wall : Kind::fluid, 0, 1000.0, mu(rng));
      if (wall) {
        P.wall_normal[p] = Vec<2>(0.0, 1.0);
        P.wall_depth[p] = 0.5 * dp;
      } else {
        P.velocity[p] = Vec<2>(speed(rng), speed(rng));
      }
    }
  NeighborGrid<2> grid(Vec<2>(-dp, -2 * dp), Vec<2>(13 * dp, 13 * dp), re + skin);
  grid.bin(P.position);
  NeighborList list;
  build_neighbor_list(grid, P.position, re + skin, list);
  const ViscousWall wall{WallSlip::no_slip, 0.5 * dp};
  std::size_t beyond = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::fluid) continue;
    Vec<2> sum = Vec<2>::Zero();
    for (const std::uint32_t* q = list.begin(i); q != list.end(i); ++q) {
      const double r2 = distance_squared<2>(P.position[*q], P.position[i]);
      if (r2 >= re * re) {
        ++beyond;
        continue;
      }
      sum += viscous_pair_term<2>(i, *q, r2, P, re, wall);
    }
    const Vec<2> expected = viscous_scale<2>(i, P, 1.0, 1.0) * sum;
    const Vec<2> a = viscous_acceleration<2>(i, P, list, re, 1.0, 1.0, wall);
    ASSERT_EQ(bits(a[0]), bits(expected[0])) << i;
    ASSERT_EQ(bits(a[1]), bits(expected[1])) << i;
  }
  EXPECT_GT(beyond, P.size());
}

}  // namespace
}  // namespace slide
