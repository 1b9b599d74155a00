#pragma once
// The pressure that confines a particle's shearing, for a pressure-dependent yield stress (Mohr-Coulomb, mu(I):
// fluid/rheology/). Particle i shears against each neighbour j across their midplane, where the pressure is
// (p_i + p_j) / 2 to first order; the confining pressure is the kernel-weighted mean of those midplane pressures
// over i's fluid neighbours within re (weight W_ij, seed eq. 1):
//   p_c,i = p_i / 2 + sum_j W_ij p_j / (2 sum_j W_ij),
// and p_c,i = p_i for a particle without fluid neighbours.
// Why not p_i itself: the free-surface condition sets p = 0 on the particles of the surface row, half a spacing
// inside the true surface, so a cohesionless sediment's surface row had no frictional strength at all and flowed
// off a slope gentler than its friction angle (measured: a Mohr-Coulomb layer, phi = 30 deg, on 20 deg; the
// continuum pressure at that row's centres is rho g dp / 2 cos a). In the bulk, for a pressure linear in space and a
// neighbourhood symmetric about i, the weighted mean of p_j is p_i and p_c,i = p_i exactly.
#include <cmath>
#include <cstdint>

#include "fluid/kernel.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"

namespace slide {

template <int D>
double confining_pressure(std::size_t i, const Particles<D>& P, const NeighborList& nl, double re) {
  const double re2 = re * re;
  double weight = 0.0, weighted = 0.0;
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q) {
    const std::uint32_t j = *q;
    if (P.kind[j] != Kind::fluid) continue;
    const double r2 = distance_squared<D>(P.position[j], P.position[i]);
    if (r2 >= re2) continue;
    const double w = kernel_weight(std::sqrt(r2), re);
    weight += w;
    weighted += w * P.pressure[j];
  }
  if (weight == 0.0) return P.pressure[i];
  return 0.5 * P.pressure[i] + 0.5 * weighted / weight;
}

}  // namespace slide
