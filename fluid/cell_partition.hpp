#pragma once
// Which process owns which cell of the neighbour grid (fluid/neighbor_grid.hpp): recursive coordinate bisection over
// the cells' weights (their particles). The grid's box of cells is cut across its longest axis (in cells) at the cell
// boundary that gives the first half of the processes their share of the weight, and each half is cut again, until
// one process is left per box. Every process computes the same map from the same weights (no communication, no
// randomness), and the cut lies at a cell boundary, so a process's particles are those of whole cells.
//
// Only the partition's balance depends on this choice: the results do not (fluid/domain.hpp: every neighbour sum and
// every sum over particles is taken in an order of ids, whoever owns them).
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace slide {

template <int D>
class CellPartition {
 public:
  CellPartition() = default;
  // weight[c]: the weight of the grid's linear cell c (x fastest). Throws std::invalid_argument when there are fewer
  // cells than processes.
  CellPartition(const std::array<int, D>& cells, const std::vector<std::int64_t>& weight, int processes)
      : cells_(cells), owner_(weight.size(), 0) {
    std::size_t total = 1;
    for (int k = 0; k < D; ++k) total *= static_cast<std::size_t>(cells[k]);
    if (total != weight.size()) throw std::logic_error("CellPartition: one weight per cell");
    if (total < static_cast<std::size_t>(processes))
      throw std::invalid_argument("the neighbour grid has " + std::to_string(total) + " cells, fewer than the " +
                                  std::to_string(processes) + " processes: use fewer processes");
    std::array<int, D> lo{}, hi = cells;
    bisect(lo, hi, 0, processes, weight);
  }
  int owner(std::size_t cell) const { return owner_[cell]; }
  const std::vector<int>& owners() const { return owner_; }
  bool empty() const { return owner_.empty(); }

 private:
  std::size_t linear(const std::array<int, D>& c) const {
    std::size_t l = 0;
    for (int k = D - 1; k >= 0; --k) l = l * static_cast<std::size_t>(cells_[k]) + static_cast<std::size_t>(c[k]);
    return l;
  }
  // Calls f(c) for every cell of the box [lo, hi).
  template <class F>
  void for_each_cell(const std::array<int, D>& lo, const std::array<int, D>& hi, F&& f) const {
    std::array<int, D> c = lo;
    for (int k = 0; k < D; ++k)
      if (lo[k] >= hi[k]) return;
    while (true) {
      f(c);
      int k = 0;
      for (; k < D; ++k) {
        if (++c[k] < hi[k]) break;
        c[k] = lo[k];
      }
      if (k == D) return;
    }
  }
  static std::size_t volume(const std::array<int, D>& lo, const std::array<int, D>& hi) {
    std::size_t v = 1;
    for (int k = 0; k < D; ++k) v *= static_cast<std::size_t>(hi[k] - lo[k]);
    return v;
  }

  // Processes [first, last) share the box [lo, hi), which has at least last - first cells. Half of them (the first
  // (last - first) / 2) on one side of a cut across its longest axis; where no cut there leaves each side a cell per
  // process, across the next longest; and where no axis has one, the processes are split unevenly (one more, one
  // fewer on the first side, and so on), each side's weight in proportion.
  void bisect(const std::array<int, D>& lo, const std::array<int, D>& hi, int first, int last,
              const std::vector<std::int64_t>& weight) {
    if (last - first == 1) {
      for_each_cell(lo, hi, [&](const std::array<int, D>& c) { owner_[linear(c)] = first; });
      return;
    }
    std::array<int, D> axes;
    for (int k = 0; k < D; ++k) axes[k] = k;
    std::stable_sort(axes.begin(), axes.end(), [&](int a, int b) { return hi[a] - lo[a] > hi[b] - lo[b]; });
    const int n = last - first;
    for (int step = 0; step < 2 * n; ++step) {
      const int left = n / 2 + (step % 2 == 0 ? step / 2 : -(step + 1) / 2);
      if (left < 1 || left >= n) continue;
      for (const int axis : axes) {
        const int cut = best_cut(lo, hi, axis, left, n - left, weight);
        if (cut < 0) continue;
        std::array<int, D> mid_hi = hi, mid_lo = lo;
        mid_hi[axis] = mid_lo[axis] = lo[axis] + cut;
        bisect(lo, mid_hi, first, first + left, weight);
        bisect(mid_lo, hi, first + left, last, weight);
        return;
      }
    }
    throw std::invalid_argument("the neighbour grid's cells cannot be shared among " + std::to_string(last - first) +
                                " processes: use fewer processes");
  }

  // The cut across `axis` (slabs from lo[axis], -1 if none) whose weight before it is nearest left/(left + right) of
  // the box's, among those that leave each side at least as many cells as processes (the lowest on a tie).
  int best_cut(const std::array<int, D>& lo, const std::array<int, D>& hi, int axis, int left, int right,
               const std::vector<std::int64_t>& weight) const {
    // The weight of each slab of the box across `axis`: its particles, and a 1/1024 of one for each cell, so that
    // empty regions are shared too, without weighing much against particles.
    std::vector<std::int64_t> slab(static_cast<std::size_t>(hi[axis] - lo[axis]), 0);
    for_each_cell(lo, hi, [&](const std::array<int, D>& c) {
      slab[static_cast<std::size_t>(c[axis] - lo[axis])] += 1 + 1024 * weight[linear(c)];
    });
    std::int64_t total = 0;
    for (const std::int64_t w : slab) total += w;
    const std::size_t across = volume(lo, hi) / slab.size();  // cells in one slab
    int best = -1;
    std::int64_t best_distance = 0, before = 0;
    for (int s = 1; s < static_cast<int>(slab.size()); ++s) {
      before += slab[static_cast<std::size_t>(s - 1)];
      const std::size_t cells_left = across * static_cast<std::size_t>(s);
      const std::size_t cells_right = across * (slab.size() - static_cast<std::size_t>(s));
      if (cells_left < static_cast<std::size_t>(left) || cells_right < static_cast<std::size_t>(right)) continue;
      // |before / total - left / (left + right)| scaled by total (left + right): integers, no rounding.
      const std::int64_t distance = std::abs(before * (left + right) - total * left);
      if (best < 0 || distance < best_distance) {
        best = s;
        best_distance = distance;
      }
    }
    return best;
  }

  std::array<int, D> cells_{};
  std::vector<int> owner_;
};

}  // namespace slide
