#pragma once
// Prescribed motion of a solid body (3-D scenes): the ln cosh law along a direction, the body not turning (the Enet &
// Grilli slide on its rail), or a time series of poses (a measured motion, a free run's bodies.csv). Its velocity is
// the exact time derivative of the same pose function, so the boundary particles move consistently. (2-D:
// rigid/prescribed_motion.hpp.)
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "rigid/hermite.hpp"
#include "rigid/ln_cosh_law.hpp"
#include "rigid/rigid_world.hpp"

namespace slide::rigid {

struct SpatialSample {
  double time = 0.0;                     // s
  Vec3 position = Vec3::Zero();          // centre of mass, m
  Quat orientation = Quat::Identity();   // rotation since the body's creation (unit)
  Vec3 velocity = Vec3::Zero();          // of the centre of mass, m/s; used where the series gives it
};

class SpatialPrescribedMotion {
 public:
  // x(t) = start + s(t) direction (made unit), the orientation that of creation.
  static SpatialPrescribedMotion ln_cosh(const Vec3& start, const Vec3& direction, const LnCoshLaw& law) {
    if (!(direction.norm() > 0.0)) throw std::invalid_argument("ln_cosh needs a direction");
    SpatialPrescribedMotion m;
    m.start_ = start;
    m.direction_ = direction.normalized();
    m.law_ = law;
    return m;
  }

  // Through the samples (times strictly increasing): the centre of mass by piecewise cubic Hermite, its slopes the
  // samples' velocities where has_velocity (a free run's bodies.csv is reproduced in position and velocity at every
  // sample), else centred differences (one-sided at the ends); the orientation by spherical linear interpolation
  // between consecutive samples (Shoemake 1985), the shorter way round, so the angular velocity is constant between
  // two samples and the orientation is reproduced at every sample.
  static SpatialPrescribedMotion from_samples(std::vector<SpatialSample> samples, bool has_velocity) {
    if (samples.size() < 2) throw std::invalid_argument("a prescribed motion needs at least two samples");
    for (std::size_t k = 1; k < samples.size(); ++k)
      if (!(samples[k].time > samples[k - 1].time))
        throw std::invalid_argument("prescribed motion times must increase strictly (row " + std::to_string(k + 1) +
                                    ")");
    for (auto& s : samples) {
      if (!(s.orientation.norm() > 0.0)) throw std::invalid_argument("a sample's quaternion is zero");
      s.orientation.normalize();
    }
    if (!has_velocity) {
      const std::size_t n = samples.size();
      for (std::size_t k = 0; k < n; ++k) {
        const std::size_t a = k == 0 ? 0 : k - 1, b = k + 1 == n ? k : k + 1;
        samples[k].velocity = (samples[b].position - samples[a].position) / (samples[b].time - samples[a].time);
      }
    }
    SpatialPrescribedMotion m;
    m.samples_ = std::move(samples);
    return m;
  }

  const std::vector<SpatialSample>& samples() const { return samples_; }  // empty for the ln cosh law
  double first_time() const { return law_ ? -INFINITY : samples_.front().time; }
  double last_time() const { return law_ ? INFINITY : samples_.back().time; }

  SpatialState at(double t) const {
    SpatialState s;
    if (law_) {
      s.position = start_ + law_->distance(t) * direction_;
      s.velocity = law_->speed(t) * direction_;
      return s;
    }
    const std::size_t k = segment_holding(samples_, t);
    const SpatialSample &a = samples_[k], &b = samples_[k + 1];
    const double h = b.time - a.time, u = (t - a.time) / h;
    const auto [h00, h10, h01, h11, d00, d10, d01, d11] = HermiteBasis(u);
    s.position = h00 * a.position + (h10 * h) * a.velocity + h01 * b.position + (h11 * h) * b.velocity;
    s.velocity = (d00 / h) * a.position + d10 * a.velocity + (d01 / h) * b.position + d11 * b.velocity;
    // q(u) = q_a r(u), r(u) the turn by u theta about the axis n of q_a^-1 q_b (in a's frame): the world angular
    // velocity is R_a n theta / h.
    Quat to_b = a.orientation.conjugate() * b.orientation;
    if (to_b.w() < 0.0) to_b.coeffs() *= -1.0;  // q and -q are one rotation: take the turn of at most pi
    const Eigen::AngleAxisd turn(to_b);
    s.orientation = a.orientation * Quat(Eigen::AngleAxisd(u * turn.angle(), turn.axis()));
    s.angular_velocity = a.orientation * (turn.axis() * (turn.angle() / h));
    return s;
  }

 private:
  std::vector<SpatialSample> samples_;
  std::optional<LnCoshLaw> law_;
  Vec3 start_ = Vec3::Zero(), direction_ = Vec3::UnitX();
};

}  // namespace slide::rigid
