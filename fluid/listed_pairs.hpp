#pragma once
// What the pair stages need of all of a particle's listed neighbours at once, several pairs at a time: the kernel
// weights, and whether any neighbour is closer than a distance.
//
// Why: a pair stage's own loop branched on r < re for each pair, and about a third of the listed pairs lie beyond re
// (the list's skin), in no order the branch predictor can follow; its square root and division ran one pair at a
// time. Here the pairs go through the SIMD lanes (std::experimental::simd: 2 lanes of SSE2 in a baseline x86-64
// build, more where the build targets them), with no branch. The square root and the division are correctly rounded
// in every lane, so each weight is bit-identical to kernel_weight(sqrt(r2), re) (fluid/kernel.hpp), 0 beyond re:
// r2 >= re^2 gives sqrt(r2) >= re (sqrt(fl(re^2)) = re exactly), so 1 - r / re <= 0 and the weight is 0.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "fluid/lanes.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/vec.hpp"

namespace slide {


// W into w[0 .. count) for the neighbours nb[0 .. count) of a particle at xi, and W / r^2 into w_over_r2 unless it is
// nullptr (the W / r^2 gradient models' factor, fluid/gradient.hpp; W / 0 for a neighbour on top of xi).
template <int D>
void listed_kernel_weights(const Vec<D>& xi, const std::vector<Vec<D>>& x, const std::uint32_t* nb, std::size_t count,
                           double re, double* w, double* w_over_r2 = nullptr) {
  constexpr std::size_t L = pair_lanes;
  std::size_t k = 0;
  for (; k + L <= count; k += L) {
    const Lanes r2 = lane_distances_squared<D>(xi, x, [&](std::size_t l) { return nb[k + l]; });
    Lanes s = Lanes(1.0) - stdx::sqrt(r2) / Lanes(re);
    stdx::where(s < Lanes(0.0), s) = 0.0;
    const Lanes weight = s * s * s;
    weight.copy_to(w + k, stdx::element_aligned);
    if (w_over_r2) (weight / r2).copy_to(w_over_r2 + k, stdx::element_aligned);
  }
  for (; k < count; ++k) {
    const double r2 = distance_squared<D>(x[nb[k]], xi);
    w[k] = kernel_weight(std::sqrt(r2), re);
    if (w_over_r2) w_over_r2[k] = w[k] / r2;
  }
}

// Room for a particle's weights in the calling thread's own buffer (kept from call to call, grown when a list is
// longer than any before on that thread).
// A stage holds the pointer only while it sums one particle's pairs, and calls no other stage that uses the room.
inline double* listed_weights_room(std::size_t count) {
  thread_local std::vector<double> room;
  if (room.size() < count) room.resize(count + count / 4);
  return room.data();
}

template <int D>
void listed_kernel_weights(std::size_t i, const std::vector<Vec<D>>& x, const NeighborList& nl, double re, double* w) {
  listed_kernel_weights<D>(x[i], x, nl.begin(i), nl.count[i], re, w);
}

// Whether any of the neighbours nb[0 .. count) lies closer to xi than sqrt(distance2) (r2 < distance2, the test the
// collision stage makes of each pair).
template <int D>
bool any_listed_closer(const Vec<D>& xi, const std::vector<Vec<D>>& x, const std::uint32_t* nb, std::size_t count,
                       double distance2) {
  constexpr std::size_t L = pair_lanes;
  std::size_t k = 0;
  for (; k + L <= count; k += L) {
    const Lanes r2 = lane_distances_squared<D>(xi, x, [&](std::size_t l) { return nb[k + l]; });
    if (stdx::any_of(r2 < Lanes(distance2))) return true;
  }
  for (; k < count; ++k)
    if (distance_squared<D>(x[nb[k]], xi) < distance2) return true;
  return false;
}

}  // namespace slide
