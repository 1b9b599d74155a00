#pragma once
// Herschel-Bulkley viscoplastic fluid (Herschel & Bulkley 1926, Kolloid-Z. 39, 291-300), the rheology of the seed
// paper's deformable slides: shear stress tau = tau_y + K g^n once yielded, i.e. the effective viscosity
//   eta(g) = K g^(n - 1) + tau_y / g,
// with the yield term regularised (fluid/rheology/regularisation.hpp) and, for n < 1, the power-law term capped at
// max_power_law_viscosity_pa_s (fluid/rheology/power_law.hpp). n = 1 and tau_y = 0 give a Newtonian fluid of
// viscosity K exactly; n = 1 alone is a Bingham fluid.
#include "fluid/rheology/power_law.hpp"
#include "fluid/rheology/regularisation.hpp"

namespace slide {

struct HerschelBulkley {
  double yield_stress_pa;               // tau_y, Pa
  double consistency_pa_s_n;            // K, Pa s^n
  double flow_index;                    // n, dimensionless
  Regularisation regularisation;        // of the yield term
  double max_power_law_viscosity_pa_s;  // cap on K g^(n - 1) for n < 1, Pa s (unused for n >= 1)

  double effective_viscosity(double shear_rate_per_s, double /*pressure_pa*/) const {
    return power_law_viscosity(consistency_pa_s_n, flow_index, shear_rate_per_s, max_power_law_viscosity_pa_s) +
           yield_viscosity(regularisation, yield_stress_pa, shear_rate_per_s);
  }
};

}  // namespace slide
