#pragma once
#include <cmath>

namespace slide {

// Seed eq. 7 (Lee et al. 2008): p = rho c0^2 / gamma * ((n / n0)^gamma - 1).
// Integral gamma (the usual 7) is evaluated by multiplication: it is on the hot path and std::pow is slow.
struct EquationOfState {
  double n0 = 1.0;
  double sound_speed = 1.0;  // c0, m/s
  double gamma = 7.0;
  int integral_gamma = 7;    // gamma when it is an integer, else 0

  EquationOfState() = default;
  EquationOfState(double n0_, double c0, double gamma_) : n0(n0_), sound_speed(c0), gamma(gamma_) {
    integral_gamma = (gamma_ == std::floor(gamma_) && gamma_ >= 1 && gamma_ <= 16) ? static_cast<int>(gamma_) : 0;
  }

  double power(double ratio) const {
    if (integral_gamma == 0) return std::pow(ratio, gamma);
    double r = 1.0, b = ratio;
    for (int e = integral_gamma; e > 0; e >>= 1, b *= b)
      if (e & 1) r *= b;
    return r;
  }

  double pressure(double number_density, double rho) const {
    return rho * sound_speed * sound_speed / gamma * (power(number_density / n0) - 1.0);
  }

  // Inverse: the number-density ratio n / n0 at which the pressure is p.
  double number_density_ratio(double p, double rho) const {
    return std::pow(1.0 + gamma * p / (rho * sound_speed * sound_speed), 1.0 / gamma);
  }
};

}  // namespace slide
