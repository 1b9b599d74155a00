#pragma once
// A phase: a named material with its reference density and rheology (water, a sediment, ...). A particle carries its
// phase's index (Particles::phase); its viscosity follows from the phase's rheology and the local shear rate.
#include <limits>
#include <string>

#include "fluid/rheology/rheology.hpp"

namespace slide {

struct Phase {
  std::string name;
  double density_kg_m3;  // reference density rho_0 of the equation of state
  Rheology rheology;
  // Coulomb basal friction coefficient mu_b = tan(phi_b) against walls (fluid/basal_friction.hpp); infinity: no bound,
  // the no-slip wall.
  double basal_friction = std::numeric_limits<double>::infinity();
};

}  // namespace slide
