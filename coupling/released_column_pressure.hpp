#pragma once
// The pressure in a water column at the instant it is released (t = 0+): the exact answer a wall model is tested
// against (tests/test_wall_models.cpp).
#include <cmath>

namespace slide {

// An incompressible column of width a (wall face x = 0, free face x = a) and height h (floor y = 0, free surface
// y = h), at rest, released at t = 0. At t = 0+ the velocity is still zero, so the acceleration is g - grad p / rho
// and incompressibility makes p harmonic, with p = 0 on the free faces x = a and y = h, dp/dx = 0 on the wall (no
// flow through it) and dp/dy = -rho g on the floor. Separation of variables in cos(k x), with the floor condition's
// Fourier series 1 = sum_n 2 (-1)^(n+1) / (a k_n) cos(k_n x) on [0, a), gives
//   p(x, y) = rho g sum_{n>=1} 2 (-1)^(n+1) / (a k_n^2) cos(k_n x) sinh(k_n (h - y)) / cosh(k_n h),
//   k_n = (2n - 1) pi / (2 a)
// (derived here by separation of variables; issue 12 states the same series). Each term satisfies Laplace's equation and the conditions on x = 0,
// x = a and y = h; the floor's condition holds for the sum. The terms fall as 1/n^2 (exp(-k_n y) above the floor),
// so the sum is taken until a term is below 1e-12 of rho g a and at most `max_terms` terms (on the floor, 2000
// terms leave about 1e-4 of rho g a). Even in x: p(-x, y) = p(x, y) continues the field into the wall.
inline double released_column_pressure(double x, double y, double width, double height, double rho, double g,
                                       int max_terms = 2000) {
  const double pi = 3.14159265358979323846;
  double sum = 0.0;
  for (int n = 1; n <= max_terms; ++n) {
    const double k = (2 * n - 1) * pi / (2 * width);
    // sinh(k (h - y)) / cosh(k h) without overflow, for 0 <= y <= h.
    const double ratio = (std::exp(-k * y) - std::exp(-k * (2 * height - y))) / (1.0 + std::exp(-2 * k * height));
    const double term = 2.0 / (width * k * k) * std::cos(k * x) * ratio;
    sum += (n % 2 == 1) ? term : -term;
    if (std::abs(term) < 1e-12 * width && n > 8) break;
  }
  return rho * g * sum;
}

}  // namespace slide
