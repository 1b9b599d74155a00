#pragma once
// Periodic boundaries in x by ghost particles. Every MPS operator takes its pair vectors as x[j] - x[i] from the
// neighbour list, so instead of a minimum-image rule in each operator the real particles near one end of the period
// get images (ghosts, fluid/ghosts.hpp) beyond the other end, and the operators see a full neighbourhood without
// knowing it. This file holds the period and the wrapping of real particles into it.

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "fluid/parallel.hpp"
#include "fluid/particles.hpp"

namespace slide {

// The period [x_min, x_max) in x; L = x_max - x_min.
struct PeriodicX {
  double x_min = 0.0, x_max = 0.0;

  double length() const { return x_max - x_min; }

  // x brought into [x_min, x_max) by a whole number of periods; a value already inside is returned unchanged, bit
  // for bit. Non-finite values are returned as they are (the stability check reports them).
  double wrap(double x) const {
    if ((x >= x_min && x < x_max) || !std::isfinite(x)) return x;
    const double L = length();
    x -= L * std::floor((x - x_min) / L);
    // Rounding can leave x just outside; one more period, and x_min for a value that x + L rounded up onto x_max.
    if (x >= x_max) x -= L;
    if (x < x_min) x += L;
    if (x >= x_max || x < x_min) x = x_min;
    return x;
  }
};

// Wraps every real particle's x into the period (ghosts must have been removed).
template <int D>
void wrap_positions(Particles<D>& P, const PeriodicX& period) {
  parallel_for(P.real_count(), [&](std::size_t i) { P.position[i][0] = period.wrap(P.position[i][0]); });
}

}  // namespace slide
