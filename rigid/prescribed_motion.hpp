#pragma once
// Prescribed planar motion of a body: a time series or a closed-form law (3-D: rigid/spatial_prescribed_motion.hpp). The velocity returned is the exact time
// derivative of the same position function, so a prescribed body's boundary particles move consistently.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <optional>
#include <string>
#include <vector>

#include "rigid/hermite.hpp"
#include "rigid/ln_cosh_law.hpp"
#include "rigid/rigid_world.hpp"

namespace slide::rigid {

struct MotionSample {
  double time = 0.0;
  PlanarState state;  // position, angle; velocity and angular velocity used when has_velocity
};

class PrescribedMotion {
 public:
  // Piecewise cubic Hermite through the samples (times strictly increasing). With has_velocity the samples'
  // velocities are the slopes (a free run's bodies.csv is reproduced in position and velocity at every sample);
  // otherwise the slopes are centred differences (one-sided at the ends).
  static PrescribedMotion from_samples(std::vector<MotionSample> samples, bool has_velocity) {
    if (samples.size() < 2) throw std::invalid_argument("a prescribed motion needs at least two samples");
    for (std::size_t k = 1; k < samples.size(); ++k)
      if (!(samples[k].time > samples[k - 1].time))
        throw std::invalid_argument("prescribed motion times must increase strictly (row " + std::to_string(k + 1) +
                                    ")");
    if (!has_velocity) {
      const std::size_t n = samples.size();
      for (std::size_t k = 0; k < n; ++k) {
        const std::size_t a = k == 0 ? 0 : k - 1, b = k + 1 == n ? k : k + 1;
        const double h = samples[b].time - samples[a].time;
        samples[k].state.velocity = (samples[b].state.position - samples[a].state.position) / h;
        samples[k].state.angular_velocity = (samples[b].state.angle - samples[a].state.angle) / h;
      }
    }
    PrescribedMotion m;
    m.samples_ = std::move(samples);
    return m;
  }

  // Sliding along a straight line from rest by the ln cosh law (rigid/ln_cosh_law.hpp): x(t) = start + s(t) direction
  // (unit), angle constant.
  static PrescribedMotion ln_cosh(const Vec2& start, double angle, const Vec2& direction, double s0, double t0,
                                  double begin) {
    PrescribedMotion m;
    m.law_ = LnCoshLaw(s0, t0, begin);
    m.start_ = start;
    m.angle_ = angle;
    m.direction_ = direction.normalized();
    return m;
  }

  double first_time() const { return law_ ? -INFINITY : samples_.front().time; }
  double last_time() const { return law_ ? INFINITY : samples_.back().time; }

  PlanarState at(double t) const {
    PlanarState s;
    if (law_) {
      s.position = start_ + law_->distance(t) * direction_;
      s.angle = angle_;
      s.velocity = law_->speed(t) * direction_;
      return s;
    }
    const std::size_t k = segment_holding(samples_, t);
    const MotionSample &a = samples_[k], &b = samples_[k + 1];
    const double h = b.time - a.time, u = (t - a.time) / h;
    const auto [h00, h10, h01, h11, d00, d10, d01, d11] = HermiteBasis(u);
    s.position = h00 * a.state.position + (h10 * h) * a.state.velocity + h01 * b.state.position +
                 (h11 * h) * b.state.velocity;
    s.velocity = (d00 / h) * a.state.position + d10 * a.state.velocity + (d01 / h) * b.state.position +
                 d11 * b.state.velocity;
    s.angle = h00 * a.state.angle + h10 * h * a.state.angular_velocity + h01 * b.state.angle +
              h11 * h * b.state.angular_velocity;
    s.angular_velocity = d00 / h * a.state.angle + d10 * a.state.angular_velocity + d01 / h * b.state.angle +
                         d11 * b.state.angular_velocity;
    return s;
  }

 private:
  std::vector<MotionSample> samples_;
  std::optional<LnCoshLaw> law_;
  Vec2 start_ = Vec2::Zero(), direction_ = Vec2::UnitX();
  double angle_ = 0.0;
};

}  // namespace slide::rigid
