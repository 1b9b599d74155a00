#pragma once
// Geometric facts of the scene that the solver must know beyond its particles: which directions are periodic, and
// which planes are planes of symmetry.
// (The domain's bounds, which bound the stability check and the neighbour grid, are in fluid/check_options.hpp.)
#include <optional>
#include <vector>

#include "fluid/mirror_plane.hpp"
#include "fluid/periodic.hpp"

namespace slide {

struct DomainOptions {
  // Periodic in x over [x_min, x_max) (fluid/periodic.hpp); unset: not periodic. Fluid and fixed walls only (rigid
  // bodies are refused), and the fixed walls' particles must lie in the period, covering it once.
  std::optional<PeriodicX> periodic_x;
  // Planes of symmetry (fluid/mirror_plane.hpp): the particles near them get mirror images beyond (fluid/ghosts.hpp).
  // Every particle lies on their modelled side; two planes on one axis stand at least twice the list radius apart; not
  // along a periodic x; not with the implicit viscosity (its matrix takes a ghost's velocity as its source's).
  std::vector<MirrorPlane> mirrors;
  // Several processes (fluid/domain.hpp): the cells are shared anew when the largest process's share of the particles
  // exceeds the mean by this factor (scene key processes.rebalance_imbalance). The results do not depend on it, only the
  // balance and the time spent repartitioning; 1.25 is a first choice, not tuned by a sweep.
  double rebalance_imbalance = 1.25;
};

}  // namespace slide
