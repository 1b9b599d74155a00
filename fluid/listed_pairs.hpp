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

#include "fluid/kernel.hpp"
#include "fluid/lanes.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/vec.hpp"

namespace slide {


// Which factor of each pair a pressure gradient reads at the number density's positions (fluid/pair_weights.hpp):
// W / r^2 for the W / r^2 models, -W'(r) / r (derivative_over_r, fluid/kernel.hpp) for the kernel-derivative ones.
enum class PairFactor : std::uint8_t { w_over_r2, derivative_over_r };

// W into w[0 .. count) for the neighbours nb[0 .. count) of a particle at xi, and the pair factor F into factor[0 ..
// count) unless it is nullptr: W / r^2 (W / 0 for a neighbour on top of xi) or -W'(r) / r (+0 from re on, as
// derivative_over_r; 3 / (re 0) for a neighbour on top), each bit-identical to the scalar formula: the same operations
// in the same order, each correctly rounded in every lane.
// moment (the derivative factor only): nullptr, or the sum of factor * r_ij (x) r_ij (the corrected gradient's A_i
// before its division by kappa n0, fluid/corrective_matrix.hpp) over the pairs within re, written to moment's upper
// triangle. Taken here, where the pair's components are at hand, it cost a third of the separate pass it replaced.
template <int D, PairFactor F = PairFactor::w_over_r2>
void listed_kernel_weights(const Vec<D>& xi, const std::vector<Vec<D>>& x, const std::uint32_t* nb, std::size_t count,
                           double re, double* w, double* factor = nullptr, Mat<D>* moment = nullptr) {
  constexpr std::size_t L = pair_lanes;
  Lanes moment_lanes[D][D];
  if (moment)
    for (int a = 0; a < D; ++a)
      for (int b = a; b < D; ++b) moment_lanes[a][b] = 0.0;
  std::size_t k = 0;
  for (; k + L <= count; k += L) {
    Lanes difference[D];
    const Lanes r2 =
        lane_distances_squared<D>(xi, x, [&](std::size_t l) { return nb[k + l]; }, moment ? difference : nullptr);
    const Lanes r = stdx::sqrt(r2);
    Lanes s = Lanes(1.0) - r / Lanes(re);
    stdx::where(s < Lanes(0.0), s) = 0.0;
    const Lanes weight = s * s * s;
    weight.copy_to(w + k, stdx::element_aligned);
    if (!factor) continue;
    if constexpr (F == PairFactor::w_over_r2) {
      (weight / r2).copy_to(factor + k, stdx::element_aligned);
    } else {
      // -(-3 s s / re) / r, kernel_derivative's operations; s = 0 from re on gives +0
      const Lanes f = -((Lanes(-3.0) * s * s) / Lanes(re)) / r;
      f.copy_to(factor + k, stdx::element_aligned);
      if (moment)
        for (int a = 0; a < D; ++a)
          for (int b = a; b < D; ++b) moment_lanes[a][b] += f * difference[a] * difference[b];
    }
  }
  if (moment)
    for (int a = 0; a < D; ++a)
      for (int b = a; b < D; ++b) (*moment)(a, b) = (*moment)(b, a) = stdx::reduce(moment_lanes[a][b]);
  for (; k < count; ++k) {
    const Vec<D> rij = x[nb[k]] - xi;
    const double r2 = distance_squared<D>(x[nb[k]], xi);
    const double r = std::sqrt(r2);
    w[k] = kernel_weight(r, re);
    if (!factor) continue;
    factor[k] = F == PairFactor::w_over_r2 ? w[k] / r2 : derivative_over_r(r, re);
    if (moment && F == PairFactor::derivative_over_r && factor[k] != 0.0) {
      const Mat<D> term = factor[k] * (rij * rij.transpose());
      *moment += term;
    }
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
