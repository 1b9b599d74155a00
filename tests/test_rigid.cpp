// rigid/: the Bullet world without fluid, against closed forms.
#include <btBulletDynamicsCommon.h>
#include <gtest/gtest.h>

#include <cmath>

#include "rigid/polygon.hpp"
#include "rigid/prescribed_motion.hpp"
#include "rigid/rigid_world.hpp"
#include "rigid/spatial_prescribed_motion.hpp"

namespace slide::rigid {
namespace {

std::vector<Vec2> box(const Vec2& c, double w, double h) {
  return {c + Vec2(-w / 2, -h / 2), c + Vec2(w / 2, -h / 2), c + Vec2(w / 2, h / 2), c + Vec2(-w / 2, h / 2)};
}

BodySpec box_body(const Vec2& c, double w, double h, double density, double friction = 0.0) {
  BodySpec s;
  s.outline = box(c, w, h);
  s.mass = density * w * h;
  s.inertia = s.mass * (w * w + h * h) / 12.0;
  s.friction = friction;
  return s;
}

TEST(Rigid, BulletIsDoublePrecision) {
  EXPECT_EQ(sizeof(btScalar), 8u);
  EXPECT_EQ(bullet_scalar_size(), 8u);
}

TEST(Rigid, PolygonPropertiesMatchClosedForms) {
  const auto b = box(Vec2(1.0, 2.0), 0.4, 0.2);
  EXPECT_NEAR(signed_area(b), 0.08, 1e-15);
  EXPECT_NEAR((centroid(b) - Vec2(1.0, 2.0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR(polar_moment_about_centroid(b), 0.08 * (0.16 + 0.04) / 12.0, 1e-15);
  // Right triangle with legs a, b at the origin: centroid (a/3, b/3), J_c = A (a^2 + b^2) / 18.
  const std::vector<Vec2> t{Vec2(0, 0), Vec2(0.5, 0), Vec2(0, 0.3)};
  EXPECT_NEAR(signed_area(t), 0.075, 1e-15);
  EXPECT_NEAR((centroid(t) - Vec2(0.5 / 3, 0.1)).norm(), 0.0, 1e-15);
  EXPECT_NEAR(polar_moment_about_centroid(t), 0.075 * (0.25 + 0.09) / 18.0, 1e-15);
  // Clockwise input is turned around; the inset of a box is the smaller box.
  EXPECT_TRUE(is_convex_ccw(counter_clockwise({t[0], t[2], t[1]})));
  const auto in = inset(b, 0.01);
  EXPECT_NEAR(signed_area(in), 0.38 * 0.18, 1e-14);
}

TEST(Rigid, FreeFlightKeepsVelocityAndSpin) {
  RigidWorld w(Vec2(0.0, 0.0), 1e-3);
  const int b = w.add_body(box_body(Vec2(0.0, 0.0), 0.2, 0.1, 800.0));
  w.set_velocity(b, Vec2(1.5, -0.5), 2.0);
  const double dt = 1e-3;
  const int steps = 2000;
  for (int k = 0; k < steps; ++k) w.step(dt);
  const PlanarState s = w.state(b);
  const double t = steps * dt;
  EXPECT_NEAR(s.position[0], 1.5 * t, 1e-9 * 1.5 * t);
  EXPECT_NEAR(s.position[1], -0.5 * t, 1e-9 * 0.5 * t);
  EXPECT_NEAR(s.angle, 2.0 * t, 1e-9 * 2.0 * t);
  EXPECT_NEAR(s.velocity[0], 1.5, 1e-12);
  EXPECT_NEAR(s.angular_velocity, 2.0, 1e-12);
}

TEST(Rigid, FreeFallFollowsSemiImplicitEulerAndClosedForm) {
  const double g = 9.81, dt = 1e-3;
  RigidWorld w(Vec2(0.0, -g), 1e-3);
  const int b = w.add_body(box_body(Vec2(0.0, 10.0), 0.2, 0.1, 800.0));
  const int n = 1000;
  for (int k = 0; k < n; ++k) w.step(dt);
  const double y = w.state(b).position[1];
  // Bullet: v += g dt, then x += v dt, so y_n = y0 - g dt^2 n (n + 1) / 2 exactly; the closed form is y0 - g t^2/2.
  EXPECT_NEAR(y, 10.0 - g * dt * dt * n * (n + 1) / 2.0, 1e-10);
  const double t = n * dt;
  EXPECT_NEAR(y, 10.0 - 0.5 * g * t * t, 0.5 * g * t * dt + 1e-10);
  EXPECT_NEAR(w.state(b).velocity[1], -g * t, 1e-10);
  EXPECT_NEAR(w.contact_force(b).norm(), 0.0, 1e-9);
}

// A 0.2 x 0.1 box resting on a slope of angle theta, Coulomb coefficient mu (the slope has friction 1, so
// Bullet's product rule gives mu). Returns the distance slid along the slope after time t.
double slide_on_slope(double theta, double mu, double t, double* velocity = nullptr, Vec2* contact = nullptr) {
  const double g = 9.81, dt = 5e-4, w_box = 0.2, h_box = 0.1;
  RigidWorld w(Vec2(0.0, -g), 5e-4);
  const Vec2 down(std::cos(theta), -std::sin(theta));  // along the slope, downwards to +x
  const Vec2 normal(std::sin(theta), std::cos(theta));  // out of the slope
  w.add_static_segment(Vec2(-5.0 * std::cos(theta), 5.0 * std::sin(theta)), Vec2(5.0 * std::cos(theta), -5.0 * std::sin(theta)),
                       -normal, 0.5, 1.0, 0.0);
  BodySpec s = box_body(Vec2::Zero(), w_box, h_box, 1000.0, mu);
  // Rotate the box onto the slope, resting on it.
  const Vec2 c = (0.5 * h_box) * normal;
  for (auto& v : s.outline) v = c + v[0] * down + v[1] * normal;
  const int b = w.add_body(s);
  const Vec2 x0 = w.state(b).position;
  const int n = static_cast<int>(std::lround(t / dt));
  Vec2 contact_sum = Vec2::Zero();  // per-step contact forces jitter; their mean over the second half is compared
  for (int k = 0; k < n; ++k) {
    w.step(dt);
    if (2 * k >= n) contact_sum += w.contact_force(b);
  }
  const PlanarState st = w.state(b);
  if (velocity) *velocity = st.velocity.dot(down);
  if (contact) *contact = contact_sum / (n - (n + 1) / 2);
  return (st.position - x0).dot(down);
}

TEST(Rigid, BlockSlidesDownSlopeWithCoulombFriction) {
  const double theta = M_PI / 4, mu = 0.3, g = 9.81, t = 0.5;
  double v = 0.0;
  Vec2 contact;
  const double s = slide_on_slope(theta, mu, t, &v, &contact);
  const double a = g * (std::sin(theta) - mu * std::cos(theta));
  EXPECT_NEAR(v, a * t, 0.01 * a * t);
  EXPECT_NEAR(s, 0.5 * a * t * t, 0.01 * 0.5 * a * t * t);
  // Contact force: normal m g cos theta out of the slope, friction mu times it up the slope.
  const double m = 1000.0 * 0.2 * 0.1;
  const Vec2 normal(std::sin(theta), std::cos(theta)), down(std::cos(theta), -std::sin(theta));
  EXPECT_NEAR(contact.dot(normal), m * g * std::cos(theta), 0.01 * m * g);
  EXPECT_NEAR(contact.dot(down), -mu * m * g * std::cos(theta), 0.01 * m * g);
}

TEST(Rigid, BlockStaysWhenFrictionExceedsSlope) {
  const double theta = M_PI / 4;
  const double s = slide_on_slope(theta, 1.2, 1.0);  // mu > tan(45 deg) = 1
  EXPECT_LT(std::abs(s), 1e-4);
}

TEST(Rigid, HeldBodyWaitsThenFalls) {
  RigidWorld w(Vec2(0.0, -9.81), 1e-3);
  const int b = w.add_body(box_body(Vec2(0.0, 1.0), 0.2, 0.1, 800.0));
  w.set_held(b, true);
  for (int k = 0; k < 100; ++k) w.step(1e-3);
  EXPECT_EQ(w.state(b).position[1], 1.0);
  EXPECT_EQ(w.state(b).velocity[1], 0.0);
  w.set_held(b, false);
  for (int k = 0; k < 100; ++k) w.step(1e-3);
  EXPECT_NEAR(w.state(b).velocity[1], -9.81 * 0.1, 1e-10);
}

TEST(Rigid, LockedComponentsStayPut) {
  RigidWorld w(Vec2(0.0, -9.81), 1e-3);
  BodySpec s = box_body(Vec2(0.0, 1.0), 0.2, 0.1, 800.0);
  s.locked = {false, true, false};
  const int b = w.add_body(s);
  w.apply_force(b, Vec2(1.6, 0.0), 0.5);
  w.step(1e-3);
  EXPECT_EQ(w.state(b).position[1], 1.0);
  EXPECT_NEAR(w.state(b).velocity[0], 1.6 / 16.0 * 1e-3, 1e-15);
  EXPECT_NEAR(w.state(b).angular_velocity, 0.5 / w.inertia(b) * 1e-3, 1e-12);
}

TEST(Rigid, PrescribedLawVelocityIsItsDerivative) {
  const auto m = PrescribedMotion::ln_cosh(Vec2(1.0, 2.0), 0.3, Vec2(1.0, -1.0), 0.8, 0.6, 0.1);
  for (double t : {0.05, 0.2, 0.5, 1.3}) {
    const double h = 1e-6;
    const Vec2 fd = (m.at(t + h).position - m.at(t - h).position) / (2 * h);
    EXPECT_NEAR((fd - m.at(t).velocity).norm(), 0.0, 1e-8) << t;
    EXPECT_EQ(m.at(t).angle, 0.3);
  }
  // The law itself: s = s0 ln cosh((t - begin) / t0) along the unit direction.
  const double s = 0.8 * std::log(std::cosh((1.0 - 0.1) / 0.6));
  EXPECT_NEAR((m.at(1.0).position - Vec2(1.0, 2.0) - s * Vec2(1.0, -1.0) / std::sqrt(2.0)).norm(), 0.0, 1e-14);
}

TEST(Rigid, PrescribedSeriesReproducesSamplesAndDifferentiates) {
  std::vector<MotionSample> samples;
  for (int k = 0; k <= 20; ++k) {
    MotionSample s;
    s.time = 0.05 * k;
    const double t = s.time;
    s.state.position = Vec2(t * t, std::sin(t));
    s.state.angle = 0.2 * t;
    s.state.velocity = Vec2(2 * t, std::cos(t));
    s.state.angular_velocity = 0.2;
    samples.push_back(s);
  }
  const auto m = PrescribedMotion::from_samples(samples, true);
  for (const auto& s : samples) {
    EXPECT_NEAR((m.at(s.time).position - s.state.position).norm(), 0.0, 1e-14);
    EXPECT_NEAR((m.at(s.time).velocity - s.state.velocity).norm(), 0.0, 1e-12);
  }
  for (double t : {0.013, 0.31, 0.777}) {
    const double h = 1e-6;
    const Vec2 fd = (m.at(t + h).position - m.at(t - h).position) / (2 * h);
    EXPECT_NEAR((fd - m.at(t).velocity).norm(), 0.0, 1e-7) << t;
    EXPECT_NEAR((m.at(t + h).angle - m.at(t - h).angle) / (2 * h), m.at(t).angular_velocity, 1e-7);
    // Cubic Hermite of a smooth law: close to the law between samples.
    EXPECT_NEAR(m.at(t).position[0], t * t, 1e-12);
  }
  EXPECT_THROW(m.at(1.5), std::out_of_range);
}

// A 3-D series of poses: between two orientations q_a and q_b = q_a Rz(60 deg) (q_a a quarter turn about x), 2 s
// apart, the orientation turns uniformly about q_a's z axis, the world's -y: half way it is q_a Rz(30 deg), the angular
// velocity (pi/3)/2 rad/s about -y throughout, the orientation's derivative; q_b given as -q_b (the same rotation)
// turns the same short way. Positions are cubic Hermite with the given velocities: a quadratic exactly.
TEST(Rigid, SpatialSeriesTurnsTheShortWayAtTheRateOfItsSamples) {
  const Quat qa(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitX()));
  const Quat qb(qa * Quat(Eigen::AngleAxisd(M_PI / 3, Eigen::Vector3d::UnitZ())));
  const auto sample = [](double t, const Quat& q) {
    SpatialSample s;
    s.time = t;
    s.position = Vec3(t * t, 1.0 - t, 0.5 * t * t);
    s.velocity = Vec3(2 * t, -1.0, t);
    s.orientation = q;
    return s;
  };
  for (const double sign : {1.0, -1.0}) {
    Quat b = qb;
    b.coeffs() *= sign;
    const auto m = SpatialPrescribedMotion::from_samples({sample(1.0, qa), sample(3.0, b)}, true);
    const SpatialState mid = m.at(2.0);
    const Quat expected(qa * Quat(Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d::UnitZ())));
    EXPECT_NEAR(mid.orientation.angularDistance(expected), 0.0, 1e-14) << sign;
    EXPECT_NEAR((mid.angular_velocity - Vec3(0.0, -M_PI / 6, 0.0)).norm(), 0.0, 1e-14) << sign;
    EXPECT_NEAR((mid.position - Vec3(4.0, -1.0, 2.0)).norm(), 0.0, 1e-14);
    EXPECT_NEAR((mid.velocity - Vec3(4.0, -1.0, 2.0)).norm(), 0.0, 1e-14);
    EXPECT_NEAR(m.at(3.0).orientation.angularDistance(qb), 0.0, 1e-14);
    // The angular velocity is the orientation's derivative: q(t + h) q(t)^-1 = exp(h w / 2).
    const double h = 1e-6;
    const Eigen::AngleAxisd step(Quat(m.at(1.7 + h).orientation * m.at(1.7).orientation.conjugate()));
    EXPECT_NEAR((step.axis() * step.angle() / h - m.at(1.7).angular_velocity).norm(), 0.0, 1e-8);
  }
  EXPECT_THROW(SpatialPrescribedMotion::from_samples({sample(1.0, qa)}, true), std::invalid_argument);
}

}  // namespace
}  // namespace slide::rigid
