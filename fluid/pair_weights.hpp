#pragma once
// The pressure gradient's factor of every listed pair at one set of positions (fluid/listed_pairs.hpp PairFactor: W /
// r^2 for the W / r^2 models, -W'(r) / r for the kernel-derivative ones), laid out as the neighbour list
// (fluid/neighbor_grid.hpp): particle i's k-th listed neighbour has its factor at of(i)[k], 0 beyond re. The number
// density takes them at the predicted positions, several pairs at a time, and the pressure gradient, at the same
// positions, reads them: the square root, the divisions and the branch on the distance of each pair were half the
// gradient's cost (perf); keeping W made the bench case's loop 11 % faster (stop 25), keeping W / r^2 instead took
// the gradient's last division per pair (stop 26), keeping -W'(r) / r did the same for the derivative models (stop
// 27, docs/profile.md).
#include <cstddef>
#include <vector>

#include "fluid/listed_pairs.hpp"
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
  // Which step's positions the factors are of (-1: none), and which factor they are; a rebuilt list or a restored
  // state forgets them.
  void mark_taken_at(long step, PairFactor factor) {
    taken_at_step_ = step;
    factor_ = factor;
  }
  void forget() { taken_at_step_ = -1; }
  bool taken_at(long step, PairFactor factor) const { return taken_at_step_ == step && factor_ == factor; }

 private:
  std::vector<std::vector<double>> blocks_;
  long taken_at_step_ = -1;
  PairFactor factor_ = PairFactor::w_over_r2;
};

}  // namespace slide
