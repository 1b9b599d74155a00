#pragma once
#include <cmath>
#include <vector>

#include "fluid/kernel.hpp"
#include "fluid/listed_pairs.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/parallel.hpp"

namespace slide {

// Seed eq. 5: n_i = sum_{j != i} W(|r_j - r_i|).
template <int D>
double number_density_of(std::size_t i, const std::vector<Vec<D>>& x, const NeighborList& nl, double re) {
  double n = 0.0;
  const double re2 = re * re;
  for (const std::uint32_t* p = nl.begin(i); p != nl.end(i); ++p) {
    const double r2 = distance_squared<D>(x[*p], x[i]);
    if (r2 < re2) n += kernel_weight(std::sqrt(r2), re);
  }
  return n;
}

// The same with each neighbour weighted by fill_j (boundary particles that stand for mirrored fluid).
template <int D>
double weighted_number_density_of(std::size_t i, const std::vector<Vec<D>>& x, const std::vector<double>& fill,
                                  const NeighborList& nl, double re) {
  double n = 0.0;
  const double re2 = re * re;
  for (const std::uint32_t* p = nl.begin(i); p != nl.end(i); ++p) {
    const double r2 = distance_squared<D>(x[*p], x[i]);
    if (r2 < re2) n += fill[*p] * kernel_weight(std::sqrt(r2), re);
  }
  return n;
}

// Either sum, keeping each listed neighbour's pair factor (0 beyond re) in factor[0 .. count) for the pressure
// gradient at the same positions (fluid/pair_weights.hpp): W(|r_ij|) / |r_ij|^2 or -W'(|r_ij|) / |r_ij|, as the model
// reads (fluid/listed_pairs.hpp). fill: the neighbours' weights, or nullptr for 1 each. The terms and their order are
// those above (a zero weight beyond re adds nothing to a sum that starts at +0 and has no negative term), so the sums
// are bit-identical to them.
// moment: nullptr, or (the derivative factor only) the corrected gradient's second moment (listed_kernel_weights).
template <int D>
double number_density_keeping_weights(std::size_t i, const std::vector<Vec<D>>& x, const std::vector<double>* fill,
                                      const NeighborList& nl, double re, double* factor,
                                      PairFactor which = PairFactor::w_over_r2, Mat<D>* moment = nullptr) {
  const std::size_t count = nl.count[i];
  double* w = listed_weights_room(count);
  if (which == PairFactor::w_over_r2)
    listed_kernel_weights<D, PairFactor::w_over_r2>(x[i], x, nl.begin(i), count, re, w, factor);
  else
    listed_kernel_weights<D, PairFactor::derivative_over_r>(x[i], x, nl.begin(i), count, re, w, factor, moment);
  double n = 0.0;
  const std::uint32_t* nb = nl.begin(i);
  if (fill)
    for (std::size_t k = 0; k < count; ++k) n += (*fill)[nb[k]] * w[k];
  else
    for (std::size_t k = 0; k < count; ++k) n += w[k];
  return n;
}

template <int D>
void compute_number_density(const std::vector<Vec<D>>& x, const NeighborList& nl, double re, std::vector<double>& n) {
  n.resize(x.size());
  parallel_for(x.size(), [&](std::size_t i) { n[i] = number_density_of<D>(i, x, nl, re); });
}

}  // namespace slide
