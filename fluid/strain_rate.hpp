#pragma once
// The velocity gradient and the shear rate of a fluid particle, from which non-Newtonian rheologies take their
// viscosity (fluid/rheology/rheology.hpp).
#include <Eigen/LU>
#include <cmath>
#include <cstdint>

#include "fluid/kernel.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"
#include "fluid/viscosity.hpp"

namespace slide {

// u_j,eff - u_i for neighbour j of fluid particle i: u_j - u_i for a fluid neighbour, the no-slip mirror of
// fluid/viscosity.hpp (no_slip_mirror_factor), the same as the viscous term's,
// for a boundary neighbour (wall or dummy). Where a Coulomb basal friction lets the particle slide (wall_fraction
// s_i < 1, fluid/basal_friction.hpp) the wall carries only s_i of the no-slip stress, and its pair enters with s_i:
// the shear the material itself sees at the wall is the wall stress over its viscosity, not the slip over the
// distance (a block sliding as one would otherwise read its slip as shear in its bottom rows and yield there).
// s_i is the previous step's (lagged).
template <int D>
inline Vec<D> velocity_difference(std::size_t i, std::uint32_t j, const Particles<D>& P, double min_distance) {
  if (P.kind[j] == Kind::fluid) return P.velocity[j] - P.velocity[i];
  const double d_j = P.wall_depth[j];
  const double d_i = P.wall_normal[j].dot(P.position[i] - P.position[j]) - d_j;
  return (P.wall_fraction[i] * no_slip_mirror_factor(d_i, d_j, min_distance)) * (P.velocity[j] - P.velocity[i]);
}

// Velocity gradient L_ab = du_a / dx_b of fluid particle i: seed eq. 3 (the MPS gradient, Koshizuka & Oka 1996)
// applied to each velocity component, with its normalisation d / n0 I replaced by the particle's own moment matrix
// (the corrected gradient of Randles & Libersky 1996 and Bonet & Lok 1999; in MPS, Khayyer & Gotoh 2011):
//   A = sum_j (u_j - u_i) (x) r_ij W / |r_ij|^2,   M = sum_j r_ij (x) r_ij W / |r_ij|^2,   L = A M^-1,
// over the neighbours within re, r_ij = x_j - x_i. Boundary neighbours: no_slip, the mirrored velocity
// (velocity_difference), and they count in M; free_slip, left out of both (a free-slip wall exerts no shear).
// L is then exact for a linear velocity field on any arrangement of neighbours that spans the plane, where eq. 3
// is exact only on a full regular lattice (M = n0 / d I there, and both agree). Why it matters: in a shear flow rows
// of particles slide past each other, and on such a sheared lattice eq. 3 read a plane Poiseuille flow's shear rate
// 1-6 % low; a power-law viscosity K g^(n-1) carries (n - 1) times that error, and the Herschel-Bulkley n = 0.5
// channel's velocity (which goes as the stress^(1/n)) came out 3.5-4.3 % low at every resolution while Bingham
// (n = 1, insensitive) stayed within 0.5 % (tests/test_hb_poiseuille.cpp). Where M is near singular (a particle with
// neighbours on one side only, at a free surface) eq. 3's d / n0 is kept: det M below a quarter of the full
// lattice's (n0 / d)^d.
template <int D>
Mat<D> velocity_gradient(std::size_t i, const Particles<D>& P, const NeighborList& nl, double re, double n0,
                         const ViscousWall& wall) {
  const double re2 = re * re;
  Mat<D> A = Mat<D>::Zero(), M = Mat<D>::Zero();
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q) {
    const std::uint32_t j = *q;
    if (P.kind[j] != Kind::fluid && wall.slip == WallSlip::free_slip) continue;
    const Vec<D> rij = P.position[j] - P.position[i];
    const double r2 = rij.squaredNorm();
    if (r2 >= re2) continue;
    const double w = kernel_weight(std::sqrt(r2), re) / r2;
    A += w * velocity_difference<D>(i, j, P, wall.min_distance) * rij.transpose();
    M += w * rij * rij.transpose();
  }
  if (M.determinant() < 0.25 * std::pow(n0 / D, D)) return (D / n0) * A;
  return A * M.inverse();
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
