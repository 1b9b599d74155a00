#pragma once
// Collision model: the usual MPS safeguard against particles that come too close, offered as a scene option.
#include <cmath>
#include <vector>

#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"

namespace slide {

// Lee, Park, Kim, Jeong & Kim (2011, Comput. Methods Appl. Mech. Eng. 200), after Koshizuka et al. (1998): a fluid
// particle i and a neighbour j closer than the collision distance that approach each other collide inelastically
// with restitution e. For a fluid partner the momentum is shared by their masses, for a boundary particle (wall,
// immovable) i alone rebounds:
//   du_i = - sum_j m (1 + e) max(0, (u_i - u_j) . e_ij) e_ij,   e_ij = (x_j - x_i) / |x_j - x_i|,
//   m = rho_j / (rho_i + rho_j) for fluid j, 1 for boundary j.
// Every pair uses the velocities before the collisions (each particle computes its own change), so the result does
// not depend on the order of the pairs and fluid-fluid collisions conserve momentum.
template <int D>
Vec<D> collision_velocity_change(std::size_t i, const Particles<D>& P, const NeighborList& nl, double distance,
                                 double restitution) {
  const auto& x = P.position;
  const auto& u = P.velocity;
  const double d2 = distance * distance;
  Vec<D> du = Vec<D>::Zero();
  for (const std::uint32_t* q = nl.begin(i); q != nl.end(i); ++q) {
    const std::uint32_t j = *q;
    const Vec<D> rij = x[j] - x[i];
    const double r2 = rij.squaredNorm();
    if (r2 >= d2 || r2 == 0.0) continue;
    const Vec<D> e = rij / std::sqrt(r2);
    const bool fluid = P.kind[j] == Kind::fluid;
    const double approach = (u[i] - (fluid ? u[j] : Vec<D>::Zero())).dot(e);
    if (approach <= 0.0) continue;
    const double share = fluid ? P.density[j] / (P.density[i] + P.density[j]) : 1.0;
    du -= (share * (1.0 + restitution) * approach) * e;
  }
  return du;
}

}  // namespace slide
