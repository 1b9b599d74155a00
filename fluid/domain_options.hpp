#pragma once
// Geometric facts of the scene that the solver must know beyond its particles: which directions are periodic.
// (The domain's bounds, which bound the stability check and the neighbour grid, are in fluid/check_options.hpp.)
#include <optional>

#include "fluid/periodic.hpp"

namespace slide {

struct DomainOptions {
  // Periodic in x over [x_min, x_max) (fluid/periodic.hpp); unset: not periodic. Fluid and fixed walls only (rigid
  // bodies are refused), and the fixed walls' particles must lie in the period, covering it once.
  std::optional<PeriodicX> periodic_x;
};

}  // namespace slide
