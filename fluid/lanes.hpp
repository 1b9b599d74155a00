#pragma once
// SIMD lanes of doubles for the pair stages (std::experimental::simd): 2 in a baseline x86-64 build, 4 with AVX2
// (CMakeLists.txt SLIDE_SIMD); run.json reports the count as pair_lanes. Square roots and divisions are correctly
// rounded in every lane, so what a stage computes in lanes is bit-identical to the same formula one pair at a time.
#include <cstddef>
#include <experimental/simd>
#include <vector>

#include "fluid/vec.hpp"

namespace slide {

namespace stdx = std::experimental;
using Lanes = stdx::native_simd<double>;
inline constexpr std::size_t pair_lanes = Lanes::size();

// |x[index(l)] - q|^2 in lane l, summed in distance_squared's order (fluid/vec.hpp): 0 + d0^2 + d1^2 (+ d2^2).
// Always inlined: as a call it returned its lanes through memory and the bench case's loop ran 10 % slower (stop 26).
// difference: nullptr, or room for the components x[index(l)] - q (D lanes).
template <int D, class Index>
[[gnu::always_inline]] inline Lanes lane_distances_squared(const Vec<D>& q, const std::vector<Vec<D>>& x, Index&& index,
                                                           Lanes* difference = nullptr) {
  Lanes r2(0.0);
  for (int c = 0; c < D; ++c) {
    const Lanes d([&](auto l) { return x[index(l)][c] - q[c]; });
    r2 += d * d;
    if (difference) difference[c] = d;
  }
  return r2;
}

}  // namespace slide
