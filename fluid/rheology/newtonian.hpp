#pragma once
// Newtonian fluid: eta = mu, independent of shear rate and pressure (water).
namespace slide {

struct Newtonian {
  double viscosity_pa_s;  // dynamic viscosity, Pa s

  double effective_viscosity(double /*shear_rate_per_s*/, double /*pressure_pa*/) const { return viscosity_pa_s; }
};

}  // namespace slide
