#pragma once
// A velocity profile across the flow: the fluid's mean velocity in horizontal bins (velocity_profile.csv). For a
// channel periodic in x, the mean over the period; the Poiseuille error measure (tools/measures/poiseuille_profile.hpp)
// reads it.
#include <cmath>
#include <map>
#include <vector>

#include "coupling/simulation.hpp"

namespace slide {

struct VelocityProfileRow {
  double y = 0.0;      // m, mean height of its fluid particles
  double u = 0.0;      // m/s, mean x-velocity of its fluid particles
  double v = 0.0;      // m/s, mean y-velocity
  long particles = 0;
};

// The real fluid particles in bins [y_origin + k bin, y_origin + (k + 1) bin), k any integer: each non-empty bin's
// mean height and velocity, in increasing y. Sums run in particle order, which is fixed (results are the same for any thread
// count).
template <int D>
std::vector<VelocityProfileRow> velocity_profile(const Simulation<D>& sim, double y_origin, double bin) {
  const auto& P = sim.particles();
  std::map<long, VelocityProfileRow> bins;
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    if (P.kind[i] != Kind::fluid) continue;
    const long k = static_cast<long>(std::floor((P.position[i][1] - y_origin) / bin));
    VelocityProfileRow& r = bins[k];
    r.y += P.position[i][1];
    r.u += P.velocity[i][0];
    r.v += P.velocity[i][1];
    ++r.particles;
  }
  std::vector<VelocityProfileRow> out;
  for (auto& [k, r] : bins) {
    r.y /= r.particles;
    r.u /= r.particles;
    r.v /= r.particles;
    out.push_back(r);
  }
  return out;
}

}  // namespace slide
