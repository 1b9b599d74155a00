#pragma once
// What `slide check` prints about a built scene: particle counts, spacing and lattice, the derived constants, the
// initial time step, the domain, a memory estimate, the start (hydrostatic or settled) and the bodies.
#include <string>

#include "cases/scene.hpp"

namespace slide::cases {

// Memory the run will hold, MB: two copies of the particles (the state and the last good one), the position copy
// for the skin test, and the neighbour list.
double memory_estimate_mb(const Simulation<2>& sim);

std::string check_report(const Scene& scene);

}  // namespace slide::cases
