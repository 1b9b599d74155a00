// Particles::reorder: every per-particle array gathered by the order, with more particles than a parallel loop's
// threshold (fluid/parallel.hpp), so that the gather runs on several threads where they are given.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "fluid/particles.hpp"

namespace slide {
namespace {

TEST(Particles, ReorderGathersEveryArrayByTheOrder) {
  constexpr std::size_t n = 3 * parallel_threshold + 17;
  Particles<2> P, original;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = static_cast<double>(i);
    const std::size_t k = P.add(Vec<2>(s, -s), static_cast<Kind>(i % 3), static_cast<std::uint8_t>(i % 2), 1000.0 + s,
                                1e-3 * s);
    P.velocity[k] = Vec<2>(2 * s, 3 * s);
    P.acceleration[k] = Vec<2>(-s, 4 * s);
    P.pressure[k] = 5 * s;
    P.number_density[k] = 6 * s;
    P.wall_fraction[k] = 7 * s;
    P.wall_normal[k] = Vec<2>(8 * s, 9 * s);
    P.wall_depth[k] = 10 * s;
    P.wall_fill[k] = 11 * s;
    P.body_frame[k] = static_cast<std::int32_t>(i) - 1;
  }
  original = P;
  std::vector<std::uint32_t> order(n);
  for (std::uint32_t i = 0; i < n; ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), std::mt19937(5));
  std::vector<Vec<2>> buffer;
  P.reorder(order, buffer);
  ASSERT_EQ(P.size(), n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t o = order[i];
    ASSERT_EQ(P.position[i], original.position[o]) << i;
    ASSERT_EQ(P.velocity[i], original.velocity[o]) << i;
    ASSERT_EQ(P.acceleration[i], original.acceleration[o]) << i;
    ASSERT_EQ(P.pressure[i], original.pressure[o]) << i;
    ASSERT_EQ(P.number_density[i], original.number_density[o]) << i;
    ASSERT_EQ(P.density[i], original.density[o]) << i;
    ASSERT_EQ(P.viscosity[i], original.viscosity[o]) << i;
    ASSERT_EQ(P.wall_fraction[i], original.wall_fraction[o]) << i;
    ASSERT_EQ(P.phase[i], original.phase[o]) << i;
    ASSERT_EQ(P.kind[i], original.kind[o]) << i;
    ASSERT_EQ(P.id[i], original.id[o]) << i;
    ASSERT_EQ(P.wall_normal[i], original.wall_normal[o]) << i;
    ASSERT_EQ(P.wall_depth[i], original.wall_depth[o]) << i;
    ASSERT_EQ(P.wall_fill[i], original.wall_fill[o]) << i;
    ASSERT_EQ(P.body_frame[i], original.body_frame[o]) << i;
  }
}

}  // namespace
}  // namespace slide
