#pragma once
// The fluid particles around each boundary particle's mirror image, with their pressure weights
// (fluid/wall_pressure.hpp): the mirror fill finds them through the grid at the predicted positions, and the mirror
// wall pressure, at the same positions, reads them instead of searching the grid again. Laid out in blocks of
// particles, as the neighbour list, but only boundary particles have an entry (its particle and count, then its
// neighbours): 8 B for each of them and 16 B a kept neighbour, nothing for a fluid particle (one index per particle
// put the bench case at 16x the particles over 600 B a particle, stop 26). Each block is filled and read by one thread
// at a time, in the particles' order.
#include <algorithm>
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

  // For i = 0 .. n - 1: find(i, keep) returns whether i has an image (a boundary particle); keep(f, w_f) adds fluid
  // particle f with weight w_f to its list.
  template <class Find>
  void take(std::size_t n, Find&& find) {
    n_ = n;
    blocks_.resize((n + block_size - 1) / block_size);  // a block's storage is kept from step to step
    parallel_for_blocks(blocks_.size(), n, [&](std::size_t b) {
      // Found into the thread's own scratch, then copied, as the neighbour list is (assign_with_margin).
      thread_local std::vector<ImageNeighbour> found;
      thread_local std::vector<Owner> owners;
      found.clear();
      owners.clear();
      for (std::size_t i = b * block_size; i < std::min(n, (b + 1) * block_size); ++i) {
        const auto before = static_cast<std::uint32_t>(found.size());
        if (find(i, [&](std::uint32_t f, double w) { found.push_back({f, w}); }))
          owners.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(found.size()) - before});
      }
      assign_with_margin(found, blocks_[b].neighbours);
      assign_with_margin(owners, blocks_[b].owners);
    });
  }

  // use(i, begin, end) for every particle that had an image, with its kept neighbours; blocks in parallel.
  template <class Use>
  void for_each(Use&& use) const {
    parallel_for_blocks(blocks_.size(), n_, [&](std::size_t b) {
      const ImageNeighbour* q = blocks_[b].neighbours.data();
      for (const Owner& o : blocks_[b].owners) {
        use(static_cast<std::size_t>(o.particle), q, q + o.count);
        q += o.count;
      }
    });
  }

 private:
  struct Owner {
    std::uint32_t particle, count;
  };
  struct Block {
    std::vector<ImageNeighbour> neighbours;
    std::vector<Owner> owners;
  };
  std::size_t n_ = 0;
  std::vector<Block> blocks_;
};

}  // namespace slide
