#pragma once
// Piecewise cubic Hermite interpolation through timed samples (the prescribed motions' series, 2-D and 3-D): which
// segment holds a time, and the basis at the fraction u of it.
#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace slide::rigid {

// The Hermite basis at u in [0, 1] and its derivative with respect to u: on a segment of length h from sample a to b,
// x(u) = h00 x_a + h10 h v_a + h01 x_b + h11 h v_b, and dx/dt = (d00 x_a + d01 x_b) / h + d10 v_a + d11 v_b.
struct HermiteBasis {
  double h00, h10, h01, h11, d00, d10, d01, d11;
  explicit HermiteBasis(double u)
      : h00((1 + 2 * u) * (1 - u) * (1 - u)),
        h10(u * (1 - u) * (1 - u)),
        h01(u * u * (3 - 2 * u)),
        h11(u * u * (u - 1)),
        d00(6 * u * u - 6 * u),
        d10(3 * u * u - 4 * u + 1),
        d01(-d00),
        d11(3 * u * u - 2 * u) {}
};

// The index k of the segment [samples[k].time, samples[k + 1].time] that holds t (the later one at a sample's time;
// the last at the last time); std::out_of_range outside the samples by more than the 1e-9 s a scene's check allows
// (a run's last step ends at end_time to round-off).
template <class Sample>
std::size_t segment_holding(const std::vector<Sample>& samples, double t) {
  if (t < samples.front().time - 1e-9 || t > samples.back().time + 1e-9)
    throw std::out_of_range("time " + std::to_string(t) + " s outside the prescribed motion's samples");
  std::size_t k = std::upper_bound(samples.begin(), samples.end(), t,
                                   [](double v, const Sample& m) { return v < m.time; }) -
                  samples.begin();
  return std::min(std::max<std::size_t>(k, 1), samples.size() - 1) - 1;
}

}  // namespace slide::rigid
