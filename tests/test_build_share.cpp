// A 3-D scene built in parts (cases/build_share.hpp): the slabs of columns each process owns, cut where the counted
// particles reach an even part, cover every column once; the margin holds the columns either side; the axis is the one
// of the wider spread.
#include <gtest/gtest.h>

#include "cases/build_share.hpp"

namespace slide::cases {
namespace {

// 10 columns along x (0..9) of 10 particles each, all in one column along y; dp = 1.
BuildCount ten_columns_of_ten() {
  BuildCount count;
  for (int c = 0; c < 10; ++c)
    for (int k = 0; k < 10; ++k) count.add(Vec<3>(c + 0.5, 0.5, k + 0.5), 1.0);
  return count;
}

TEST(BuildShare, CountsEachParticleInItsColumnAlongBothAxesAndItsBox) {
  const BuildCount count = ten_columns_of_ten();
  EXPECT_EQ(count.particles, 100);
  ASSERT_EQ(count.per_column[0].size(), 10u);
  for (const auto& [column, n] : count.per_column[0]) EXPECT_EQ(n, 10) << column;
  ASSERT_EQ(count.per_column[1].size(), 1u);
  EXPECT_EQ(count.per_column[1].at(0), 100);
  EXPECT_EQ(count.lo, Vec<3>(0.5, 0.5, 0.5));
  EXPECT_EQ(count.hi, Vec<3>(9.5, 0.5, 9.5));
}

// Three processes: the second begins where 40 particles lie before (40 x 3 >= 100), the third where 70 do
// (70 x 3 >= 200); the first reaches down to any column, the last up to any.
TEST(BuildShare, CutsSlabsWhereTheCountReachesAnEvenPartAndCoversEveryColumnOnce) {
  const BuildCount count = ten_columns_of_ten();
  const BuildShare first(count, 1.0, 2, 3, 0), second(count, 1.0, 2, 3, 1), third(count, 1.0, 2, 3, 2);
  EXPECT_EQ(first.axis(), 0);
  for (int c = -50; c < 60; ++c) {
    const Vec<3> x(c + 0.5, 7.0, 3.0);
    const int owners = int(first.owns(x)) + int(second.owns(x)) + int(third.owns(x));
    EXPECT_EQ(owners, 1) << "column " << c;
    const int expected = c < 4 ? 0 : c < 7 ? 1 : 2;
    EXPECT_TRUE((expected == 0 ? first : expected == 1 ? second : third).owns(x)) << "column " << c;
  }
  EXPECT_EQ(first.owned(), 40);
  EXPECT_EQ(second.owned(), 30);
  EXPECT_EQ(third.owned(), 30);
  // The margin: 2 columns either side of the slab.
  EXPECT_EQ(second.held(), 70);  // columns 2..8
  EXPECT_TRUE(second.holds(Vec<3>(2.5, 0.0, 0.0)));
  EXPECT_FALSE(second.holds(Vec<3>(1.5, 0.0, 0.0)));
  EXPECT_TRUE(second.holds(Vec<3>(8.5, 0.0, 0.0)));
  EXPECT_FALSE(second.holds(Vec<3>(9.5, 0.0, 0.0)));
  EXPECT_EQ(first.held(), 60);  // columns 0..5
  EXPECT_EQ(third.held(), 50);  // columns 5..9
}

TEST(BuildShare, CutsAcrossTheAxisOfTheWiderSpread) {
  BuildCount count;
  for (int c = 0; c < 3; ++c)
    for (int d = 0; d < 8; ++d) count.add(Vec<3>(c * 0.1 + 0.05, d * 0.1 + 0.05, 0.0), 0.1);
  const BuildShare first(count, 0.1, 1, 2, 0), second(count, 0.1, 1, 2, 1);
  EXPECT_EQ(first.axis(), 1);
  EXPECT_EQ(first.owned(), 12);
  EXPECT_EQ(second.owned(), 12);
  EXPECT_TRUE(first.owns(Vec<3>(0.25, 0.35, 0.0)));
  EXPECT_TRUE(second.owns(Vec<3>(0.25, 0.45, 0.0)));
}

// One column heavier than an even part: the processes whose cut falls inside it own nothing, and every particle is
// still owned once.
TEST(BuildShare, LeavesAProcessEmptyWhereOneColumnHoldsMoreThanItsPart) {
  BuildCount count;
  for (int k = 0; k < 90; ++k) count.add(Vec<3>(0.5, 0.5, k + 0.5), 1.0);
  for (int k = 0; k < 10; ++k) count.add(Vec<3>(1.5, 0.5, k + 0.5), 1.0);
  std::int64_t owned = 0;
  for (int r = 0; r < 4; ++r) owned += BuildShare(count, 1.0, 1, 4, r).owned();
  EXPECT_EQ(owned, 100);
  EXPECT_EQ(BuildShare(count, 1.0, 1, 4, 0).owned(), 90);
  EXPECT_EQ(BuildShare(count, 1.0, 1, 4, 1).owned(), 0);
  EXPECT_EQ(BuildShare(count, 1.0, 1, 4, 3).owned(), 10);
}

}  // namespace
}  // namespace slide::cases
