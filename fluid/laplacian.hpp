#pragma once
#include <cmath>
#include <vector>

#include "fluid/kernel.hpp"
#include "fluid/neighbor_grid.hpp"

namespace slide {

// Seed eq. 4 (Koshizuka & Oka 1996), with the integral ratio taken as the lattice sum lambda:
//   lap phi_i = 2 d / (lambda n0) * sum_{j != i} (phi_j - phi_i) W(|r_ij|).
// Exact for a quadratic field on the lattice that defined n0 and lambda, away from boundaries.
// Field is any indexable container of scalars or Eigen vectors.
template <int D, class Field>
auto mps_laplacian(std::size_t i, const std::vector<Vec<D>>& x, const Field& phi, const NeighborList& nl, double re,
                   double n0, double lambda) {
  using Value = std::decay_t<decltype(phi[i])>;
  Value sum = phi[i] - phi[i];  // zero of the right type and size
  const double re2 = re * re;
  for (const std::uint32_t* p = nl.begin(i); p != nl.end(i); ++p) {
    const std::uint32_t j = *p;
    const double r2 = distance_squared<D>(x[j], x[i]);
    if (r2 >= re2) continue;
    sum += (phi[j] - phi[i]) * kernel_weight(std::sqrt(r2), re);
  }
  return Value((2.0 * D / (lambda * n0)) * sum);  // evaluated: an Eigen expression would outlive `sum`
}

}  // namespace slide
