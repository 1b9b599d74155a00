#pragma once
// The power-law (Ostwald-de Waele) part shared by Herschel-Bulkley and Mohr-Coulomb: eta_K(g) = K g^(n - 1), with
// consistency K in Pa s^n and flow index n (dimensionless). Viscosities in Pa s.
#include <algorithm>
#include <cmath>

namespace slide {

// eta_K(g) = K g^(n - 1)                                         (Ostwald-de Waele power law)
//  * n = 1: exactly K (no pow), so a Newtonian fluid is reproduced bit for bit.
//  * n < 1 (shear-thinning): K g^(n - 1) diverges as g -> 0; it is capped at max_viscosity_pa_s, its own cap,
//    independent of the yield stress's regularisation. g = 0 gives the cap.
//  * n > 1 (shear-thickening): no cap; g = 0 gives 0.
inline double power_law_viscosity(double consistency_pa_s_n, double flow_index, double shear_rate_per_s,
                                  double max_viscosity_pa_s) {
  if (flow_index == 1.0) return consistency_pa_s_n;
  if (shear_rate_per_s <= 0.0) return flow_index < 1.0 ? max_viscosity_pa_s : 0.0;
  const double eta = consistency_pa_s_n * std::pow(shear_rate_per_s, flow_index - 1.0);
  return flow_index < 1.0 ? std::min(eta, max_viscosity_pa_s) : eta;
}

}  // namespace slide
