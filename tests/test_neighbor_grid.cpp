// The cell-list neighbour search against brute force on random points.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "fluid/neighbor_grid.hpp"

namespace slide {
namespace {

template <int D>
std::vector<Vec<D>> random_points(std::size_t n, double size, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, size);
  std::vector<Vec<D>> x(n);
  for (auto& p : x)
    for (int k = 0; k < D; ++k) p[k] = u(rng);
  return x;
}

template <int D>
void expect_list_matches_brute_force(std::size_t n, double radius) {
  const auto x = random_points<D>(n, 1.0, 42 + D);
  NeighborGrid<D> grid(Vec<D>::Zero(), Vec<D>::Ones(), radius);
  grid.bin(x);
  NeighborList list;
  build_neighbor_list(grid, x, radius, list);
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<std::uint32_t> expected, got(list.begin(i), list.end(i));
    for (std::size_t j = 0; j < n; ++j)
      if (j != i && distance_squared<D>(x[i], x[j]) < radius * radius) expected.push_back(static_cast<std::uint32_t>(j));
    std::sort(got.begin(), got.end());
    ASSERT_EQ(got, expected) << "particle " << i;
  }
}

TEST(NeighborGrid, MatchesBruteForce2D) { expect_list_matches_brute_force<2>(2000, 0.05); }
TEST(NeighborGrid, MatchesBruteForce3D) { expect_list_matches_brute_force<3>(2000, 0.12); }

// Rebuilt on other points, with more particles than a parallel loop's threshold and only the first ones listed (as
// periodic ghosts are not): each block keeps its storage, and no list keeps anything of the build before.
TEST(NeighborGrid, RebuildingListsExactlyTheNewNeighboursInEveryBlock) {
  const double radius = 0.02;
  NeighborGrid<2> grid(Vec<2>::Zero(), Vec<2>::Ones(), radius);
  NeighborList list;
  for (unsigned seed : {3u, 4u}) {
    const auto x = random_points<2>(seed == 3 ? 9000 : 7000, 1.0, seed);
    const std::size_t listed = x.size() - 600;
    grid.bin(x);
    build_neighbor_list(grid, x, radius, list, listed);
    ASSERT_EQ(list.blocks.size(), (x.size() + NeighborList::block_size - 1) / NeighborList::block_size);
    std::size_t total = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      std::vector<std::uint32_t> expected, got(list.begin(i), list.end(i));
      if (i < listed)
        for (std::size_t j = 0; j < x.size(); ++j)
          if (j != i && distance_squared<2>(x[i], x[j]) < radius * radius)
            expected.push_back(static_cast<std::uint32_t>(j));
      std::sort(got.begin(), got.end());
      ASSERT_EQ(got, expected) << "seed " << seed << ", particle " << i;
      total += expected.size();
    }
    EXPECT_EQ(list.total(), total);
  }
}

TEST(NeighborGrid, SortedIndicesArePermutationGroupedByCell) {
  const auto x = random_points<2>(500, 1.0, 7);
  NeighborGrid<2> grid(Vec<2>::Zero(), Vec<2>::Ones(), 0.1);
  grid.bin(x);
  auto order = grid.sorted_indices();
  std::vector<std::size_t> cells;
  for (auto i : order) cells.push_back(grid.linear(grid.cell_of(x[i])));
  EXPECT_TRUE(std::is_sorted(cells.begin(), cells.end()));
  std::sort(order.begin(), order.end());
  for (std::size_t i = 0; i < order.size(); ++i) EXPECT_EQ(order[i], i);
}

// Points reordered by the sorted indices: follow_reorder gives exactly the binning a fresh bin of them gives (the step
// relies on it instead of binning again), and the neighbour lists built from it are the same, in the same order.
template <int D>
void expect_follow_reorder_equals_fresh_bin(std::size_t n, double radius) {
  const auto x = random_points<D>(n, 1.0, 11 + D);
  NeighborGrid<D> followed(Vec<D>::Zero(), Vec<D>::Ones(), radius), fresh = followed;
  followed.bin(x);
  std::vector<Vec<D>> sorted;
  for (const auto i : followed.sorted_indices()) sorted.push_back(x[i]);
  followed.follow_reorder();
  fresh.bin(sorted);
  ASSERT_EQ(followed.sorted_indices(), fresh.sorted_indices());
  NeighborList a, b;
  build_neighbor_list(followed, sorted, radius, a);
  build_neighbor_list(fresh, sorted, radius, b);
  for (std::size_t i = 0; i < n; ++i)
    ASSERT_EQ(std::vector<std::uint32_t>(a.begin(i), a.end(i)), std::vector<std::uint32_t>(b.begin(i), b.end(i)))
        << "particle " << i;
}

TEST(NeighborGrid, FollowingAReorderBinsAsAFreshBinDoes2D) { expect_follow_reorder_equals_fresh_bin<2>(6000, 0.03); }
TEST(NeighborGrid, FollowingAReorderBinsAsAFreshBinDoes3D) { expect_follow_reorder_equals_fresh_bin<3>(6000, 0.1); }

// Binned with keys (a particle's global id), every list names the same particles in the same order for any storage
// order: the same points shuffled give lists equal key for key, and the order within a cell is by key. What a
// process's share of the particles, stored in its own order, needs for its sums to match one process's.
template <int D>
void expect_keyed_lists_independent_of_storage(std::size_t n, double radius) {
  const auto x = random_points<D>(n, 1.0, 5 + D);
  std::vector<std::uint64_t> key(n);
  for (std::size_t i = 0; i < n; ++i) key[i] = 1000 + 7 * ((i * 7919) % n);  // distinct, unrelated to the index
  std::vector<std::uint32_t> perm(n);
  for (std::size_t i = 0; i < n; ++i) perm[i] = static_cast<std::uint32_t>(i);
  std::shuffle(perm.begin(), perm.end(), std::mt19937_64(3));
  std::vector<Vec<D>> y(n);
  std::vector<std::uint64_t> key_y(n);
  for (std::size_t i = 0; i < n; ++i) y[i] = x[perm[i]], key_y[i] = key[perm[i]];
  NeighborGrid<D> gx(Vec<D>::Zero(), Vec<D>::Ones(), radius), gy = gx;
  gx.bin(x, [&](std::uint32_t j) { return key[j]; });
  gy.bin(y, [&](std::uint32_t j) { return key_y[j]; });
  NeighborList lx, ly;
  build_neighbor_list(gx, x, radius, lx);
  build_neighbor_list(gy, y, radius, ly);
  std::size_t nonempty = 0;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<std::uint64_t> a, b;
    for (const std::uint32_t* q = lx.begin(perm[i]); q != lx.end(perm[i]); ++q) a.push_back(key[*q]);
    for (const std::uint32_t* q = ly.begin(i); q != ly.end(i); ++q) b.push_back(key_y[*q]);
    ASSERT_EQ(a, b) << "particle " << perm[i];
    nonempty += !a.empty();
  }
  EXPECT_GT(nonempty, n / 2);
  // Within a cell: increasing keys (cells are contiguous in the sorted indices).
  const auto& s = gx.sorted_indices();
  std::size_t in_key_order = 0;
  for (std::size_t k = 1; k < n; ++k) {
    const auto a = gx.cell_of(x[s[k - 1]]), b = gx.cell_of(x[s[k]]);
    if (a == b) {
      ASSERT_LT(key[s[k - 1]], key[s[k]]);
      ++in_key_order;
    }
  }
  EXPECT_GT(in_key_order, n / 2);
}

TEST(NeighborGrid, KeyedListsDoNotDependOnTheStorageOrder2D) { expect_keyed_lists_independent_of_storage<2>(5000, 0.04); }
TEST(NeighborGrid, KeyedListsDoNotDependOnTheStorageOrder3D) { expect_keyed_lists_independent_of_storage<3>(5000, 0.12); }

TEST(NeighborGrid, PointQueryMatchesBruteForce) {
  const auto x = random_points<2>(1000, 1.0, 9);
  NeighborGrid<2> grid(Vec<2>::Zero(), Vec<2>::Ones(), 0.08);
  grid.bin(x);
  const Vec<2> q(0.43, 0.61);
  std::vector<std::uint32_t> got, expected;
  grid.for_each_near(q, 0.08, x, [&](std::uint32_t j, double) { got.push_back(j); });
  for (std::size_t j = 0; j < x.size(); ++j)
    if (distance_squared<2>(x[j], q) < 0.08 * 0.08) expected.push_back(static_cast<std::uint32_t>(j));
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, expected);
}

}  // namespace
}  // namespace slide
