#pragma once
// The turning points of a sampled series y(x): a decaying oscillation's troughs and crests (a floating body's heave).
#include <cstddef>
#include <vector>

namespace slide::tools {

struct Extremum {
  double x = 0.0, y = 0.0;
};

// Each sample k (not the first or last, x[k] > from) where y turns (y[k] - y[k-1] and y[k+1] - y[k] of opposite signs),
// refined to the vertex of the parabola through samples k - 1, k, k + 1 (exact for a series that is a parabola
// there; O(h^2) off for a smooth one sampled at h). In order of x.
inline std::vector<Extremum> turning_points(const std::vector<double>& x, const std::vector<double>& y, double from = -1e300) {
  std::vector<Extremum> out;
  for (std::size_t k = 1; k + 1 < x.size() && k + 1 < y.size(); ++k) {
    if (!(x[k] > from) || !((y[k] - y[k - 1]) * (y[k + 1] - y[k]) < 0.0)) continue;
    // Newton's form through the three samples: p = y_k + d0 u + a u (u + h0), u = t - x_k, a the second divided
    // difference.
    const double h0 = x[k] - x[k - 1], h1 = x[k + 1] - x[k];
    const double d0 = (y[k] - y[k - 1]) / h0, d1 = (y[k + 1] - y[k]) / h1;
    const double a = (d1 - d0) / (h0 + h1);  // half the second derivative
    // p = y_k + s u + a u^2 with s = d0 + a h0 its slope at x_k; its vertex at u = -s / (2 a).
    const double s = d0 + a * h0;
    const double t = -s / (2.0 * a);
    out.push_back({x[k] + t, y[k] + s * t + a * t * t});
  }
  return out;
}

}  // namespace slide::tools
