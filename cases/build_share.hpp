#pragma once
// A 3-D scene built on several processes: each makes only the particles of its own slab of lattice columns, and of a
// margin of columns either side that the build's steps reading across columns need, then drops the margin
// (cases/scene.cpp); the first re-sort then gives each process its cells' particles (fluid/domain.hpp). A process so
// holds its part of the scene, not the whole, from the start: a scene too large for one machine's memory is built
// across many.
//
// Why slabs of whole columns: the steps that read other particles read along a column (the hydrostatic start
// compresses each vertical run of water from its support, cases/build_initial_state.cpp) or a short way across it
// (a boundary particle takes the shift of the nearest run within re; the overlap check looks 0.75 dp around), so a
// process holding whole columns and re beyond them does each of its own columns as the whole build would.
//
// The slabs are cut across the plan axis (x or y) along which the particles spread furthest, each holding an even part
// of them: a counting pass over the scene's lattice points first (every process alike; BuildCount) keeps no particle,
// only their count per column along each axis, their box, and which wall points repeat a point an earlier wall placed
// (where two tanks meet, or a terrain covers a tank's floor: the earlier one stands). Every particle gets the id the
// whole build gives it (its place in the order the whole build makes them), so the run is the same to the bit.
#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "fluid/vec.hpp"

namespace slide::cases {

struct BuildCount {
  std::array<std::map<long, std::int64_t>, 2> per_column;  // particles by column index along x and along y
  Vec<3> lo = Vec<3>::Constant(1e300), hi = Vec<3>::Constant(-1e300);  // the box of every particle, m
  std::int64_t particles = 0;
  // The wall points (numbered in the order the walls offer them) that repeat an earlier wall's, ascending.
  std::vector<std::uint64_t> repeated_wall_points;

  void add(const Vec<3>& x, double dp);
};

// The column a point lies in along `axis` (0: x, 1: y) on a lattice of spacing dp: a vertical run is in one column.
long column_of(const Vec<3>& x, int axis, double dp);

class BuildShare {
 public:
  // Process `rank` of `processes`: its slab of columns, cut where the count of the columns before it reaches rank
  // times an even part, and `margin_columns` columns either side.
  BuildShare(const BuildCount& count, double dp, long margin_columns, int processes, int rank);

  bool owns(const Vec<3>& x) const {
    const long c = column_of(x, axis_, dp_);
    return c >= first_ && c < end_;
  }
  // Owned, or in the margin: made here.
  bool holds(const Vec<3>& x) const {
    const long c = column_of(x, axis_, dp_);
    return c >= first_ - margin_ && c < end_ + margin_;
  }
  int axis() const { return axis_; }
  std::int64_t held() const { return held_; }  // the particles made here, margin included
  std::int64_t owned() const { return owned_; }

 private:
  int axis_ = 0;
  double dp_ = 0.0;
  long first_ = 0, end_ = 0, margin_ = 0;  // own columns [first_, end_)
  std::int64_t held_ = 0, owned_ = 0;
};

}  // namespace slide::cases
