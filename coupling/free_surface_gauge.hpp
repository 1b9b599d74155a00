#pragma once
#include <cmath>
#include <limits>

#include "coupling/simulation.hpp"

namespace slide {

// Free-surface elevation at a gauge (x, or (x, y) in 3-D): the highest point on the vertical line where the
// fluid's number density field sum_fluid W(|r - r_j|) reaches half of n0. On a flat surface whose top particles sit
// half a spacing below the water's edge this puts the surface at that edge. Scans down from above the highest
// nearby fluid particle in steps of dp/4, then bisects. NaN when the line meets no water.
template <int D>
double free_surface_elevation(const Simulation<D>& sim, const Vec<D>& gauge_point) {
  constexpr int up = D - 1;
  const auto& P = sim.particles;
  const double re = sim.re(), dp = sim.options.dp;
  const double threshold = 0.5 * sim.lattice.n0;
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
  Vec<D> q = gauge_point;
  auto density_at = [&](double y) {
    q[up] = y;
    return sim.fluid_number_density_at(q);
  };
  const double step = 0.25 * dp;
  for (double y = top + re; y >= bottom - re; y -= step) {
    if (density_at(y) >= threshold) {
      double below = y, above = y + step;
      for (int it = 0; it < 20; ++it) {
        const double mid = 0.5 * (below + above);
        (density_at(mid) >= threshold ? below : above) = mid;
      }
      return 0.5 * (below + above);
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace slide
