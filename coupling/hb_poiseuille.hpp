#pragma once
// Plane Poiseuille flow of a Herschel-Bulkley fluid: the closed form, and the error of a simulated channel against it
// (product code: the tests and, later, sweeps call the same measure).
#include <algorithm>
#include <cmath>
#include <map>

#include "coupling/simulation.hpp"
#include "fluid/strain_rate.hpp"

namespace slide {

// Steady flow between walls at y = +-H driven by a body force G = rho g_x [N/m^3] (the closed form in
// ../shared/validation/README.md; e.g. Bird, Dai & Yarusso 1983, Rev. Chem. Eng. 1):
//   u(y) = n / ((n + 1) G K^(1/n)) [(G H - tau0)^((n+1)/n) - (G max(|y|, y0) - tau0)^((n+1)/n)],  y0 = tau0 / G,
// a rigid plug for |y| <= y0. Requires G H > tau0 (the fluid flows).
struct HbPoiseuille {
  double consistency, flow_index, yield_stress, body_force, half_width;  // K [Pa s^n], n, tau0 [Pa], G, H [m]

  double plug_half_width() const { return std::min(yield_stress / body_force, half_width); }
  double velocity(double y_from_centre) const {
    const double n = flow_index, G = body_force, y = std::max(std::abs(y_from_centre), plug_half_width());
    const double e = (n + 1.0) / n;
    return n / ((n + 1.0) * G * std::pow(consistency, 1.0 / n)) *
           (std::pow(G * half_width - yield_stress, e) - std::pow(std::max(G * y - yield_stress, 0.0), e));
  }
  double max_velocity() const { return velocity(0.0); }
  // Shear rate at the wall, |du/dy| = ((G H - tau0) / K)^(1/n).
  double wall_shear_rate() const { return std::pow((body_force * half_width - yield_stress) / consistency, 1.0 / flow_index); }
};

struct ChannelProfileError {
  double l2 = 0.0;             // rms over the channel's fluid particles of (u - u_exact) / u_max
  double centreline = 0.0;     // (mean u of the particles nearest the centre - u_max) / u_max
  double plug_half_width = 0;  // m: where the row-mean shear rate rises through 1 % of the wall's (interpolated)
  std::size_t particles = 0;
};

// The error of the fluid particles of a channel whose walls' faces are y = centre -+ H against the closed form.
// Rows are the particles' y rounded to `row_tolerance`; the plug's half width is the distance from the centre at
// which the rows' mean shear rate (fluid/strain_rate.hpp) first exceeds 1 % of the closed form's wall shear rate,
// interpolated linearly between rows.
template <int D>
ChannelProfileError channel_profile_error(const Simulation<D>& sim, const HbPoiseuille& exact, double centre) {
  const auto& P = sim.particles;
  const double u_max = exact.max_velocity(), dp = sim.options.dp;
  ChannelProfileError e;
  double sum2 = 0.0, nearest = INFINITY, centre_sum = 0.0;
  std::size_t centre_count = 0;
  std::map<long, std::pair<double, int>> rate_by_row;  // row (y / (dp/8) rounded) -> summed shear rate, count
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    if (P.kind[i] != Kind::fluid) continue;
    const double y = P.position[i][1] - centre;
    const double d = (P.velocity[i][0] - exact.velocity(y)) / u_max;
    sum2 += d * d;
    ++e.particles;
    nearest = std::min(nearest, std::abs(y));
    auto& r = rate_by_row[std::lround(std::abs(y) / (0.125 * dp))];
    r.first += shear_rate<D>(i, P, sim.neighbors(), sim.re(), sim.lattice.n0, sim.options.viscous_wall());
    ++r.second;
  }
  for (std::size_t i = 0; i < P.real_count(); ++i)
    if (P.kind[i] == Kind::fluid && std::abs(std::abs(P.position[i][1] - centre) - nearest) < 1e-6 * dp) {
      centre_sum += P.velocity[i][0];
      ++centre_count;
    }
  e.l2 = std::sqrt(sum2 / std::max<std::size_t>(e.particles, 1));
  e.centreline = (centre_sum / std::max<std::size_t>(centre_count, 1) - u_max) / u_max;
  const double threshold = 0.01 * exact.wall_shear_rate();
  double y_prev = 0.0, g_prev = 0.0;
  bool first = true;
  e.plug_half_width = exact.half_width;
  for (const auto& [row, sum_count] : rate_by_row) {
    const double y = row * 0.125 * dp, g = sum_count.first / sum_count.second;
    if (g > threshold) {
      e.plug_half_width = first ? 0.0 : y_prev + (threshold - g_prev) / (g - g_prev) * (y - y_prev);
      break;
    }
    y_prev = y, g_prev = g, first = false;
  }
  return e;
}

}  // namespace slide
