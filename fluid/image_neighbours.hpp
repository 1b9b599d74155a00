#pragma once
// The fluid particles around each boundary particle's mirror image, with their pressure weights
// (fluid/wall_pressure.hpp): the mirror fill finds them through the grid at the predicted positions, and the mirror
// wall pressure, at the same positions, reads them instead of searching the grid again. Laid out in blocks of
// particles, as the neighbour list: each block is filled by one thread, in the particles' order.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "fluid/neighbor_grid.hpp"
#include "fluid/parallel.hpp"
#include "fluid/wall_pressure.hpp"

namespace slide {

class ImageNeighbours {
 public:
  static constexpr std::size_t block_size = 512;

  // For i = 0 .. n - 1: find(i, keep), where keep(f, w_f) adds fluid particle f with weight w_f to i's list.
  template <class Find>
  void take(std::size_t n, Find&& find) {
    first_.resize(n);
    count_.resize(n);
    blocks_.resize((n + block_size - 1) / block_size);  // a block's storage is kept from step to step
    parallel_for_blocks(blocks_.size(), n, [&](std::size_t b) {
      // Found into the thread's own scratch, then copied, as the neighbour list is (fluid/neighbor_grid.hpp): a
      // block's storage is then its size and a margin, not the up to twice that a growing vector holds.
      thread_local std::vector<ImageNeighbour> found;
      found.clear();
      for (std::size_t i = b * block_size; i < std::min(n, (b + 1) * block_size); ++i) {
        first_[i] = static_cast<std::uint32_t>(found.size());
        find(i, [&](std::uint32_t f, double w) { found.push_back({f, w}); });
        count_[i] = static_cast<std::uint32_t>(found.size()) - first_[i];
      }
      std::vector<ImageNeighbour>& block = blocks_[b];
      if (block.capacity() < found.size()) block = std::vector<ImageNeighbour>();  // no copy of the old contents
      reserve_with_margin(block, found.size());
      block.assign(found.begin(), found.end());
    });
  }
  const ImageNeighbour* begin(std::size_t i) const { return blocks_[i / block_size].data() + first_[i]; }
  const ImageNeighbour* end(std::size_t i) const { return begin(i) + count_[i]; }

 private:
  std::vector<std::uint32_t> first_, count_;
  std::vector<std::vector<ImageNeighbour>> blocks_;
};

}  // namespace slide
