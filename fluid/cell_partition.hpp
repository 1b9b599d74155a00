#pragma once
// Which process owns which cell of the neighbour grid (fluid/neighbor_grid.hpp): recursive coordinate bisection over
// the cells' weights (their particles). The cells are ordered across their longest axis (in cells), then the next
// longest, and so on; the first half of the processes takes the cells before the cut that gives it its share of the
// weight, and each half is cut again, until one process is left per set. Where a cut between two slabs across the
// axis comes within 0.5 % of the cells' weight of the share (1 % of an even half), it is taken there (a flat face: the fewest ghosts); otherwise inside the slab
// (a step, along the next axis). Every process computes the same map from the same weights (no communication, no
// randomness), and a process's particles are those of whole cells.
//
// Why the step (stop 57): cuts at slab boundaries only left parts 5-28 % off balance past 16 processes, where a slab
// weighs more than a share's error allows (tools/bench --partition; Zoltan's RCB, which splits slabs, reached
// 1.001-1.012); docs/using.md has the figures.
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
    std::vector<std::uint32_t> all(total);
    coordinates_.resize(total * D);
    for (std::size_t c = 0; c < total; ++c) {
      all[c] = static_cast<std::uint32_t>(c);
      std::size_t rest = c;
      for (int k = 0; k < D; ++k) {
        coordinates_[c * D + std::size_t(k)] = static_cast<int>(rest % static_cast<std::size_t>(cells[k]));
        rest /= static_cast<std::size_t>(cells[k]);
      }
    }
    bisect(all, 0, processes, weight);
    std::vector<int>().swap(coordinates_);
  }
  int owner(std::size_t cell) const { return owner_[cell]; }
  const std::vector<int>& owners() const { return owner_; }
  bool empty() const { return owner_.empty(); }

 private:
  int coordinate(std::uint32_t cell, int axis) const { return coordinates_[std::size_t(cell) * D + std::size_t(axis)]; }

  // Processes [first, last) share the cells `set` (at least last - first of them): the first half of the processes
  // the cells before the cut (order_and_cut), the others the rest.
  void bisect(std::vector<std::uint32_t>& set, int first, int last, const std::vector<std::int64_t>& weight) {
    if (last - first == 1) {
      for (const std::uint32_t c : set) owner_[c] = first;
      return;
    }
    const std::size_t cut = order_and_cut(set, (last - first) / 2, last - first, weight);
    std::vector<std::uint32_t> after(set.begin() + static_cast<std::ptrdiff_t>(cut), set.end());
    set.resize(cut);
    set.shrink_to_fit();
    const int middle = first + (last - first) / 2;
    bisect(set, first, middle, weight);
    bisect(after, middle, last, weight);
  }

  // Orders `set` across its axes, longest first (the first of equal extents), and returns where the first `left` of
  // `processes` take their share: the position (at least `left` cells before it and processes - left after) whose
  // weight before it is nearest left / processes of the set's, at a slab boundary where one comes within 0.5 % of
  // the set's weight (the lowest on a tie). A cell weighs its particles and 1/1024 of one, so that empty regions are
  // shared too, without weighing much against particles.
  // The cells are put in slabs across the longest axis (a counting sort); only a slab the cut may fall inside is
  // ordered along the other axes: the weight before a position grows with it, so the nearest lies at a slab boundary
  // or inside the slab where the share is crossed, or at the ends the cell counts allow.
  std::size_t order_and_cut(std::vector<std::uint32_t>& set, int left, int processes,
                            const std::vector<std::int64_t>& weight) const {
    std::array<int, D> lo, hi;
    lo.fill(INT32_MAX);
    hi.fill(-1);
    for (const std::uint32_t c : set)
      for (int k = 0; k < D; ++k) lo[k] = std::min(lo[k], coordinate(c, k)), hi[k] = std::max(hi[k], coordinate(c, k));
    std::array<int, D> axes;
    for (int k = 0; k < D; ++k) axes[k] = k;
    std::stable_sort(axes.begin(), axes.end(), [&](int a, int b) { return hi[a] - lo[a] > hi[b] - lo[b]; });
    const int a0 = axes[0];
    // Slabs across a0: slab_first[s] .. slab_first[s + 1] in `set`.
    std::vector<std::size_t> slab_first(static_cast<std::size_t>(hi[a0] - lo[a0]) + 2, 0);
    for (const std::uint32_t c : set) ++slab_first[static_cast<std::size_t>(coordinate(c, a0) - lo[a0]) + 1];
    for (std::size_t k = 1; k < slab_first.size(); ++k) slab_first[k] += slab_first[k - 1];
    {
      std::vector<std::size_t> next(slab_first.begin(), slab_first.end() - 1);
      std::vector<std::uint32_t> sorted(set.size());
      for (const std::uint32_t c : set) sorted[next[static_cast<std::size_t>(coordinate(c, a0) - lo[a0])]++] = c;
      set.swap(sorted);
    }
    const auto cell_weight = [&](std::uint32_t c) { return 1 + 1024 * weight[c]; };
    std::int64_t total = 0;
    for (const std::uint32_t c : set) total += cell_weight(c);
    // |before / total - left / processes| scaled by total processes: integers, no rounding.
    const auto distance = [&](std::int64_t before) { return std::abs(before * processes - total * left); };
    const std::size_t lowest = static_cast<std::size_t>(left), highest = set.size() - std::size_t(processes - left);
    std::size_t best_slab = 0, crossed = slab_first.size();  // crossed: the slab inside which the share is crossed
    std::int64_t best_slab_distance = 0, before = 0;
    for (std::size_t s = 0; s + 1 < slab_first.size(); ++s) {
      const std::int64_t start = before;
      for (std::size_t i = slab_first[s]; i < slab_first[s + 1]; ++i) before += cell_weight(set[i]);
      if (start * processes < total * left && before * processes > total * left) crossed = s;
      const std::size_t cut = slab_first[s + 1];
      if (cut < lowest || cut > highest) continue;
      const std::int64_t d = distance(before);
      if (best_slab == 0 || d < best_slab_distance) best_slab = cut, best_slab_distance = d;
    }
    if (best_slab != 0 && __int128(best_slab_distance) * 200 <= __int128(total) * processes) return best_slab;
    // Inside a slab: the one crossed, and those holding the ends the counts allow, each ordered along the other axes.
    const auto order_slab_holding = [&](std::size_t position) {
      const auto s = static_cast<std::size_t>(std::upper_bound(slab_first.begin(), slab_first.end(), position) -
                                              slab_first.begin()) - 1;
      order_slab(set, slab_first[s], slab_first[s + 1], axes);
    };
    if (crossed < slab_first.size()) order_slab(set, slab_first[crossed], slab_first[crossed + 1], axes);
    order_slab_holding(lowest);
    order_slab_holding(highest);
    std::size_t best = 0;
    std::int64_t best_distance = 0;
    before = 0;
    for (std::size_t cut = 1; cut <= highest; ++cut) {
      before += cell_weight(set[cut - 1]);
      if (cut < lowest) continue;
      const std::int64_t d = distance(before);
      if (best == 0 || d < best_distance) best = cut, best_distance = d;
    }
    return best;
  }

  // Orders set[begin, end), one slab, along the axes after the first (the others in `axes`' order).
  void order_slab(std::vector<std::uint32_t>& set, std::size_t begin, std::size_t end,
                  const std::array<int, D>& axes) const {
    std::sort(set.begin() + static_cast<std::ptrdiff_t>(begin), set.begin() + static_cast<std::ptrdiff_t>(end),
              [&](std::uint32_t a, std::uint32_t b) {
                for (int k = 1; k < D; ++k)
                  if (coordinate(a, axes[k]) != coordinate(b, axes[k]))
                    return coordinate(a, axes[k]) < coordinate(b, axes[k]);
                return false;
              });
  }

  std::array<int, D> cells_{};
  std::vector<int> coordinates_;  // D a cell, of the cells' indices (x fastest)
  std::vector<int> owner_;
};

}  // namespace slide
