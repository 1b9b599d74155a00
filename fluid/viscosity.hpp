#pragma once
// Newtonian viscous acceleration through the MPS Laplacian, with the wall treatments the scene can choose.
#include <algorithm>
#include <cmath>
#include <vector>

#include "fluid/kernel.hpp"
#include "fluid/listed_pairs.hpp"
#include "fluid/name_table.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"

namespace slide {

enum class WallSlip { no_slip, free_slip };

inline constexpr auto wall_slip_names =
    make_name_table<WallSlip>(std::pair{WallSlip::no_slip, "no_slip"}, std::pair{WallSlip::free_slip, "free_slip"});

inline std::string_view to_string(WallSlip s) { return wall_slip_names.name(s); }

// The viscous wall condition: the slip choice and, for no_slip, the smallest distance from the face a fluid particle
// is taken to have in the mirror (below).
struct ViscousWall {
  WallSlip slip = WallSlip::no_slip;
  double min_distance = 0.0;  // m; the scenes use dp / 2, the first lattice row's distance from a face
};

// The no-slip mirror (Morris, Fox & Zhu 1997): a boundary particle at depth d_j behind its face carries, as seen from
// a fluid particle at distance d_i in front of it, the velocity mirrored through the face,
// u_j,eff = u_b - (d_j / d_i)(u_i - u_b), u_b the boundary's own velocity, so that
//   u_j,eff - u_i = (1 + d_j / d_i)(u_b - u_i)
// and the velocity vanishes on the face itself rather than half a spacing beyond it. d_i is clipped below at
// min_distance, so that a particle very near (or past) the face does not get an unbounded factor. Morris et al. cap
// the factor itself at 1.5 instead; that cap also acts on particles at their lattice distance dp / 2 (exact factors 2,
// 4, 6 for the layers at dp/2, 3dp/2, 5dp/2), and cost plane Poiseuille flow at 20 particles across +3.6 % at the
// centreline against +0.25 % with the clip (tests/test_viscosity.cpp, square lattice; hexagonal +1.7 % against
// +0.12 %). The same factor serves the strain rate (fluid/strain_rate.hpp) and the semi-implicit stage.
inline double no_slip_mirror_factor(double d_i, double d_j, double min_distance) {
  return 1.0 + d_j / std::max(d_i, min_distance);
}

// a_i = 1/rho_i * 2d / (lambda n0) * sum_j mu_ij (u_j - u_i) W(|r_ij|)        (seed eq. 4 applied to mu grad u)
// mu_ij = 2 mu_i mu_j / (mu_i + mu_j), the harmonic mean across a pair (Shakibaeinia & Jin 2011, multiphase MPS),
// which equals mu for a single fluid.
// Boundary neighbours:
//  * no_slip: the fluid velocity is mirrored into the wall (no_slip_mirror_factor above), relative to the
//    boundary's own velocity for a moving body; with the wall viscosity mu_w,i = s_i mu_i (Particles::wall_fraction,
//    below 1 for a phase with a Coulomb basal friction: fluid/basal_friction.hpp).
//  * free_slip: boundary particles exert no shear; they are left out of the sum.
template <int D>
inline Vec<D> viscous_pair_term_w(std::size_t i, std::uint32_t j, double w, const Particles<D>& P,
                                  const ViscousWall& wall) {
  const auto& x = P.position;
  const auto& u = P.velocity;
  const double mu_i = P.viscosity[i];
  if (P.kind[j] == Kind::fluid) {
    const double mu_j = P.viscosity[j];
    const double mu_ij = mu_i == mu_j ? mu_i : 2.0 * mu_i * mu_j / (mu_i + mu_j);
    return (mu_ij * w) * (u[j] - u[i]);
  }
  if (wall.slip == WallSlip::free_slip) return Vec<D>::Zero();
  const double d_j = P.wall_depth[j];
  const double d_i = P.wall_normal[j].dot(x[i] - x[j]) - d_j;
  // mu_w,i = s_i mu_i: the wall viscosity, below mu_i where a Coulomb basal friction bounds the wall's shear stress
  // (fluid/basal_friction.hpp; s_i = 1 otherwise).
  return (mu_i * P.wall_fraction[i] * no_slip_mirror_factor(d_i, d_j, wall.min_distance) * w) * (u[j] - u[i]);
}

// The same for a pair at squared distance r2.
template <int D>
inline Vec<D> viscous_pair_term(std::size_t i, std::uint32_t j, double r2, const Particles<D>& P, double re,
                                const ViscousWall& wall) {
  return viscous_pair_term_w<D>(i, j, kernel_weight(std::sqrt(r2), re), P, wall);
}

template <int D>
double viscous_scale(std::size_t i, const Particles<D>& P, double n0, double lambda) {
  return 2.0 * D / (lambda * n0 * P.density[i]);
}

// The weights are taken for the whole list first (fluid/listed_pairs.hpp). A fluid neighbour beyond re (weight 0)
// adds a zero term instead of being skipped: the sum is unchanged to the bit for finite velocities and viscosities (it
// starts at +0, and x + 0 = x; a non-finite neighbour beyond re now spreads to i a stage sooner, in a run the step's
// checks then stop anyway), and a
// branch on each pair's weight, which the predictor cannot follow, is gone (4 % of the bench case's first 0.05 s,
// stop 26). Boundary neighbours beyond re are still skipped: their mirror factor divides by a distance.
template <int D>
Vec<D> viscous_acceleration(std::size_t i, const Particles<D>& P, const NeighborList& nl, double re, double n0,
                            double lambda, const ViscousWall& wall) {
  const std::size_t count = nl.count[i];
  double* w = listed_weights_room(count);
  listed_kernel_weights<D>(i, P.position, nl, re, w);
  const std::uint32_t* nb = nl.begin(i);
  Vec<D> sum = Vec<D>::Zero();
  for (std::size_t k = 0; k < count; ++k)
    if (P.kind[nb[k]] == Kind::fluid || w[k] != 0.0) sum += viscous_pair_term_w<D>(i, nb[k], w[k], P, wall);
  return viscous_scale<D>(i, P, n0, lambda) * sum;
}

}  // namespace slide
