#pragma once
// The fluid's pressure continued to a point among it: what a wall particle (fluid/wall_pressure.hpp) and a
// free-surface particle (fluid/free_surface_pressure.hpp) take from their neighbours.
#include "fluid/kernel.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"

namespace slide {

// Shepard mean of the pressure of particle i's fluid neighbours f that `use(f)` accepts, each continued to i along the
// effective downward acceleration `head_acceleration` (Adami, Hu & Adams 2012, J. Comput. Phys. 231, eq. 27):
//   p_i = ( sum_f p_f W_if + head_acceleration . sum_f rho_f (r_i - r_f) W_if ) / sum_f W_if.
// Exact for a hydrostatic field of that acceleration. Returns false (and leaves p) when no neighbour is used.
template <int D, class Use>
bool continued_pressure(std::size_t i, const Particles<D>& P, const NeighborList& nl, double re,
                        const Vec<D>& head_acceleration, const Use& use, double& p) {
  const auto& x = P.position;
  const double re2 = re * re;
  double sum_w = 0.0, sum_pw = 0.0, sum_head = 0.0;
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q) {
    const std::uint32_t f = *q;
    if (P.kind[f] != Kind::fluid || !use(f)) continue;
    const Vec<D> r_if = x[i] - x[f];
    const double r2 = r_if.squaredNorm();
    if (r2 >= re2) continue;
    const double weight = kernel_weight(std::sqrt(r2), re);
    sum_w += weight;
    sum_pw += P.pressure[f] * weight;
    sum_head += P.density[f] * head_acceleration.dot(r_if) * weight;
  }
  if (sum_w <= 0.0) return false;
  p = (sum_pw + sum_head) / sum_w;
  return true;
}

}  // namespace slide
