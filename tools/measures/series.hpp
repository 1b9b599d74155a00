#pragma once
// A sampled series y(x), x increasing, read between its samples.
#include <cstddef>
#include <vector>

namespace slide::tools {

// Linear interpolation of y(x) at `at`; the end values beyond the ends. x increasing, at least one sample.
inline double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  if (at <= x.front()) return y.front();
  for (std::size_t k = 1; k < x.size(); ++k)
    if (at <= x[k]) return y[k - 1] + (y[k] - y[k - 1]) * (at - x[k - 1]) / (x[k] - x[k - 1]);
  return y.back();
}

}  // namespace slide::tools
