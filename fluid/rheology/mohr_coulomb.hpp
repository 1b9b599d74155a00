#pragma once
// Herschel-Bulkley flow with a pressure-dependent Mohr-Coulomb yield stress, a common viscoplastic model of a
// sediment whose strength grows with confinement (e.g. Fourtakas & Rogers 2016, Adv. Water Resour. 92, 186-199, in
// its Drucker-Prager form):
//   tau_y(p) = c + max(p, 0) tan(phi),
//   eta(g, p) = K g^(n - 1) + tau_y(p) / g,
// the yield term regularised and the power-law term capped for n < 1 as in fluid/rheology/herschel_bulkley.hpp.
// Cohesion c in Pa; the friction angle phi is stored in degrees as given and converted where used; a tensile
// (negative) pressure adds no frictional strength. phi = 0 is Herschel-Bulkley with tau_y = c exactly.
#include <algorithm>
#include <cmath>

#include "fluid/rheology/power_law.hpp"
#include "fluid/rheology/regularisation.hpp"

namespace slide {

struct MohrCoulomb {
  double cohesion_pa;                   // c, Pa
  double friction_angle_deg;            // phi, degrees
  double consistency_pa_s_n;            // K, Pa s^n
  double flow_index;                    // n, dimensionless
  Regularisation regularisation;        // of the yield term
  double max_power_law_viscosity_pa_s;  // cap on K g^(n - 1) for n < 1, Pa s (unused for n >= 1)

  // tau_y(p) = c + max(p, 0) tan(phi), Pa.
  double yield_stress(double pressure_pa) const {
    return cohesion_pa + std::max(pressure_pa, 0.0) * std::tan(friction_angle_deg * (M_PI / 180.0));
  }

  double effective_viscosity(double shear_rate_per_s, double pressure_pa) const {
    return power_law_viscosity(consistency_pa_s_n, flow_index, shear_rate_per_s, max_power_law_viscosity_pa_s) +
           yield_viscosity(regularisation, yield_stress(pressure_pa), shear_rate_per_s);
  }
};

}  // namespace slide
