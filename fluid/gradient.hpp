#pragma once
// Pressure-gradient models. All three reduce to the seed's eq. 3 for a smooth field on a regular lattice; they
// differ in what they do with particle disorder and free surfaces.
#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

#include "fluid/kernel.hpp"
#include "fluid/listed_pairs.hpp"
#include "fluid/name_table.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"

namespace slide {

enum class GradientModel {
  standard,   // seed eq. 3: (p_j - p_i)
  pmin,       // (p_j - p_min,i)
  symmetric,  // (p_i + p_j)
  variational,  // (p_i + p_j) with the kernel derivative: energy-conserving
  difference,   // (p_j - p_i) with the kernel derivative: no background-pressure forces, lattice-stable
  corrected,    // variational with each particle's corrective matrix: no shear stress from the background pressure
};

inline constexpr auto gradient_model_names = make_name_table<GradientModel>(
    std::pair{GradientModel::standard, "standard"}, std::pair{GradientModel::pmin, "pmin"},
    std::pair{GradientModel::symmetric, "symmetric"}, std::pair{GradientModel::variational, "variational"},
    std::pair{GradientModel::difference, "difference"}, std::pair{GradientModel::corrected, "corrected"});

inline std::string_view to_string(GradientModel m) { return gradient_model_names.name(m); }

// Seed eq. 3 (Koshizuka & Oka 1996; Lee et al. 2008), the MPS gradient of any scalar phi:
//   grad phi_i = d / n0 * sum_{j != i} (phi_j - phi_i) / |r_ij|^2 * r_ij * W(|r_ij|),  r_ij = r_j - r_i.
// Exact for a linear field on a regular lattice away from boundaries. As a pressure gradient it lets a particle
// be pulled towards lower-pressure neighbours, which clusters particles (the seed's "interface instabilities").
template <int D, class Field>
Vec<D> mps_gradient(std::size_t i, const std::vector<Vec<D>>& x, const Field& phi, const NeighborList& nl,
                    double re, double n0) {
  Vec<D> g = Vec<D>::Zero();
  const double re2 = re * re;
  for (const std::uint32_t* p = nl.begin(i); p != nl.end(i); ++p) {
    const std::uint32_t j = *p;
    const Vec<D> rij = x[j] - x[i];
    const double r2 = rij.squaredNorm();
    if (r2 >= re2) continue;
    g += ((phi[j] - phi[i]) * kernel_weight(std::sqrt(r2), re) / r2) * rij;
  }
  return (D / n0) * g;
}

// Pressure gradient by model, over all neighbours within re.
//  * pmin (Koshizuka, Nobe & Oka 1998, Int. J. Numer. Meth. Fluids 26): p_i is replaced by the smallest pressure
//    among i and its neighbours, so every pair term is repulsive:
//      grad p_i = d / n0 * sum (p_j - p_min,i) / |r_ij|^2 * r_ij * W.
//  * symmetric (Oochi, Koshizuka & Sakai 2010; Tanaka & Masunaga 2010): the pair force is antisymmetric, so the
//    pressure forces between fluid particles conserve linear momentum exactly:
//      grad p_i = d / n0 * sum (p_i + p_j) / |r_ij|^2 * r_ij * W.
//    On a full regular lattice sum r_ij W / r^2 = 0, so it equals eq. 3 there.
//    Against a boundary particle j (wall, dummy) the pair vector is split along the wall's normal n_j: the normal
//    part keeps (p_i + p_j), which holds the fluid off the wall, and the tangential part uses (p_j - p_i). Why: with
//    (p_i + p_j) in every direction, a fluid layer next to a row of fixed wall particles has a negative tangential
//    stiffness (a repulsive pair force pushes a particle that slides along the wall further away from alignment),
//    and in a still tank that layer slides and stirs the tank within 0.1 s (measured here). A wall can only push
//    along its normal; the tangential part then carries just the pressure difference, which completes the
//    gradient along the wall.
// The smallest pressure among i and its neighbours within re (pmin model).
template <int D>
double neighborhood_min_pressure(std::size_t i, const Particles<D>& P, const NeighborList& nl, double re) {
  const double re2 = re * re;
  double p_ref = P.pressure[i];
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q)
    if (distance_squared<D>(P.position[*q], P.position[i]) < re2) p_ref = std::min(p_ref, P.pressure[*q]);
  return p_ref;
}

// One neighbour's term of the W / r^2 models (the sum below times d / n0 is grad p_i), w = W(r_ij) / r_ij^2.
template <int D, GradientModel M>
inline Vec<D> pressure_pair_term_w(std::size_t i, std::uint32_t j, const Vec<D>& rij, double w, const Particles<D>& P,
                                   double p_ref) {
  const auto& p = P.pressure;
  if constexpr (M == GradientModel::symmetric) {
    if (P.kind[j] == Kind::fluid) return ((p[i] + p[j]) * w) * rij;
    const Vec<D>& n = P.wall_normal[j];
    const Vec<D> normal_part = rij.dot(n) * n;
    return ((p[i] + p[j]) * w) * normal_part + ((p[j] - p[i]) * w) * (rij - normal_part);
  } else {
    return ((p[j] - p_ref) * w) * rij;
  }
}

// The same from r2 = |r_ij|^2 < re^2.
template <int D, GradientModel M>
inline Vec<D> pressure_pair_term(std::size_t i, std::uint32_t j, const Vec<D>& rij, double r2, const Particles<D>& P,
                                 double re, double p_ref) {
  return pressure_pair_term_w<D, M>(i, j, rij, kernel_weight(std::sqrt(r2), re) / r2, P, p_ref);
}

template <int D, GradientModel M>
Vec<D> pressure_gradient_of(std::size_t i, const Particles<D>& P, const NeighborList& nl, double re, double n0) {
  const auto& x = P.position;
  const double re2 = re * re;
  double p_ref = P.pressure[i];
  if constexpr (M == GradientModel::pmin) p_ref = neighborhood_min_pressure<D>(i, P, nl, re);
  Vec<D> g = Vec<D>::Zero();
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q) {
    const std::uint32_t j = *q;
    const Vec<D> rij = x[j] - x[i];
    const double r2 = rij.squaredNorm();
    if (r2 >= re2) continue;
    g += pressure_pair_term<D, M>(i, j, rij, r2, P, re, p_ref);
  }
  return (D / n0) * g;
}

// The same from the W / r^2 factors the number density kept at these positions (fluid/pair_weights.hpp; w[k]: that of
// the k-th listed neighbour, 0 beyond re): no square root and no division. The factors and the sum's order are those
// above, so the result is bit-identical (for finite pressures). A fluid neighbour beyond re adds a zero term rather
// than being skipped on a branch the predictor cannot follow (as in fluid/viscosity.hpp; 2 % of the bench case's
// first 0.05 s, stop 26).
template <int D, GradientModel M>
Vec<D> pressure_gradient_from_weights(std::size_t i, const Particles<D>& P, const NeighborList& nl, double re, double n0,
                                      const double* w) {
  const auto& x = P.position;
  double p_ref = P.pressure[i];
  if constexpr (M == GradientModel::pmin) p_ref = neighborhood_min_pressure<D>(i, P, nl, re);
  Vec<D> g = Vec<D>::Zero();
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q, ++w) {
    const std::uint32_t j = *q;
    if (P.kind[j] != Kind::fluid && *w == 0.0) continue;
    g += pressure_pair_term_w<D, M>(i, j, x[j] - x[i], *w, P, p_ref);
  }
  return (D / n0) * g;
}

//  * variational: the symmetric pair sum with the kernel's derivative in place of W / r,
//      grad p_i = 1 / (kappa n0) * sum (p_i + p_j) (-W'(r_ij)) r_ij / |r_ij|,  kappa = sum(-W' r) / (d n0),
//    which is -dE/dr_i of the energy E = sum_i Psi(n_i) with Psi'(n) = p(n) / (rho kappa n0) (the MPS analogue of
//    variational SPH, e.g. Bonet & Lok 1999; Price 2012). Its forces conserve energy as well as momentum, so a
//    damped still tank settles into an equilibrium, which the W / r^2 form, not derived from any energy, does not.
//    Exact for a linear field on the regular lattice (kappa from that lattice).
//  * difference: the same kernel with the pressure difference,
//      grad p_i = 1 / (kappa n0) * sum (p_j - p_i) (-W'(r_ij)) r_ij / |r_ij|.
//    Linearised about a state of uniform pressure it is exactly minus the adjoint of the number density's
//    linearisation (dn_i = sum W'(r_ij) e_ij . (u_j - u_i)), so the discrete acoustic operator is negative
//    semidefinite: no mode of a regular lattice grows. The (p_i + p_j) forms instead add a force proportional to
//    the background pressure that makes a compressed square lattice shear-unstable (growth rate ~ sqrt(p / rho) /
//    dp; measured here: a 0.5 m still tank stirs itself within 0.1 s), and pmin carries an effective background of
//    about rho g 2 dp. The price: pair forces are not antisymmetric, so momentum is conserved only approximately.
// The pair term from the factor f = -W'(r) / r (derivative_over_r, fluid/kernel.hpp): (dp f) r_ij. The factor is
// rounded once on its own, so that the number density's stage can keep it for this stage (fluid/pair_weights.hpp);
// before stop 27 the term was rounded as (dp (-W')) / r, which differs in the last bit.
template <int D, bool Symmetric>
inline Vec<D> derivative_pair_term_f(std::size_t i, std::uint32_t j, const Vec<D>& rij, double f,
                                     const Particles<D>& P) {
  const auto& p = P.pressure;
  const double dp = Symmetric ? p[i] + p[j] : p[j] - p[i];
  return (dp * f) * rij;
}

//  * corrected: the variational pair sum with each particle's pressure acting through its corrective matrix L,
//      grad p_i = 1 / (kappa n0) * sum (p_i L_i + p_j L_j) (-W'(r_ij)) r_ij / |r_ij|,
//      L_i = A_i^-1,  A_i = 1 / (kappa n0) * sum (-W'(r_ij)) r_ij (x) r_ij / |r_ij|   (A = L = I on the regular lattice),
//    the renormalisation of Bonet & Lok (1999, Comput. Methods Appl. Mech. Engrg. 180) applied to the symmetric form,
//    as in the corrective-matrix MPS of Khayyer & Gotoh (2011, J. Comput. Phys. 230) and Duan et al. (2019). Pair
//    forces stay antisymmetric (momentum is conserved, a body gets exactly what it gives). Why: under (p_i + p_j) a
//    uniform pressure p exerts on any arrangement the stress p sum f r (x) r / (kappa n0), isotropic only on the
//    regular lattice; a sheared packing carries a shear stress proportional to the pressure. Water at rest then
//    resists shear like a solid: a box towed through still water at 0.02-0.2 m/s met 15-26 N/m at dp 0.01 and
//    0.005 alike, not converging away (where drag and viscosity give under 0.1 N/m), and slides under water were
//    held by it. With L the background's stress is p I for any arrangement. Free-surface particles (n < beta n0),
//    whose support is cut, and boundary particles keep L = I (fluid/corrective_matrix.hpp).
template <int D>
inline Vec<D> corrected_pair_term_f(std::size_t i, std::uint32_t j, const Vec<D>& rij, double f,
                                    const Particles<D>& P) {
  const auto& p = P.pressure;
  const auto& L = P.gradient_correction;
  return f * (p[i] * (L[i] * rij) + p[j] * (L[j] * rij));
}

template <int D>
Vec<D> corrected_pressure_gradient_from_factors(std::size_t i, const Particles<D>& P, const NeighborList& nl,
                                                double n0, double kappa, const double* f) {
  // The pair terms' sum with p_i L_i taken out of it: p_i L_i sum f r_ij + sum f p_j L_j r_ij (one matrix product a
  // pair instead of two). A neighbour beyond re (f = 0) adds a zero term rather than being skipped on a branch the
  // predictor cannot follow (a third of the listed pairs; the branch took 15 % of this loop, perf, and skipping only
  // the boundary ones, as the other models do, 4 % of a sediment step): every pressure and matrix is finite.
  const auto& x = P.position;
  const auto& p = P.pressure;
  const auto& L = P.gradient_correction;
  const Vec<D>& xi = P.position[i];
  Vec<D> own = Vec<D>::Zero(), others = Vec<D>::Zero();
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q, ++f) {
    const std::uint32_t j = *q;
    const Vec<D> fr = *f * (x[j] - xi);
    own += fr;
    others += p[j] * (L[j] * fr);
  }
  return (1.0 / (kappa * n0)) * (p[i] * (L[i] * own) + others);
}

template <int D, bool Symmetric>
inline Vec<D> derivative_pair_term(std::size_t i, std::uint32_t j, const Vec<D>& rij, double r2, const Particles<D>& P,
                                   double re) {
  return derivative_pair_term_f<D, Symmetric>(i, j, rij, derivative_over_r(std::sqrt(r2), re), P);
}

template <int D, bool Symmetric>
Vec<D> derivative_pressure_gradient(std::size_t i, const Particles<D>& P, const NeighborList& nl, double re,
                                    double n0, double kappa) {
  const auto& x = P.position;
  const double re2 = re * re;
  Vec<D> g = Vec<D>::Zero();
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q) {
    const std::uint32_t j = *q;
    const Vec<D> rij = x[j] - x[i];
    const double r2 = rij.squaredNorm();
    if (r2 >= re2) continue;
    g += derivative_pair_term<D, Symmetric>(i, j, rij, r2, P, re);
  }
  return (1.0 / (kappa * n0)) * g;
}

// The same from the factors -W'(r) / r the number density kept at these positions (fluid/pair_weights.hpp; f[k]: that
// of the k-th listed neighbour, +0 beyond re), bit-identical for finite pressures, as the W / r^2 models' above.
template <int D, bool Symmetric>
Vec<D> derivative_pressure_gradient_from_factors(std::size_t i, const Particles<D>& P, const NeighborList& nl,
                                                 double n0, double kappa, const double* f) {
  const auto& x = P.position;
  Vec<D> g = Vec<D>::Zero();
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q, ++f) {
    const std::uint32_t j = *q;
    if (P.kind[j] != Kind::fluid && *f == 0.0) continue;
    g += derivative_pair_term_f<D, Symmetric>(i, j, x[j] - x[i], *f, P);
  }
  return (1.0 / (kappa * n0)) * g;
}

// What neighbour j alone contributes to grad p_i under model m (zero beyond re), with the model's scale: the
// pressure force that j exerts on i is -V_i times this. Used to give a body exactly the opposite of what its
// boundary particles gave the fluid.
template <int D>
Vec<D> pressure_gradient_pair(GradientModel m, std::size_t i, std::uint32_t j, const Particles<D>& P,
                              const NeighborList& nl, double re, double n0, double kappa) {
  const Vec<D> rij = P.position[j] - P.position[i];
  const double r2 = rij.squaredNorm();
  if (r2 >= re * re) return Vec<D>::Zero();
  switch (m) {
    case GradientModel::standard:
      return (D / n0) * pressure_pair_term<D, GradientModel::standard>(i, j, rij, r2, P, re, P.pressure[i]);
    case GradientModel::pmin:
      // A ghost (a body's fluid neighbour beyond a plane of symmetry) has no list of its own: its source's
      // neighbourhood, whose minimum is the same (found in review).
      return (D / n0) * pressure_pair_term<D, GradientModel::pmin>(
                            i, j, rij, r2, P, re, neighborhood_min_pressure<D>(P.real_index(i), P, nl, re));
    case GradientModel::symmetric:
      return (D / n0) * pressure_pair_term<D, GradientModel::symmetric>(i, j, rij, r2, P, re, P.pressure[i]);
    case GradientModel::variational: return (1.0 / (kappa * n0)) * derivative_pair_term<D, true>(i, j, rij, r2, P, re);
    case GradientModel::difference: return (1.0 / (kappa * n0)) * derivative_pair_term<D, false>(i, j, rij, r2, P, re);
    case GradientModel::corrected:
      return (1.0 / (kappa * n0)) * corrected_pair_term_f<D>(i, j, rij, derivative_over_r(std::sqrt(r2), re), P);
  }
  return Vec<D>::Zero();
}

// The pair factor model m reads from the number density's stage (fluid/pair_weights.hpp).
inline PairFactor kept_pair_factor(GradientModel m) {
  const bool derivative =
      m == GradientModel::variational || m == GradientModel::difference || m == GradientModel::corrected;
  return derivative ? PairFactor::derivative_over_r : PairFactor::w_over_r2;
}

// pair_factors: the factors kept_pair_factor(m) of i's listed pairs at these positions (fluid/pair_weights.hpp), or
// nullptr: then they are taken here first, several pairs at a time (fluid/listed_pairs.hpp), and summed as kept ones
// are. Either way the result is bit-identical, for finite pressures, to the pair-by-pair sums above
// (pressure_gradient_of, derivative_pressure_gradient), which the tests compare it with. Taking them in lanes for
// the semi-implicit predictor's gradient, which has no kept factors, made the Rzadkiewicz slide's loop 1.06x faster
// (dp 0.02, 1 thread, min of 4 alternating runs, stop 27).
template <int D>
Vec<D> pressure_gradient(GradientModel m, std::size_t i, const Particles<D>& P, const NeighborList& nl, double re,
                         double n0, double kappa, const double* pair_factors = nullptr) {
  const double* f = pair_factors;
  if (!f) {
    const std::size_t count = nl.count[i];
    double* room = listed_weights_room(2 * count);  // the weights W, then the factors
    const Vec<D>& xi = P.position[i];
    const std::uint32_t* nb = nl.begin(i);
    if (kept_pair_factor(m) == PairFactor::w_over_r2)
      listed_kernel_weights<D, PairFactor::w_over_r2>(xi, P.position, nb, count, re, room, room + count);
    else
      listed_kernel_weights<D, PairFactor::derivative_over_r>(xi, P.position, nb, count, re, room, room + count);
    f = room + count;
  }
  using G = GradientModel;
  switch (m) {
    case G::standard: return pressure_gradient_from_weights<D, G::standard>(i, P, nl, re, n0, f);
    case G::pmin: return pressure_gradient_from_weights<D, G::pmin>(i, P, nl, re, n0, f);
    case G::symmetric: return pressure_gradient_from_weights<D, G::symmetric>(i, P, nl, re, n0, f);
    case G::variational: return derivative_pressure_gradient_from_factors<D, true>(i, P, nl, n0, kappa, f);
    case G::difference: return derivative_pressure_gradient_from_factors<D, false>(i, P, nl, n0, kappa, f);
    case G::corrected: return corrected_pressure_gradient_from_factors<D>(i, P, nl, n0, kappa, f);
  }
  return Vec<D>::Zero();
}

}  // namespace slide
