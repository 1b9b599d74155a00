#pragma once
// What `slide check` prints about a built scene: particle counts, spacing and lattice, the derived constants, the
// initial time step, the domain, a memory estimate, the start (hydrostatic or settled) and the bodies.
#include <string>

#include "cases/scene.hpp"

namespace slide::cases {

template <int D>
std::string check_report(const Scene<D>& scene);

}  // namespace slide::cases
