#pragma once
// How a yield stress becomes a finite viscosity. A yield stress tau_y alone gives the apparent viscosity tau_y / g,
// which is infinite in unsheared material (g = 0); each regularisation below replaces it by a bounded function that
// tends to tau_y / g wherever the material is sheared. Units: tau_y in Pa, shear rate g in 1/s, viscosities in Pa s
// (dynamic, never divided by density).
#include <algorithm>
#include <cmath>
#include <variant>

namespace slide {

// Papanastasiou (1987, J. Rheol. 31, 385-404), exponential regularisation with exponent m (seconds):
//   mu_y(g) = tau_y (1 - exp(-m g)) / g,   mu_y(0) = tau_y m  (the limit g -> 0).
// The shear stress mu_y g = tau_y (1 - exp(-m g)) tends to tau_y for m g >> 1; the larger m, the sharper the yield.
// 1 - exp(-m g) is evaluated as -expm1(-m g), which keeps full accuracy when m g is small.
struct Papanastasiou {
  double exponent_s;
};

inline double yield_viscosity(const Papanastasiou& r, double yield_stress_pa, double shear_rate_per_s) {
  const double m = r.exponent_s;
  if (shear_rate_per_s <= 0.0) return yield_stress_pa * m;
  return -yield_stress_pa * std::expm1(-m * shear_rate_per_s) / shear_rate_per_s;
}

// Bi-viscosity (O'Donovan & Tanner 1984, J. Non-Newtonian Fluid Mech. 15, 75-83; Beverly & Tanner 1992, J. Rheol.
// 36, 429-444): unyielded material is a very viscous Newtonian fluid,
//   mu_y(g) = min(tau_y / g, mu_max),   mu_y(0) = mu_max,
// exact (tau_y / g) above the crossover shear rate tau_y / mu_max. Without a yield stress (tau_y <= 0) it is 0 at
// every shear rate, the limit of min(0 / g, mu_max).
struct BiViscosity {
  double max_viscosity_pa_s;
};

inline double yield_viscosity(const BiViscosity& r, double yield_stress_pa, double shear_rate_per_s) {
  if (yield_stress_pa <= 0.0) return 0.0;
  if (shear_rate_per_s <= 0.0) return r.max_viscosity_pa_s;
  return std::min(yield_stress_pa / shear_rate_per_s, r.max_viscosity_pa_s);
}

using Regularisation = std::variant<Papanastasiou, BiViscosity>;

// The regularised yield-stress viscosity mu_y(tau_y, g) of whichever regularisation r holds.
inline double yield_viscosity(const Regularisation& r, double yield_stress_pa, double shear_rate_per_s) {
  return std::visit([&](const auto& reg) { return yield_viscosity(reg, yield_stress_pa, shear_rate_per_s); }, r);
}

}  // namespace slide
