#pragma once
// Cell-list neighbour search. Cells are at least as large as the search radius, so the neighbours of a point lie
// in its own cell and the 3^D cells around it. Points are binned with a stable counting sort, which also gives
// the cell order used to re-sort particles for cache locality.
//
// Within a cell the points come in index order, or, binned with a key, in the order of their keys (the particles'
// global ids: fluid/particles.hpp, order_key). With keys every neighbour sum runs in an order that depends on where the
// particles are and who they are, not on where they are stored: the same for any process's share of them, which the
// output's independence of the process count needs (DESIGN.md, "One domain seam").
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "fluid/parallel.hpp"
#include "fluid/vec.hpp"

namespace slide {

template <int D>
class NeighborGrid {
 public:
  NeighborGrid() = default;
  NeighborGrid(const Vec<D>& lo, const Vec<D>& hi, double cell_size) : lo_(lo), cell_size_(cell_size) {
    total_cells_ = 1;
    for (int k = 0; k < D; ++k) {
      cells_[k] = std::max(1, static_cast<int>(std::ceil((hi[k] - lo[k]) / cell_size)));
      total_cells_ *= cells_[k];
    }
  }

  double cell_size() const { return cell_size_; }
  const std::array<int, D>& cells() const { return cells_; }  // along each axis
  std::size_t total_cells() const { return total_cells_; }

  // Cell coordinates of x; points outside the box are put in the nearest edge cell (the caller checks the domain).
  std::array<int, D> cell_of(const Vec<D>& x) const {
    std::array<int, D> c;
    for (int k = 0; k < D; ++k) {
      const int ck = static_cast<int>(std::floor((x[k] - lo_[k]) / cell_size_));
      c[k] = std::clamp(ck, 0, cells_[k] - 1);
    }
    return c;
  }
  std::size_t linear(const std::array<int, D>& c) const {
    std::size_t l = 0;
    for (int k = D - 1; k >= 0; --k) l = l * cells_[k] + c[k];
    return l;
  }

  // Bins the points by cell (stable: equal cells keep index order).
  void bin(const std::vector<Vec<D>>& x) {
    const std::size_t n = x.size();
    point_cell_.resize(n);
    parallel_for(n, [&](std::size_t i) { point_cell_[i] = static_cast<std::uint32_t>(linear(cell_of(x[i]))); });
    cell_start_.assign(total_cells_ + 1, 0);
    for (std::size_t i = 0; i < n; ++i) ++cell_start_[point_cell_[i] + 1];
    for (std::size_t c = 0; c < total_cells_; ++c) cell_start_[c + 1] += cell_start_[c];
    sorted_.resize(n);
    std::vector<std::uint32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
    for (std::size_t i = 0; i < n; ++i) sorted_[fill[point_cell_[i]]++] = static_cast<std::uint32_t>(i);
  }

  // Bins the points by cell, and within a cell by key(i) (distinct keys; equal ones keep index order).
  template <class Key>
  void bin(const std::vector<Vec<D>>& x, Key&& key) {
    bin(x);
    // Insertion sort within each cell: cells hold tens of points, and after a re-sort by this same order nearly all of
    // them are in place already.
    parallel_for(total_cells_, [&](std::size_t c) {
      std::uint32_t* first = sorted_.data() + cell_start_[c];
      std::uint32_t* last = sorted_.data() + cell_start_[c + 1];
      for (std::uint32_t* p = first + 1; p < last; ++p) {
        const std::uint32_t j = *p;
        const auto kj = key(j);
        std::uint32_t* q = p;
        for (; q > first && key(q[-1]) > kj; --q) *q = q[-1];
        *q = j;
      }
    });
  }

  // Point indices ordered by cell: the permutation that re-sorts particles for locality.
  const std::vector<std::uint32_t>& sorted_indices() const { return sorted_; }

  // After the points were reordered by sorted_indices() (new point i is old point sorted_[i], positions unchanged):
  // the binning bin() would now give, without computing it again (with keys: bin with the same keys). Every cell
  // starts where it did, and the sorted order is the identity: the reordered points come cell by cell in index order,
  // which is bin's order (stable) and key order within a cell.
  void follow_reorder() {
    for (std::size_t s = 0; s < sorted_.size(); ++s) sorted_[s] = static_cast<std::uint32_t>(s);
  }

  // Calls f(j, r2) for every binned point j with |x_j - q|^2 < radius^2, in a fixed order (cells in lexicographic
  // order, points within a cell in index or key order). radius must not exceed the cell size.
  // Cells are numbered along x first and points are sorted by cell, so the cells of a row (fixed y, and z) that the
  // search visits hold one contiguous run of sorted points: each row is walked as one run, in the same order as cell
  // by cell (1 % faster on the bench case, stop 26; taking the run's points several at a time in SIMD lanes was not
  // faster still).
  template <class F>
  void for_each_near(const Vec<D>& q, double radius, const std::vector<Vec<D>>& x, F&& f) const {
    const double r2max = radius * radius;
    const auto c = cell_of(q);
    std::array<int, D> lo, hi;
    for (int k = 0; k < D; ++k) {
      lo[k] = std::max(c[k] - 1, 0);
      hi[k] = std::min(c[k] + 1, cells_[k] - 1);
    }
    std::array<int, D> row_lo = lo, row_hi = hi;
    auto walk_row = [&] {
      visit_run(cell_start_[linear(row_lo)], cell_start_[linear(row_hi) + 1], q, r2max, x, f);
    };
    if constexpr (D == 2) {
      for (int y = lo[1]; y <= hi[1]; ++y) {
        row_lo[1] = row_hi[1] = y;
        walk_row();
      }
    } else {
      for (int z = lo[2]; z <= hi[2]; ++z)
        for (int y = lo[1]; y <= hi[1]; ++y) {
          row_lo[1] = row_hi[1] = y;
          row_lo[2] = row_hi[2] = z;
          walk_row();
        }
    }
  }

 private:
  template <class F>
  void visit_run(std::uint32_t from, std::uint32_t to, const Vec<D>& q, double r2max, const std::vector<Vec<D>>& x,
                 F& f) const {
    std::uint32_t s = from;
    for (; s < to; ++s) {
      const std::uint32_t j = sorted_[s];
      const double r2 = distance_squared<D>(x[j], q);
      if (r2 < r2max) f(j, r2);
    }
  }

  Vec<D> lo_ = Vec<D>::Zero();
  double cell_size_ = 1.0;
  std::array<int, D> cells_{};
  std::size_t total_cells_ = 0;
  std::vector<std::uint32_t> point_cell_;  // bin's scratch: each point's cell (stale after follow_reorder)
  std::vector<std::uint32_t> cell_start_, sorted_;
};

// Neighbour list in blocks of `block_size` particles: each block's lists lie back to back in a vector of their own,
// particle i's at blocks[i / block_size][first[i] .. first[i] + count[i]). Why blocks: each is built by one thread
// without knowing the other blocks' sizes, and holds exactly what it found; the fixed 32 slots a particle before
// held about 20 neighbours (128 of the bench case's 560 heap bytes a particle). Kept for several steps: it is
// built with radius re + skin and is valid while no particle has moved more than half the skin since the build.
struct NeighborList {
  static constexpr std::size_t block_size = 512;
  std::vector<std::uint32_t> first, count;
  std::vector<std::vector<std::uint32_t>> blocks;

  const std::uint32_t* begin(std::size_t i) const { return blocks[i / block_size].data() + first[i]; }
  const std::uint32_t* end(std::size_t i) const { return begin(i) + count[i]; }
  // Neighbours listed, all particles together.
  std::size_t total() const {
    std::size_t t = 0;
    for (const auto& b : blocks) t += b.size();
    return t;
  }
};

// Storage for n elements and 1/16 more, so that the small changes from build to build rarely reallocate (a vector
// that grows by itself may double).
template <class T>
void reserve_with_margin(std::vector<T>& v, std::size_t n) {
  if (v.capacity() < n) v.reserve(n + n / 16);
}

// `to` becomes a copy of `from` in storage of its size and a margin (reserve_with_margin): what a block found into a
// thread's growing scratch is kept at about its size, not the up to twice that a growing vector holds.
template <class T>
void assign_with_margin(const std::vector<T>& from, std::vector<T>& to) {
  if (to.capacity() < from.size()) to = std::vector<T>();  // no copy of the old contents
  reserve_with_margin(to, from.size());
  to.assign(from.begin(), from.end());
}

// Builds the list of all j != i with |x_j - x_i| < radius from a grid already binned on x, in the grid's visiting
// order (fixed, so every sum over a list is too). Only the first `listed` points get a list (the others, periodic
// ghosts, are found as neighbours but have an empty list of their own); all of them by default.
template <int D>
void build_neighbor_list(const NeighborGrid<D>& grid, const std::vector<Vec<D>>& x, double radius,
                         NeighborList& list, std::size_t listed = static_cast<std::size_t>(-1)) {
  const std::size_t n = x.size();
  const std::size_t m = std::min(n, listed);
  const std::size_t bs = NeighborList::block_size;
  list.first.assign(n, 0);
  list.count.assign(n, 0);
  list.blocks.resize(std::max<std::size_t>(1, (n + bs - 1) / bs));  // a block's storage is kept from build to build
  parallel_for_blocks(list.blocks.size(), m, [&](std::size_t b) {
    // Found into the thread's own scratch, then copied (assign_with_margin).
    thread_local std::vector<std::uint32_t> found;
    found.clear();
    for (std::size_t i = b * bs; i < std::min(m, (b + 1) * bs); ++i) {
      list.first[i] = static_cast<std::uint32_t>(found.size());
      grid.for_each_near(x[i], radius, x, [&](std::uint32_t j, double) {
        if (j != i) found.push_back(j);
      });
      list.count[i] = static_cast<std::uint32_t>(found.size()) - list.first[i];
    }
    assign_with_margin(found, list.blocks[b]);
  });
}

}  // namespace slide
