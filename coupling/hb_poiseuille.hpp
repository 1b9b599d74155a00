#pragma once
// Plane Poiseuille flow of a Herschel-Bulkley fluid: the closed form, and the error of a simulated channel against it
// (product code: the tests and, later, sweeps call the same measure).
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <vector>

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
  double plug_half_width = 0;  // m: the rigid core of the rows' mean velocity profile (below), resolution dp
  double unyielded_half_width = 0;  // m: the core of rows whose every particle the rheology holds unyielded (below)
  std::size_t particles = 0;
};

// The error of the fluid particles of a channel whose walls' faces are y = centre -+ H against the closed form.
// Rows are the particles' y rounded to dp / 8, folded about the centre.
//
// The plug is where the material moves rigidly, so its half width is read from the rows' mean velocities. Between
// neighbouring rows k and k + 1 (k = 0 nearest the centre), at the interval's middle, the rate g = |u_k - u_k+1| /
// (y_k+1 - y_k) carries the stress excess e = K g^n over the yield stress that the closed form's law gives it
// (K g^n = G |y| - tau0 where sheared: linear in y). The first interval whose excess exceeds 1 % of the wall's,
// 0.01 (G H - tau0), is where shearing starts; the line through its excess and the next interval's is followed back
// to zero excess, and that is the plug's edge. On the closed form sampled at the rows this reads y0 within 0.23 dp
// (Bingham) and 0.36 dp (n = 0.5) at 20 across, the worst over y0 from 5 to 25 mm (tests/test_hb_poiseuille.cpp,
// PlugMeasureReadsTheClosedForm, checks four). A creeping plug whose excess stays under the 1 % counts as rigid.
// Why not the MPS shear rate (fluid/strain_rate.hpp), which this measure used before: the kernel fits one velocity
// gradient over re = 2.1 dp, so across the kink at the plug's edge a particle up to re inside the plug reads its
// sheared neighbours. With the particles' velocities held to the closed form's shear rate (a rigid plug to 10 mm:
// the rows 2.5 and 7.5 mm from the centre 0.0005 1/s apart), that measure read a plug half width of 6.6 mm
// (Bingham, 20 across); and a threshold at 1 % of the wall's shear rate reads the closed form itself at y0 + 4 mm
// for n = 0.5 (the shear rate rises as (|y| - y0)^2 there). Figures: tests/test_hb_poiseuille.cpp.
// unyielded_half_width is the simulation's own yield state: a particle is unyielded while its stress, lagged
// viscosity times MPS shear rate, is below tau0 (the regularisation then holds its viscosity near the cap); the
// value is the middle between the last row from the centre that is unyielded throughout and the next one, 0 if the
// central row yields. It shows what the rheology sees, smearing included; the plug is the velocity's.
template <int D>
ChannelProfileError channel_profile_error(const Simulation<D>& sim, const HbPoiseuille& exact, double centre) {
  const auto& P = sim.particles();
  const double u_max = exact.max_velocity(), dp = sim.options.dp;
  ChannelProfileError e;
  double sum2 = 0.0, nearest = INFINITY, centre_sum = 0.0;
  std::size_t centre_count = 0;
  struct Row {
    double y = 0.0, u = 0.0;
    int count = 0;
    bool yielded = false;
  };
  std::map<long, Row> rows;  // row (|y| / (dp/8) rounded)
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    if (P.kind[i] != Kind::fluid) continue;
    const double y = P.position[i][1] - centre;
    const double d = (P.velocity[i][0] - exact.velocity(y)) / u_max;
    sum2 += d * d;
    ++e.particles;
    nearest = std::min(nearest, std::abs(y));
    Row& r = rows[std::lround(std::abs(y) / (0.125 * dp))];
    r.y += std::abs(y);
    r.u += P.velocity[i][0];
    ++r.count;
    const double rate = shear_rate<D>(i, P, sim.neighbors(), sim.re(), sim.lattice.n0, sim.options.viscous_wall());
    if (P.viscosity[i] * rate >= exact.yield_stress) r.yielded = true;
  }
  for (std::size_t i = 0; i < P.real_count(); ++i)
    if (P.kind[i] == Kind::fluid && std::abs(std::abs(P.position[i][1] - centre) - nearest) < 1e-6 * dp) {
      centre_sum += P.velocity[i][0];
      ++centre_count;
    }
  e.l2 = std::sqrt(sum2 / std::max<std::size_t>(e.particles, 1));
  e.centreline = (centre_sum / std::max<std::size_t>(centre_count, 1) - u_max) / u_max;

  // Row intervals from the centre out: their middles and the stress excess K g^n their shear rate carries.
  std::vector<double> middle, excess;
  std::optional<Row> prev;
  e.plug_half_width = e.unyielded_half_width = exact.half_width;
  bool unyielded_found = false;
  for (const auto& [key, sums] : rows) {
    Row r = sums;
    r.y /= r.count, r.u /= r.count;
    if (prev) {
      middle.push_back(0.5 * (prev->y + r.y));
      const double rate = std::abs(prev->u - r.u) / (r.y - prev->y);
      excess.push_back(exact.consistency * std::pow(rate, exact.flow_index));
      if (!unyielded_found && r.yielded) e.unyielded_half_width = middle.back(), unyielded_found = true;
    } else if (r.yielded) {
      e.unyielded_half_width = 0.0, unyielded_found = true;
    }
    prev = r;
  }
  const double threshold = 0.01 * (exact.body_force * exact.half_width - exact.yield_stress);
  for (std::size_t k = 0; k < excess.size(); ++k) {
    if (excess[k] <= threshold) continue;
    e.plug_half_width = middle[k];
    if (k + 1 < excess.size() && excess[k + 1] > excess[k])
      e.plug_half_width = std::max(0.0, middle[k] - excess[k] / (excess[k + 1] - excess[k]) * (middle[k + 1] - middle[k]));
    break;
  }
  return e;
}

}  // namespace slide
