#pragma once
// The discrete hydrostatic equilibrium of a water column, used to start still water at rest.
#include <string>
#include <vector>

#include "coupling/simulation.hpp"

namespace slide {

struct EquilibriumColumn {
  // gap_from_top[k]: vertical distance between row k (k = 0 the surface row) and the row below it; the last entry
  // is the bottom row's distance from the floor's wall layer.
  std::vector<double> gap_from_top;
  double relaxation_time = 0.0;   // simulated seconds of damped relaxation
  long steps = 0;
  double residual_speed = 0.0;    // largest row speed at the end, m/s
};

// Finds the equilibrium of `rows` rows of fluid particles on a floor under gravity with the scene's own operators
// (gradient model, wall model, equation of state, free surface): a periodic slab of lattice columns (so that every
// column has a complete neighbourhood), every column moving with the first one (no shear, so the lattice cannot
// rearrange), relaxed by damped dynamics until the rows stop. The equation of state alone leaves the surface
// rows out of balance (their number density lacks the missing water above), and they would oscillate for ever.
// relaxation_cfl: the Courant number it relaxes at (or the run's, if larger); the result is the run's equilibrium
// whatever it is (equilibrium_column.cpp says why), and only the cost changes. 0.5 was measured to be stable and to
// take a third of the steps of 0.2.
EquilibriumColumn equilibrium_column(const FluidOptions<2>& options, double density, double viscosity, int rows,
                                     double relaxation_cfl = 0.5);

}  // namespace slide
