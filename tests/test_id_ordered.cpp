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

// A process's share of a run on several processes: its ids are some of the run's, with nothing removed
// (removed_count 0: the share is not the run's id range). Each share by id, then the shares merged as one by id: what
// one process holding all of them writes. (Before: the share of ids 5..10 took the dense path and wrote past its
// arrays, measured as a heap corruption under mpirun.)
TEST(IdOrdered, SharesOfSeveralProcessesMergeAsOneById) {
  Particles<2> all, first, second;
  for (int i = 0; i < 11; ++i) {
    const Vec<2> x(0.1 * i, 0.02 * i);
    all.add(x, Kind::fluid, 0, 1000.0, 1e-3);
    Particles<2>& share = i % 3 == 1 || i > 6 ? second : first;
    const std::size_t k = share.add(x, Kind::fluid, 0, 1000.0, 1e-3);
    share.id[k] = static_cast<ParticleId>(i);
    share.pressure[k] = all.pressure[static_cast<std::size_t>(i)] = 10.0 * i;
  }
  std::vector<Vec<2>> buffer;
  second.reorder({4, 0, 3, 1, 5, 2}, buffer);
  const tools::IdOrdered<2> a(first), b(second), whole(all);
  expect_by_id(a, first);
  expect_by_id(b, second);
  std::vector<unsigned char> pieces = b.bytes(), first_bytes = a.bytes();
  pieces.insert(pieces.end(), first_bytes.begin(), first_bytes.end());
  const tools::IdOrdered<2> merged = tools::IdOrdered<2>::merged(pieces);
  EXPECT_EQ(merged.id, whole.id);
  EXPECT_EQ(merged.position, whole.position);
  EXPECT_EQ(merged.velocity, whole.velocity);
  EXPECT_EQ(merged.pressure, whole.pressure);
  EXPECT_EQ(merged.number_density, whole.number_density);
  EXPECT_EQ(merged.density, whole.density);
  EXPECT_EQ(merged.phase, whole.phase);
  EXPECT_EQ(merged.kind, whole.kind);
}

}  // namespace
}  // namespace slide
