#pragma once
// A body on a rail (bodies[k].motion: rail): it moves only along the rail's direction and does not turn; the rail
// takes every force across it, and its Coulomb friction, mu times that force, opposes the motion along it (Enet &
// Grilli's slide ran on wheels along a rail). The body's one degree of freedom is integrated here, as Bullet steps a
// free body (semi-implicit Euler: the speed first, then the travel with the new speed); Bullet carries the body as a
// kinematic one at the pose this gives.
#include <cmath>

namespace slide::rigid {

struct Rail {
  double direction[3] = {1.0, 0.0, 0.0};  // unit
  double friction = 0.0;                   // Coulomb coefficient of the rail
};

// The speed along the rail after dt (m/s), from the speed before, the force along the rail and the size of the force
// across it (N, gravity and the fluid together), the body's mass (kg) and the rail's friction coefficient mu:
//   m dv/dt = F_along - mu |F_across| sign(v)                   (v != 0),
//   at rest: stays so while |F_along| <= mu |F_across|, else starts under F_along - mu |F_across| sign(F_along).
// A speed that reaches zero within the step does so at t* = |v| m / (|F_along| + grip) (the force and friction both
// against it); the body then rests if friction holds it, or goes back under |F_along| - grip for the rest of the
// step (without friction this is v + dt F_along / m exactly).
inline double rail_speed_after(double speed, double force_along, double force_across, double mass, double mu,
                               double dt) {
  const double grip = mu * std::abs(force_across);  // N, the most the friction holds
  if (speed == 0.0)
    return std::abs(force_along) <= grip ? 0.0 : dt * (force_along - std::copysign(grip, force_along)) / mass;
  const double next = speed + dt * (force_along - std::copysign(grip, speed)) / mass;
  if ((next > 0.0) == (speed > 0.0)) return next;
  if (std::abs(force_along) <= grip) return 0.0;
  const double at_rest = std::abs(speed) * mass / (std::abs(force_along) + grip);
  return (dt - at_rest) * (force_along - std::copysign(grip, force_along)) / mass;
}

}  // namespace slide::rigid
