#pragma once
// The MPS weight function and the constants that follow from it on the initial lattice.
#include <cmath>

#include "fluid/vec.hpp"

namespace slide {

// Seed paper eq. 6 (Fu and Jin 2013): W(r) = (1 - r/re)^3 for r <= re, 0 beyond.
inline double kernel_weight(double r, double re) {
  if (r >= re) return 0.0;
  const double s = 1.0 - r / re;
  return s * s * s;
}

// n0 (seed eq. 5 on the initial lattice) and the Laplacian's lambda = sum W r^2 / sum W (seed eq. 4, whose integral
// ratio is evaluated as lattice sums so that the discrete Laplacian of a quadratic field is exact on that lattice).
struct LatticeConstants {
  double n0 = 0.0;
  double lambda = 0.0;
  // kappa = sum(-W'(r) r) / (d n0): normalises gradients built on the kernel derivative (exact for a linear field
  // on the lattice); 1 in the continuum limit.
  double kappa = 0.0;
};

// Derivative of the seed kernel: W'(r) = -3 (1 - r/re)^2 / re for r < re.
inline double kernel_derivative(double r, double re) {
  if (r >= re) return 0.0;
  const double s = 1.0 - r / re;
  return -3.0 * s * s / re;
}

// The derivative gradients' pair factor (fluid/gradient.hpp): -W'(r) / r for r < re, +0 from re on.
inline double derivative_over_r(double r, double re) {
  if (r >= re) return 0.0;
  return -kernel_derivative(r, re) / r;
}

// Sums over a square (2-D) or cubic (3-D) lattice of spacing dp, all points within re except the origin.
template <int D>
LatticeConstants lattice_constants(double dp, double re) {
  const int m = static_cast<int>(std::ceil(re / dp)) + 1;
  double sum_w = 0.0, sum_wr2 = 0.0, sum_dwr = 0.0;
  const int kmin = D == 3 ? -m : 0, kmax = D == 3 ? m : 0;
  for (int i = -m; i <= m; ++i)
    for (int j = -m; j <= m; ++j)
      for (int k = kmin; k <= kmax; ++k) {
        if (i == 0 && j == 0 && k == 0) continue;
        const double r2 = dp * dp * (double(i) * i + double(j) * j + double(k) * k);
        const double w = kernel_weight(std::sqrt(r2), re);
        sum_w += w;
        sum_wr2 += w * r2;
        sum_dwr += -kernel_derivative(std::sqrt(r2), re) * std::sqrt(r2);
      }
  return {sum_w, sum_wr2 / sum_w, sum_dwr / (D * sum_w)};
}

// Continuum limits used to check the lattice sums: integral of W over the kernel support (2-D: pi re^2 / 10,
// 3-D: pi re^3 / 15) and the continuum lambda (2-D: re^2 / 7, 3-D: 3 re^2 / 14).
template <int D>
double kernel_volume_integral(double re) {
  return D == 2 ? M_PI * re * re / 10.0 : M_PI * re * re * re / 15.0;
}
template <int D>
double continuum_lambda(double re) {
  return D == 2 ? re * re / 7.0 : 3.0 * re * re / 14.0;
}

}  // namespace slide
