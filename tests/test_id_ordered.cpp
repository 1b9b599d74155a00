// What a snapshot writes (tools/run_outputs.hpp IdOrdered): the real particles by id, whatever their order in the
// arrays, refilled in place by the last good state; with dense ids and with the gaps particles that left leave.
#include <gtest/gtest.h>

#include <numeric>

#include "tools/run_outputs.hpp"

namespace slide {
namespace {

void expect_by_id(const tools::IdOrdered<2>& s, const Particles<2>& P) {
  const std::size_t n = P.real_count();
  ASSERT_EQ(s.id.size(), n);
  ASSERT_EQ(s.position.size(), 2 * n);
  for (std::size_t k = 0; k + 1 < n; ++k) EXPECT_LT(s.id[k], s.id[k + 1]);
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(std::find(s.id.begin(), s.id.end(), P.id[i]) - s.id.begin());
    ASSERT_LT(k, n);
    EXPECT_EQ(s.position[2 * k], P.position[i][0]);
    EXPECT_EQ(s.position[2 * k + 1], P.position[i][1]);
    EXPECT_EQ(s.velocity[2 * k + 1], P.velocity[i][1]);
    EXPECT_EQ(s.pressure[k], P.pressure[i]);
    EXPECT_EQ(s.kind[k], static_cast<std::uint8_t>(P.kind[i]));
  }
}

TEST(IdOrdered, RefilledInPlaceFromShuffledDenseAndThenGappedIds) {
  Particles<2> P;
  for (int i = 0; i < 12; ++i) {
    const std::size_t k = P.add(Vec<2>(0.1 * i, 0.01 * i * i), i % 3 ? Kind::fluid : Kind::wall, 0, 1000.0, 1e-3);
    P.velocity[k] = Vec<2>(i, -i);
    P.pressure[k] = 100.0 * i;
  }
  std::vector<std::uint32_t> order{5, 3, 11, 0, 7, 1, 9, 2, 10, 4, 8, 6};
  std::vector<Vec<2>> buffer;
  P.reorder(order, buffer);
  tools::IdOrdered<2> s(P);
  expect_by_id(s, P);
  EXPECT_EQ(s.id, [] { std::vector<ParticleId> v(12); std::iota(v.begin(), v.end(), ParticleId{0}); return v; }());
  // Ids 3, 7 and 11 leave: the same snapshot, refilled, holds the nine others by id.
  P.remove_keeping_ids([&](std::size_t i) { return P.id[i] % 4 == 3; });
  s.assign(P);
  expect_by_id(s, P);
  EXPECT_EQ(s.id, (std::vector<ParticleId>{0, 1, 2, 4, 5, 6, 8, 9, 10}));
}

}  // namespace
}  // namespace slide
