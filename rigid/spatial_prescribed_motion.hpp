#pragma once
// Prescribed motion of a solid body (3-D scenes): the ln cosh law along a direction, the body not turning (the Enet &
// Grilli slide on its rail). Its velocity is the exact time derivative of the same position, so the boundary
// particles move consistently. (2-D: rigid/prescribed_motion.hpp, which also reads time series.)
#include "rigid/ln_cosh_law.hpp"
#include "rigid/rigid_world.hpp"

namespace slide::rigid {

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

  SpatialState at(double t) const {
    SpatialState s;
    s.position = start_ + law_.distance(t) * direction_;
    s.velocity = law_.speed(t) * direction_;
    return s;
  }

 private:
  Vec3 start_ = Vec3::Zero(), direction_ = Vec3::UnitX();
  LnCoshLaw law_;
};

}  // namespace slide::rigid
