#pragma once
// The velocity gradient and the shear rate of a fluid particle, from which non-Newtonian rheologies take their
// viscosity (fluid/rheology/rheology.hpp).
#include <cmath>
#include <cstdint>

#include "fluid/kernel.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"
#include "fluid/viscosity.hpp"

namespace slide {

// u_j,eff - u_i for neighbour j of fluid particle i: u_j - u_i for a fluid neighbour, the no-slip mirror of
// fluid/viscosity.hpp (no_slip_mirror_factor), the same as the viscous term's,
// for a boundary neighbour (wall or dummy).
template <int D>
inline Vec<D> velocity_difference(std::size_t i, std::uint32_t j, const Particles<D>& P, double min_distance) {
  if (P.kind[j] == Kind::fluid) return P.velocity[j] - P.velocity[i];
  const double d_j = P.wall_depth[j];
  const double d_i = P.wall_normal[j].dot(P.position[i] - P.position[j]) - d_j;
  return no_slip_mirror_factor(d_i, d_j, min_distance) * (P.velocity[j] - P.velocity[i]);
}

// Velocity gradient L_ab = du_a / dx_b of fluid particle i, seed eq. 3 (the MPS gradient, Koshizuka & Oka 1996)
// applied to each velocity component:
//   grad u_a,i = d / n0 * sum_{j != i, |r_ij| < re} (u_a,j - u_a,i) r_ij / |r_ij|^2 W(|r_ij|),  r_ij = x_j - x_i,
// i.e. L = d / n0 * sum (u_j - u_i) (x) r_ij W / |r_ij|^2. Boundary neighbours: no_slip, the mirrored velocity
// (velocity_difference); free_slip, left out (a free-slip wall exerts no shear).
// Like eq. 3 for any field, it is exact for a linear velocity field only where the neighbours form a full regular
// lattice (square, cubic or hexagonal: their second moments sum r r^T W / r^2 = n0 / d I); near a free surface, in a
// disordered region, or at a free-slip wall it is not.
template <int D>
Mat<D> velocity_gradient(std::size_t i, const Particles<D>& P, const NeighborList& nl, double re, double n0,
                         const ViscousWall& wall) {
  const double re2 = re * re;
  Mat<D> L = Mat<D>::Zero();
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q) {
    const std::uint32_t j = *q;
    if (P.kind[j] != Kind::fluid && wall.slip == WallSlip::free_slip) continue;
    const Vec<D> rij = P.position[j] - P.position[i];
    const double r2 = rij.squaredNorm();
    if (r2 >= re2) continue;
    L += (kernel_weight(std::sqrt(r2), re) / r2) * velocity_difference<D>(i, j, P, wall.min_distance) * rij.transpose();
  }
  return (D / n0) * L;
}

// Shear rate (magnitude of the rate of strain, e.g. Bird, Armstrong & Hassager 1987, Dynamics of Polymeric Liquids
// vol. 1): g = sqrt(2 D:D), D = (L + L^T) / 2. Simple shear u = (G y, 0) gives G; pure extension u = (a x, -a y)
// gives 2a; a rigid rotation gives 0.
template <int D>
double shear_rate_of(const Mat<D>& L) {
  const Mat<D> S = 0.5 * (L + L.transpose());
  return std::sqrt(2.0 * S.cwiseProduct(S).sum());
}

// The shear rate of fluid particle i, 1/s.
template <int D>
double shear_rate(std::size_t i, const Particles<D>& P, const NeighborList& nl, double re, double n0,
                  const ViscousWall& wall) {
  return shear_rate_of<D>(velocity_gradient<D>(i, P, nl, re, n0, wall));
}

}  // namespace slide
