#pragma once
// A slide released from rest on a plane, accelerating to a terminal speed (Watts 1998; Grilli & Watts 2005; the law
// Enet & Grilli 2007 fitted to their measured slide motion):
//   s(t) = s0 ln cosh((t - begin) / t0),  s'(t) = (s0 / t0) tanh((t - begin) / t0),
// with s0 = u_t^2 / a0 and t0 = u_t / a0 (u_t the terminal speed, a0 the initial acceleration); at rest before `begin`.
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace slide::rigid {

struct LnCoshLaw {
  double s0 = 1.0;     // m
  double t0 = 1.0;     // s
  double begin = 0.0;  // s

  LnCoshLaw() = default;
  LnCoshLaw(double s0_m, double t0_s, double begin_s) : s0(s0_m), t0(t0_s), begin(begin_s) {
    if (!(s0 > 0.0 && t0 > 0.0)) throw std::invalid_argument("ln_cosh needs positive s0 and t0");
  }
  double distance(double t) const { return s0 * std::log(std::cosh(std::max(0.0, t - begin) / t0)); }
  double speed(double t) const { return s0 / t0 * std::tanh(std::max(0.0, t - begin) / t0); }
};

}  // namespace slide::rigid
