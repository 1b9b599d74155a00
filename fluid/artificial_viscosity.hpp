#pragma once
// Artificial viscosity: the usual stabiliser of weakly compressible particle methods, offered as an option.
#include <cmath>
#include <vector>

#include "fluid/kernel.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"

namespace slide {

// Monaghan (1992, Annu. Rev. Astron. Astrophys. 30) artificial viscosity written as an extra pair pressure in the
// MPS symmetric gradient: for fluid pairs that approach each other (u_ij . r_ij < 0, u_ij = u_i - u_j,
// r_ij = r_i - r_j)
//   q_ij = -alpha rho_ij c0 dp (u_ij . r_ij) / (|r_ij|^2 + 0.01 dp^2),   rho_ij = (rho_i + rho_j) / 2,
//   a_i  = -1/rho_i * d / n0 * sum_j q_ij (r_j - r_i) W / |r_j - r_i|^2.
// The pair force is antisymmetric (momentum is conserved) and Galilean invariant; it dissipates the acoustic and
// particle-rearrangement noise that a weakly compressible model otherwise keeps forever. Its effective kinematic
// viscosity is of order alpha c0 dp / 8, so alpha is kept small. Boundary particles are not included.
template <int D>
Vec<D> artificial_viscous_acceleration(std::size_t i, const Particles<D>& P, const NeighborList& nl, double re,
                                       double n0, double alpha, double c0, double dp) {
  const auto& x = P.position;
  const auto& u = P.velocity;
  const double re2 = re * re, eta2 = 0.01 * dp * dp;
  Vec<D> g = Vec<D>::Zero();
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q) {
    const std::uint32_t j = *q;
    if (P.kind[j] != Kind::fluid) continue;
    const Vec<D> rji = x[j] - x[i];
    const double r2 = rji.squaredNorm();
    if (r2 >= re2) continue;
    const double approach = (u[i] - u[j]).dot(-rji);  // u_ij . r_ij
    if (approach >= 0.0) continue;
    const double q_ij = -alpha * 0.5 * (P.density[i] + P.density[j]) * c0 * dp * approach / (r2 + eta2);
    g += (q_ij * kernel_weight(std::sqrt(r2), re) / r2) * rji;
  }
  return (-D / (n0 * P.density[i])) * g;
}

}  // namespace slide
