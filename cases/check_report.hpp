#pragma once
// What `slide check` prints about a built scene: particle counts, spacing and lattice, the derived constants, the
// initial time step, the domain, a memory estimate, the start (hydrostatic or settled) and the bodies.
#include <string>

#include "cases/scene.hpp"

namespace slide::cases {

std::string check_report(const Scene& scene);

}  // namespace slide::cases
