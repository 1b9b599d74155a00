#pragma once
// Dense granular flow, the mu(I) rheology of Jop, Forterre & Pouliquen (2006, Nature 441, 727-730; inertial number
// after GDR MiDi 2004, Eur. Phys. J. E 14, 341-365):
//   I = g d / sqrt(p / rho_s)                          inertial number (d grain diameter m, rho_s grain density kg/m3)
//   mu(I) = mu_s + (mu_2 - mu_s) / (I0 / I + 1)        friction coefficient, from mu_s at I = 0 to mu_2 as I -> inf
//   eta(g, p) = mu(I) max(p, 0) / g                    effective viscosity, Pa s
// As I -> 0 the shear stress eta g tends to mu_s p: the material yields where the shear stress reaches mu_s p (a
// Drucker-Prager criterion with friction angle atan(mu_s)). eta itself diverges as g -> 0, so it is regularised by
// a cap, eta <= max_viscosity_pa_s, as in Lagree, Staron & Popinet (2011, J. Fluid Mech. 686, 378-408): g = 0 with
// p > 0 gives the cap. A material under no (or tensile) pressure has no strength: p <= 0 gives 0, raised to
// min_viscosity_pa_s, an optional small floor (0 by default) that keeps separating grains from moving without any
// viscous coupling at all, for numerical reasons only.
#include <algorithm>
#include <cmath>
#include <limits>

namespace slide {

struct GranularMuI {
  double mu_s;                  // static friction coefficient, dimensionless
  double mu_2;                  // limiting friction coefficient at large I, dimensionless
  double i0;                    // I0, dimensionless
  double grain_diameter_m;      // d
  double grain_density_kg_m3;   // rho_s
  double max_viscosity_pa_s;    // cap on eta
  double min_viscosity_pa_s = 0.0;  // floor on eta (numerical, optional)

  // I = g d / sqrt(p / rho_s); infinite for p <= 0 with g > 0, and 0 for g = 0.
  double inertial_number(double shear_rate_per_s, double pressure_pa) const {
    if (shear_rate_per_s <= 0.0) return 0.0;
    if (pressure_pa <= 0.0) return std::numeric_limits<double>::infinity();
    return shear_rate_per_s * grain_diameter_m / std::sqrt(pressure_pa / grain_density_kg_m3);
  }

  // mu(I) = mu_s + (mu_2 - mu_s) / (I0 / I + 1); mu(0) = mu_s, mu(inf) = mu_2.
  double friction(double inertial_number) const {
    if (inertial_number <= 0.0) return mu_s;
    return mu_s + (mu_2 - mu_s) / (i0 / inertial_number + 1.0);
  }

  // eta = min(mu(I) p / g, eta_max) for p > 0 (eta_max at g = 0), 0 for p <= 0; then at least the floor.
  double effective_viscosity(double shear_rate_per_s, double pressure_pa) const {
    if (pressure_pa <= 0.0) return min_viscosity_pa_s;
    double eta = max_viscosity_pa_s;
    if (shear_rate_per_s > 0.0)
      eta = std::min(friction(inertial_number(shear_rate_per_s, pressure_pa)) * pressure_pa / shear_rate_per_s,
                     max_viscosity_pa_s);
    return std::max(eta, min_viscosity_pa_s);
  }
};

}  // namespace slide
