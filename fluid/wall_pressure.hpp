#pragma once
#include <vector>

#include "fluid/kernel.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"

namespace slide {

// Pressure of a boundary particle (wall or dummy) extrapolated from its fluid neighbours
// (Adami, Hu & Adams 2012, J. Comput. Phys. 231, eq. 27, for a wall at rest):
//   p_w = ( sum_f p_f W_wf + g . sum_f rho_f (r_w - r_f) W_wf ) / sum_f W_wf.
// It continues the fluid's pressure field, hydrostatic part included, into the wall, so the pressure gradient
// near a wall sees a complete and consistent neighbourhood. A boundary particle with no fluid neighbour has p = 0.
template <int D>
double extrapolated_wall_pressure(std::size_t w, const Particles<D>& P, const NeighborList& nl, double re,
                                  const Vec<D>& gravity) {
  const auto& x = P.position;
  const double re2 = re * re;
  double sum_w = 0.0, sum_pw = 0.0, sum_head = 0.0;
  for (const std::uint32_t* q = nl.begin(w); q != nl.end(w); ++q) {
    const std::uint32_t f = *q;
    if (P.kind[f] != Kind::fluid) continue;
    const Vec<D> r_wf = x[w] - x[f];
    const double r2 = r_wf.squaredNorm();
    if (r2 >= re2) continue;
    const double weight = kernel_weight(std::sqrt(r2), re);
    sum_w += weight;
    sum_pw += P.pressure[f] * weight;
    sum_head += P.density[f] * gravity.dot(r_wf) * weight;
  }
  if (sum_w <= 0.0) return 0.0;
  return (sum_pw + sum_head) / sum_w;
}

}  // namespace slide
