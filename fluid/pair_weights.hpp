#pragma once
// The W / r^2 factor (W(|r_ij|) / |r_ij|^2, seed eq. 6 over the squared distance) of every listed pair at one set of
// positions, laid out as the neighbour list (fluid/neighbor_grid.hpp): particle i's k-th listed neighbour has its
// factor at of(i)[k], 0 beyond re. The number density takes them at the predicted positions, several pairs at a time
// (fluid/listed_pairs.hpp), and the W / r^2 pressure gradients, at the same positions, read them: the square root,
// the division and the branch on the distance of each pair were half the gradient's cost (perf); keeping W made the
// bench case's loop 11 % faster (stop 25), keeping W / r^2 instead took the gradient's last division per pair
// (stop 26, docs/profile.md).
#include <cstddef>
#include <vector>

#include "fluid/neighbor_grid.hpp"

namespace slide {

class PairWeights {
 public:
  // Gives every block of the list its room (storage is kept from step to step) and marks the weights as not yet
  // taken at any step.
  void shape_like(const NeighborList& nl) {
    blocks_.resize(nl.blocks.size());
    for (std::size_t b = 0; b < nl.blocks.size(); ++b) {
      reserve_with_margin(blocks_[b], nl.blocks[b].size());
      blocks_[b].resize(nl.blocks[b].size());
    }
    taken_at_step_ = -1;
  }
  double* of(const NeighborList& nl, std::size_t i) {
    return blocks_[i / NeighborList::block_size].data() + nl.first[i];
  }
  const double* of(const NeighborList& nl, std::size_t i) const {
    return blocks_[i / NeighborList::block_size].data() + nl.first[i];
  }
  // Which step's positions the weights are of (-1: none); a rebuilt list or a restored state forgets them.
  void mark_taken_at(long step) { taken_at_step_ = step; }
  void forget() { taken_at_step_ = -1; }
  bool taken_at(long step) const { return taken_at_step_ == step; }

 private:
  std::vector<std::vector<double>> blocks_;
  long taken_at_step_ = -1;
};

}  // namespace slide
