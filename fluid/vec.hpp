#pragma once
// Fixed-size vectors of the simulation's dimension D (2 or 3), unaligned so they pack densely in std::vector.
#include <Eigen/Core>

namespace slide {

template <int D>
using Vec = Eigen::Matrix<double, D, 1, Eigen::DontAlign>;

template <int D>
using Mat = Eigen::Matrix<double, D, D, Eigen::DontAlign>;

// Squared distance without the temporary Eigen would create for (a - b).squaredNorm() in debug builds.
template <int D>
inline double distance_squared(const Vec<D>& a, const Vec<D>& b) {
  double s = 0.0;
  for (int k = 0; k < D; ++k) {
    const double d = a[k] - b[k];
    s += d * d;
  }
  return s;
}

}  // namespace slide
