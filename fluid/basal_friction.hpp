#pragma once
// Coulomb basal friction: a phase that slides on a wall with a Coulomb friction coefficient mu_b = tan(phi_b) rather
// than sticking to it (the no-slip mirror of fluid/viscosity.hpp).
//
// The condition: the wall's tangential shear stress on the material is bounded by its normal stress,
//   |tau_w| <= mu_b sigma_n,
// the frictional wall of SPH landslide models (the wall shear is the smaller of the viscous and the Coulomb stress,
// e.g. Cui & Zhang 2023, CMES 135(1) 357-376, "a boundary condition considering friction"; Liang, Jiang, Ning & Zhu
// 2023, Computers and Geotechnics 105238, "a modified friction-viscous solid boundary"). The discrete form below is
// this code's own.
//
// MPS form. A fluid particle i sees its boundary neighbours j through the no-slip mirror: the pair's velocity
// difference is f_ij (u_b,j - u_i) over the normal distance d_i + d_j, so the wall shear rate its wall pairs see is
//   g_w,i = |(u_i - u_b,j)_t| / max(d_i, d_min),
// the tangential velocity relative to the wall over the particle's (clipped) distance from the face; over several
// boundary neighbours (a corner, a body's rotating wall) their W_ij-weighted mean. Its wall viscosity is
//   mu_w,i = min(mu_i, mu_b sigma_i / g_w,i),
// and the wall pairs of the viscous term, the semi-implicit system and the strain rate use mu_w,i in place of mu_i
// (Particles::wall_fraction holds s_i = mu_w,i / mu_i in [0, 1]; 1 is the no-slip wall).
//
// Why this g_w: take a flat face whose wall particles continue the fluid's lattice (the scenes' walls), every row in
// front of it sliding at U. Row i's wall pairs exert c mu_w,i U sum_j (d_i + d_j) W_ij / d_i per unit volume
// (c = 2d / (lambda n0), seed eq. 4), so with mu_w,i = mu_b sigma d_i / U the rows in front of a face element of area
// dp^(d-1) exert mu_b sigma c dp sum (d_i + d_j) W_ij over the pairs that cross it. On an isotropic lattice that sum
// of normal separations times W, over the pairs crossing a plane, is lambda n0 / (2 d dp) per dp^(d-1) of it (half
// the second moment sum r_n^2 W = lambda n0 / d of one particle's neighbourhood, over the volume dp^d per particle),
// so the wall stress is exactly mu_b sigma, the Coulomb stress (square lattice, re = 2.1 dp: the row at dp / 2
// carries 99.9 % of it, the row at 3 dp / 2 the rest). tests/test_basal_friction.cpp measures it on a sliding block.
//
// sigma_i, the normal stress at the face: the particle's pressure p_i (>= 0) carried hydrostatically to the face,
// p_i + rho_i ((g - a_b,j) . (-n_j)) d_i, as the mirror wall pressure does (fluid/wall_pressure.hpp): the first
// row lies dp / 2 in front of the face, and its own pressure would fall short of the base's by rho g dp / 2 (10 % of
// a block 5 dp thick). a_b,j is a body particle's rigid acceleration (zero for a fixed wall). Under water the grains
// press on the wall with the effective stress, that less the pore pressure at the face point x_i - d_i n_j
// (fluid/pore_pressure.hpp; zero for a dry material), and never with less than nothing.
//
// Only the shear rate is tangential: mu_w,i scales the whole wall pair, its normal part too. Scaling the tangential
// part alone would make the wall's coefficient in the semi-implicit system a tensor mu_i n n^T + mu_w (I - n n^T),
// coupling the velocity components into one block system where now one scalar SPD matrix serves every component; the
// normal velocity relative to a wall is held near zero by the pressure, so the normal part's viscous coupling
// matters little. The factor is lagged like mu_i (evaluated from the velocities at the start of the step), so the
// semi-implicit system stays linear and symmetric.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "fluid/kernel.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"
#include "fluid/pore_pressure.hpp"
#include "fluid/viscosity.hpp"

namespace slide {

// mu_b = tan(phi_b) for a basal friction angle in degrees; 90 degrees (or more) is no bound, the no-slip wall.
inline double basal_friction_coefficient(double angle_deg) {
  if (!(angle_deg < 90.0)) return std::numeric_limits<double>::infinity();
  return std::tan(angle_deg * M_PI / 180.0);
}

// s = mu_w / mu = min(1, mu_b sigma / (mu g_w)) for sigma >= 0, g_w >= 0: the fraction of the no-slip wall stress
// mu g_w that the wall carries. 1 where the Coulomb bound is not reached, for an infinite mu_b, and where nothing
// slides (g_w = 0) or the material is inviscid (mu = 0).
inline double coulomb_wall_fraction(double mu, double mu_b, double normal_stress, double wall_shear_rate) {
  const double stress = mu * wall_shear_rate;  // the no-slip wall's
  const double bound = mu_b * std::max(normal_stress, 0.0);
  if (!(stress > bound)) return 1.0;
  return bound / stress;
}

// What fluid particle i's boundary neighbours within re see of the wall (above): the wall shear rate g_w (1/s) and
// the normal stress at the face sigma (Pa), both W_ij-weighted means over them; zeros when it has none. `gravity` is
// the simulation's.
struct WallShear {
  double rate = 0.0;
  double normal_stress = 0.0;
};

//
// The slip velocity is the trial one of a return mapping (as Coulomb friction is integrated in contact mechanics,
// e.g. Wriggers, Computational Contact Mechanics, 2006, ch. 10): u_i - u_b,j + dt (g - a_b,j), the slip the step
// would reach if the wall carried no shear (`dt`, the step; 0 gives the slip at its start). Why: with the slip at the
// step's start, a material at rest sees g_w = 0, the no-slip wall (s = 1), and a stiff slide resting on a slope
// steeper than its friction angle never started (a Herschel-Bulkley block, phi_b 15 degrees on a 20 degree slope, did
// not move in 0.3 s; issue 29, item 3). With the trial slip the wall carries at most mu_b sigma from the first step.
// Where the friction holds (mu_b sigma above the driving stress), the wall's stress balances the drive at a slip
// speed of order g dt, which moves the material by a small fraction of a spacing in a second.
template <int D>
WallShear wall_shear(std::size_t i, const Particles<D>& P, const NeighborList& nl, double re, double min_distance,
                     const Vec<D>& gravity, const PorePressureField<D>& pore = {}, double dt = 0.0) {
  const double re2 = re * re;
  double sum_w = 0.0, rate = 0.0, stress = 0.0, mirrored_slip = 0.0, separation = 0.0;
  const double p_i = std::max(P.pressure[i], 0.0);
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q) {
    const std::uint32_t j = *q;
    if (P.kind[j] == Kind::fluid) continue;
    const double r2 = distance_squared<D>(P.position[j], P.position[i]);
    if (r2 >= re2) continue;
    const double w = kernel_weight(std::sqrt(r2), re);
    const Vec<D>& n = P.wall_normal[j];
    const double d_i = n.dot(P.position[i] - P.position[j]) - P.wall_depth[j];
    const Vec<D> du = P.velocity[i] - P.velocity[j] + dt * (gravity - P.acceleration[j]);
    const double slip = (du - du.dot(n) * n).norm();
    rate += w * slip / std::max(d_i, min_distance);
    mirrored_slip += w * no_slip_mirror_factor(d_i, P.wall_depth[j], min_distance) * slip;
    separation += w * std::max(d_i + P.wall_depth[j], min_distance);  // floored: no unbounded rate near a layer
    const double d_face = std::max(d_i, 0.0);
    const double total = p_i - P.density[i] * (gravity - P.acceleration[j]).dot(n) * d_face;
    stress += w * std::max(0.0, effective_pressure(total, pore.at(P.position[i] - d_face * n)));
    sum_w += w;
  }
  if (sum_w == 0.0) return {};
  // The rate whose Coulomb fraction makes i's wall pairs carry mu_b sigma times its share sum (d_i + d_j) W_ij of the
  // crossing pairs' sum (above), also where d_i is clipped at min_distance in the pairs' mirror factor
  // (fluid/viscosity.hpp): sum (1 + d_j / max(d_i, d_min)) W |du_t| / sum max(d_i + d_j, d_min) W, which is
  // |du_t| / d_i where nothing is clipped. With the clipped rate alone, the hexagonal lattice's first row along a
  // slope (d_i = 0.465 dp, half its row spacing, under the clip at dp / 2) and a block pressed nearer the face as it
  // chatters got more than mu_b sigma: a Coulomb block slid 17.5 % slower than the closed form at 20 degrees and 4.5 %
  // at 35 (issue 29). The plain rate remains for a wall without a clip distance (min_distance 0) touched at a layer.
  if (separation > 0.0) return {mirrored_slip / separation, stress / sum_w};
  return {rate / sum_w, stress / sum_w};
}

}  // namespace slide
