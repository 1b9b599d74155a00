#pragma once
// Newtonian viscous acceleration through the MPS Laplacian, with the wall treatments the scene can choose.
#include <algorithm>
#include <cmath>
#include <vector>

#include "fluid/kernel.hpp"
#include "fluid/name_table.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"

namespace slide {

enum class WallSlip { no_slip, free_slip };

inline constexpr auto wall_slip_names =
    make_name_table<WallSlip>(std::pair{WallSlip::no_slip, "no_slip"}, std::pair{WallSlip::free_slip, "free_slip"});

inline std::string_view to_string(WallSlip s) { return wall_slip_names.name(s); }

// a_i = 1/rho_i * 2d / (lambda n0) * sum_j mu_ij (u_j - u_i) W(|r_ij|)        (seed eq. 4 applied to mu grad u)
// mu_ij = 2 mu_i mu_j / (mu_i + mu_j), the harmonic mean across a pair (Shakibaeinia & Jin 2011, multiphase MPS),
// which equals mu for a single fluid.
// Boundary neighbours:
//  * no_slip: the fluid velocity is mirrored into the wall (Morris, Fox & Zhu 1997): the boundary particle at
//    depth d_j behind the face carries u_j = -(d_j / d_i) u_i, d_i being the fluid particle's distance from the
//    face, so the velocity vanishes on the face itself rather than half a spacing beyond it (relative to the
//    boundary's own velocity for a moving body). The factor
//    1 + d_j / d_i is capped at 1.5 (Morris et al.) for particles very near the face.
//  * free_slip: boundary particles exert no shear; they are left out of the sum.
template <int D>
inline Vec<D> viscous_pair_term(std::size_t i, std::uint32_t j, double r2, const Particles<D>& P, double re,
                                WallSlip slip) {
  const auto& x = P.position;
  const auto& u = P.velocity;
  const double mu_i = P.viscosity[i];
  const double w = kernel_weight(std::sqrt(r2), re);
  if (P.kind[j] == Kind::fluid) {
    const double mu_j = P.viscosity[j];
    const double mu_ij = mu_i == mu_j ? mu_i : 2.0 * mu_i * mu_j / (mu_i + mu_j);
    return (mu_ij * w) * (u[j] - u[i]);
  }
  if (slip == WallSlip::free_slip) return Vec<D>::Zero();
  // Moving boundaries (bodies) mirror the velocity relative to their own: u_j - u_i = (u_b - u_i)(1 + d_j / d_i).
  const double d_j = P.wall_depth[j];
  const double d_i = P.wall_normal[j].dot(x[i] - x[j]) - d_j;
  const double factor = d_i > d_j / 0.5 ? 1.0 + d_j / d_i : 1.5;
  return (mu_i * factor * w) * (u[j] - u[i]);
}

template <int D>
double viscous_scale(std::size_t i, const Particles<D>& P, double n0, double lambda) {
  return 2.0 * D / (lambda * n0 * P.density[i]);
}

template <int D>
Vec<D> viscous_acceleration(std::size_t i, const Particles<D>& P, const NeighborList& nl, double re, double n0,
                            double lambda, WallSlip slip) {
  const double re2 = re * re;
  Vec<D> sum = Vec<D>::Zero();
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q) {
    const std::uint32_t j = *q;
    const double r2 = distance_squared<D>(P.position[j], P.position[i]);
    if (r2 >= re2) continue;
    sum += viscous_pair_term<D>(i, j, r2, P, re, slip);
  }
  return viscous_scale<D>(i, P, n0, lambda) * sum;
}

}  // namespace slide
