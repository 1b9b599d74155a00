#pragma once
#include <cmath>
#include <limits>

#include "coupling/simulation.hpp"

namespace slide {

// The water's edge along a line: the first distance s in [s_begin, s_end] from `origin` along the unit vector
// `into_water` at which the water's volume fraction phi (free_surface_elevation, below) reaches 1/2, by steps of
// dp/4 and then bisection. NaN if it never does, or if the line already starts in water (s_begin wet: no edge
// between there and the dry side was seen). The free-surface gauge walks down a vertical line with it, the gap
// between a body's face and its water (coupling/water_gap.hpp) out along the face's normal.
template <int D>
double water_edge_along(const Simulation<D>& sim, const Vec<D>& origin, const Vec<D>& into_water, double s_begin,
                        double s_end) {
  const double dp = sim.options.dp;
  const double threshold = 0.5 * kernel_volume_integral<D>(sim.re()) / std::pow(dp, D);
  auto wet = [&](double s) { return sim.fluid_number_density_at(Vec<D>(origin + s * into_water)) >= threshold; };
  const double step = 0.25 * dp;
  if (wet(s_begin)) return std::numeric_limits<double>::quiet_NaN();
  const long samples = static_cast<long>(std::floor((s_end - s_begin) / step + 1e-9));
  for (long k = 1; k <= samples; ++k) {
    const double s = s_begin + k * step;
    if (!wet(s)) continue;
    double dry = s - step, water = s;
    for (int it = 0; it < 20; ++it) {
      const double mid = 0.5 * (dry + water);
      (wet(mid) ? water : dry) = mid;
    }
    return 0.5 * (dry + water);
  }
  return std::numeric_limits<double>::quiet_NaN();
}

// Free-surface elevation at a gauge (x, or (x, y) in 3-D): the highest point on the vertical line where the kernel
// interpolation of the water's volume fraction,
//   phi(q) = dp^d sum_fluid W(|q - r_j|) / integral(W dV),
// reaches 1/2. phi is 1 inside the water (each particle stands for dp^d of it) and 1/2 at a flat edge of a
// continuum, so the contour is the water's edge: on a flat square or hexagonal lattice at re = 2.1 dp it lies
// 0.03 dp and 0.02 dp below the edge (half a row spacing above the top row), measured by tests/test_gauge.cpp.
// (A threshold of n0 / 2, which ignores that n0 excludes a particle's own weight, put it 0.3 dp above the edge.)
// Scans down from above the highest nearby fluid particle in steps of dp/4, then bisects. NaN when the line meets
// no water. Periodic ghosts take part, here and in the number density: they are the water beyond the period's ends.
template <int D>
double free_surface_elevation(const Simulation<D>& sim, const Vec<D>& gauge_point) {
  constexpr int up = D - 1;
  const auto& P = sim.particles();
  const double re = sim.re();
  double top = -std::numeric_limits<double>::infinity(), bottom = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::fluid) continue;
    double h2 = 0.0;
    for (int k = 0; k < up; ++k) h2 += (P.position[i][k] - gauge_point[k]) * (P.position[i][k] - gauge_point[k]);
    if (h2 >= re * re) continue;
    top = std::max(top, P.position[i][up]);
    bottom = std::min(bottom, P.position[i][up]);
  }
  if (!std::isfinite(top)) return std::numeric_limits<double>::quiet_NaN();
  Vec<D> origin = gauge_point, down = Vec<D>::Zero();
  origin[up] = top + re;
  down[up] = -1.0;
  return origin[up] - water_edge_along<D>(sim, origin, down, 0.0, top - bottom + 2.0 * re);
}

}  // namespace slide
