#pragma once
// Collision model: the usual MPS safeguard against particles that come too close, offered as a scene option.
#include <cmath>
#include <vector>

#include "fluid/listed_pairs.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"

namespace slide {

// Lee, Park, Kim, Jeong & Kim (2011, Comput. Methods Appl. Mech. Eng. 200), after Koshizuka et al. (1998): a fluid
// particle i and a neighbour j closer than the collision distance that approach each other collide inelastically
// with restitution e. For a fluid partner the momentum is shared by their masses, for a boundary particle (wall,
// moving with its body, or fixed) i alone rebounds:
//   du_i = - sum_j m (1 + e) max(0, (u_i - u_j) . e_ij) e_ij,   e_ij = (x_j - x_i) / |x_j - x_i|,
//   m = rho_j / (rho_i + rho_j) for fluid j, 1 for boundary j.
// Every pair uses the velocities before the collisions (each particle computes its own change), so the result does
// not depend on the order of the pairs and fluid-fluid collisions conserve momentum.
template <int D>
inline Vec<D> collision_pair_change(std::size_t i, std::uint32_t j, const Particles<D>& P, double distance,
                                    double restitution) {
  const Vec<D> rij = P.position[j] - P.position[i];
  const double r2 = rij.squaredNorm();
  if (r2 >= distance * distance || r2 == 0.0) return Vec<D>::Zero();
  const Vec<D> e = rij / std::sqrt(r2);
  const bool fluid = P.kind[j] == Kind::fluid;
  // A boundary particle moves with its body (fixed walls: zero velocity).
  const double approach = (P.velocity[i] - P.velocity[j]).dot(e);
  if (approach <= 0.0) return Vec<D>::Zero();
  const double share = fluid ? P.density[j] / (P.density[i] + P.density[j]) : 1.0;
  return (-(share * (1.0 + restitution) * approach)) * e;
}

template <int D>
Vec<D> collision_velocity_change(std::size_t i, const Particles<D>& P, const NeighborList& nl, double distance,
                                 double restitution) {
  // Accumulated in a local that is not the return value: as the named return value it lived in the caller's memory
  // and every pair stored to it and loaded it back (measured: half of this function's time, perf annotate).
  // Most particles have no neighbour that close: one look at all the pairs at once decides (7 % of the bench case's
  // time went to this stage's pair loop, perf), and the pair terms below are taken only where one is.
  Vec<D> sum = Vec<D>::Zero();
  if (!any_listed_closer<D>(P.position[i], P.position, nl.begin(i), nl.count[i], distance * distance)) return sum;
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q)
    sum += collision_pair_change<D>(i, *q, P, distance, restitution);
  const Vec<D> du = sum;
  return du;
}

}  // namespace slide
