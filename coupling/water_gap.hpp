#pragma once
// How far the water stands off a body's faces. A fluid particle stands for dp^d of water, so water meets a face at the
// right distance when the water's edge, the contour where its kernel-interpolated volume fraction is 1/2 (the
// free-surface gauge's definition, coupling/free_surface_gauge.hpp), lies on the face. The gap is the distance from
// the face to that contour along the face's outward normal: positive when the water stands off the face (it then
// displaces water that is not there: a floating body rides high), negative when it reaches behind the face. On a
// flat lattice whose first row is half a row spacing in front of the face it reads +0.03 dp (square) and +0.02 dp
// (hexagonal) (tests/test_water_gap.cpp): the gauge's own offset, the contour lying that far inside the water.
#include <cmath>
#include <vector>

#include "coupling/free_surface_gauge.hpp"

namespace slide {

struct WaterGap {
  double mean = 0.0;           // m, over the wetted samples; NaN when no face is wetted
  double wetted_length = 0.0;  // m of face where water was found
};

// The mean gap over a convex outline (vertices counter-clockwise, world coordinates, the outline as it stands now).
// Samples every dp/4 along each face, leaving out 2 dp at each end (beside a corner the contour bends round it). A
// sample counts as wetted when the water 3 dp + re out along the normal is bulk water (volume fraction at least
// 0.9), so a face at a free surface, or above the water, does not count, and the edge lies within (-2 dp, 3 dp] of
// the face (water reaching 2 dp into the body, through a body thinner than 4 dp, is not this face's). The wetted
// length is the wetted samples times dp/4.
inline WaterGap water_gap_along_outline(const Simulation<2>& sim, const std::vector<Vec<2>>& outline) {
  const double dp = sim.options.dp;
  const double bulk = 0.9 * kernel_volume_integral<2>(sim.re()) / (dp * dp);
  double sum = 0.0;
  long wetted = 0;
  for (std::size_t k = 0; k < outline.size(); ++k) {
    const Vec<2> a = outline[k], b = outline[(k + 1) % outline.size()];
    const double length = (b - a).norm();
    const Vec<2> along = (b - a) / length;
    const Vec<2> outward(along[1], -along[0]);  // counter-clockwise outline: the right-hand normal points out
    const long samples = static_cast<long>(std::floor((length - 4.0 * dp) / (0.25 * dp) + 1e-9)) + 1;
    for (long m = 0; m < samples; ++m) {
      const Vec<2> p = a + (2.0 * dp + 0.25 * dp * m) * along;
      if (sim.fluid_number_density_at(Vec<2>(p + (3.0 * dp + sim.re()) * outward)) < bulk) continue;
      const double gap = water_edge_along<2>(sim, p, outward, -2.0 * dp, 3.0 * dp);
      if (!std::isfinite(gap)) continue;
      sum += gap;
      ++wetted;
    }
  }
  return {wetted > 0 ? sum / wetted : std::nan(""), wetted * 0.25 * dp};
}

}  // namespace slide
