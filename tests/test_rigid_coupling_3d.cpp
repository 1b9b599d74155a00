// coupling/rigid_bodies in 3-D: boundary-particle kinematics from a solid body's pose, and Newton's third law between
// the fluid and a body in six degrees of freedom.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/rigid_bodies.hpp"
#include "tests/solid_box.hpp"
#include "tests/cli_helpers.hpp"
#include "tests/scene_runner.hpp"

namespace slide::testing {
namespace {

// Spin about a principal axis (z) and drift: every particle at X + R(w t) r0 with velocity V + w x r and acceleration
// w x (w x r), its normal turned with it.
TEST(RigidCoupling3D, BodyParticlesFollowThePoseAfterManySteps) {
  RigidBodies<3> bodies(Vec<3>::Zero(), 1e-3);
  const Vec<3> centre(0.4, 0.3, 0.2);
  const int b = bodies.add("box", solid_box(centre, Vec<3>(0.3, 0.2, 0.1), 500.0), BodyMotion{}, 500.0);
  Particles<3> P;
  std::vector<Vec<3>> start;
  for (int k = 0; k < 50; ++k) {
    const Vec<3> x = centre + 0.01 * Vec<3>(std::cos(0.7 * k) * (1 + k % 5), std::sin(1.3 * k) * (1 + k % 3),
                                            std::cos(2.1 * k) * (1 + k % 4));
    const std::size_t i = P.add(x, Kind::wall, 0, 500.0, 0.0);
    P.attach_to_body(i, b, x - centre, Vec<3>(1.0, 0.0, 0.0));
    start.push_back(x);
  }
  const Vec<3> v(0.3, -0.2, 0.1), w(0.0, 0.0, 3.0);
  const double dt = 2e-4;
  bodies.world.set_velocity(b, rigid::Vec3(v), rigid::Vec3(w));
  const int steps = 10000;
  for (int k = 0; k < steps; ++k) {
    bodies.advance((k + 1) * dt, dt);
    bodies.place_particles(P, (k + 1) * dt);
  }
  const double t = steps * dt;
  const Mat<3> R = Eigen::AngleAxisd(w[2] * t, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const Vec<3> X = centre + t * v;
  double worst = 0.0, worst_v = 0.0, worst_a = 0.0, worst_n = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Vec<3> r = R * (start[i] - centre);
    worst = std::max(worst, (P.position[i] - (X + r)).norm());
    worst_v = std::max(worst_v, (P.velocity[i] - (v + w.cross(r))).norm());
    worst_a = std::max(worst_a, (P.acceleration[i] - w.cross(Vec<3>(w.cross(r)))).norm());
    worst_n = std::max(worst_n, (P.wall_normal[i] - R * Vec<3>(1.0, 0.0, 0.0)).norm());
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(worst_v, 1e-9);
  EXPECT_LT(worst_a, 1e-8);
  EXPECT_LT(worst_n, 1e-9);
}

// Water around a free box, no gravity and no walls: the box is pushed through the water, spinning, and the total
// linear momentum of water and box stays what it was to round-off, step after step.
TEST(RigidCoupling3D, FluidAndBodyConserveMomentumTogether) {
  const auto dir = fresh_directory("momentum_3d");
  write_file(dir / "s.yaml", R"(dimension: 3
particle_spacing: 0.02
lattice: square
end_time: 1
gravity: [0, 0, 0]
method: {sound_speed: 10, initial_state: lattice}
fluid:
  phases: [{name: water, rheology: {viscosity: 0.01}}]
  regions: [{type: box, min: [0, 0, 0], max: [0.3, 0.3, 0.3]}]
bodies:
  - name: block
    shape: {type: box, center: [0.15, 0.15, 0.15], size: [0.1, 0.08, 0.06]}
    density: 800
)");
  auto scene = cases::build_scene<3>(cases::load_scene(dir / "s.yaml", {}), "s");
  auto& sim = *scene->simulation;
  ASSERT_TRUE(sim.bodies());
  auto& bodies = *sim.bodies();
  bodies.world.set_velocity(0, rigid::Vec3(0.5, 0.2, -0.1), rigid::Vec3(0.5, -1.0, 2.0));
  const double volume = std::pow(sim.options.dp, 3);
  auto momentum = [&]() {
    double m[3] = {0.0, 0.0, 0.0};
    const auto& P = sim.particles();
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.kind[i] == Kind::fluid)
        for (int k = 0; k < 3; ++k) m[k] += P.density[i] * volume * P.velocity[i][k];
    const auto s = bodies.state(0);
    return Vec<3>(Vec<3>(m[0], m[1], m[2]) + bodies.world.mass(0) * s.velocity);
  };
  const Vec<3> m0 = momentum();
  const double scale = m0.norm();
  double worst = 0.0, body_force = 0.0, body_torque = 0.0;
  for (int k = 0; k < 200; ++k) {
    auto [dt, limit] = sim.allowed_time_step();
    ASSERT_FALSE(sim.step(dt, limit).has_value());
    worst = std::max(worst, (momentum() - m0).norm() / scale);
    body_force = std::max(body_force, bodies.force[0].total().norm());
    body_torque = std::max(body_torque, bodies.force[0].total_torque().norm());
  }
  // The exchange is real (the water decelerates the box and its spin) and exactly shared.
  EXPECT_GT(body_force, 1.0);
  EXPECT_GT(body_torque, 0.01);
  EXPECT_LT(bodies.state(0).velocity[0], 0.49);
  EXPECT_LT(worst, 1e-12);
}


// A prescribed box (motion: prescribed, the ln cosh law along a slanted direction) moves through water by its law to
// round-off, whatever the water pushes (the push is reported, not applied): pose, velocity and every boundary
// particle's position and velocity, from a scene built as a user writes it.
TEST(RigidCoupling3D, PrescribedBodyFollowsTheLnCoshLawThroughWater) {
  const auto dir = fresh_directory("prescribed_3d");
  write_file(dir / "s.yaml", R"(dimension: 3
particle_spacing: 0.02
lattice: square
end_time: 1
gravity: [0, 0, -9.81]
method: {sound_speed: 10, initial_state: lattice}
fluid:
  phases: [{name: water, rheology: {viscosity: 0.01}}]
  regions: [{type: box, min: [0, 0, 0], max: [0.3, 0.3, 0.3]}]
bodies:
  - name: slide
    shape: {type: box, center: [0.15, 0.15, 0.15], size: [0.1, 0.08, 0.06], angles: [0, 15, 0]}
    density: 2000
    motion: prescribed
    prescribed: {type: ln_cosh, direction: [0.9659258, 0, -0.2588190], s0: 0.5, t0: 0.2, start_time: 0.004}
)");
  auto scene = cases::build_scene<3>(cases::load_scene(dir / "s.yaml", {}), "s");
  auto& sim = *scene->simulation;
  ASSERT_TRUE(sim.bodies());
  auto& bodies = *sim.bodies();
  const Vec<3> centre(0.15, 0.15, 0.15), d = Vec<3>(0.9659258, 0.0, -0.2588190).normalized();
  const auto& P0 = sim.particles();
  std::vector<std::pair<std::size_t, Vec<3>>> start;  // body particles and where they began
  for (std::size_t i = 0; i < P0.real_count(); ++i)
    if (P0.body_of(i) == 0) start.emplace_back(P0.id[i], P0.position[i]);
  ASSERT_EQ(start.size(), 60u);  // 5 x 4 x 3 grid points, all within the 3 layers
  double t = 0.0, largest_force = 0.0;
  for (int k = 0; k < 150; ++k) {
    auto [dt, limit] = sim.allowed_time_step();
    ASSERT_FALSE(sim.step(dt, limit).has_value());
    t += dt;
    largest_force = std::max(largest_force, bodies.force[0].total().norm());
  }
  const rigid::LnCoshLaw law(0.5, 0.2, 0.004);
  const auto s = bodies.state(0);
  EXPECT_NEAR((s.position - (centre + law.distance(sim.time()) * d)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((s.velocity - law.speed(sim.time()) * d).norm(), 0.0, 1e-12);
  EXPECT_NEAR(s.angular_velocity.norm(), 0.0, 1e-15);
  EXPECT_GT(law.distance(sim.time()), 0.005);  // it has moved a quarter of a spacing at least
  const auto& P = sim.particles();
  for (const auto& [id, x0] : start) {
    std::size_t i = 0;
    while (P.id[i] != id) ++i;
    ASSERT_NEAR((P.position[i] - (x0 + law.distance(sim.time()) * d)).norm(), 0.0, 1e-12);
    ASSERT_NEAR((P.velocity[i] - law.speed(sim.time()) * d).norm(), 0.0, 1e-12);
  }
  EXPECT_GT(largest_force, 1.0);  // the water's push (and its weight's buoyancy) is felt and reported
}

// A prescribed series of poses (prescribed: {type: series}), written as bodies.csv states them: the box (placed
// pitched 15 degrees) turns about the world's z at 2 rad/s while its centre moves on a parabola. Spherical
// interpolation of a turn about a fixed axis at a constant rate is that turn, and cubic Hermite with the series'
// velocities is the parabola, so pose, velocity and every boundary particle follow the closed form to round-off
// between the rows too.
TEST(RigidCoupling3D, PrescribedSeriesTurnsABodyThroughWaterAsItsRowsSay) {
  const auto dir = fresh_directory("prescribed_series_3d");
  const double omega = 2.0;
  const Vec<3> centre(0.15, 0.15, 0.15);
  const rigid::Quat placed(Eigen::AngleAxisd(15.0 * M_PI / 180.0, Eigen::Vector3d::UnitY()));
  const auto path = [&](double t) { return Vec<3>(centre + Vec<3>(0.1 * t, 0.0, -0.5 * t * t)); };
  const auto turn = [&](double t) { return rigid::Quat(Eigen::AngleAxisd(omega * t, Eigen::Vector3d::UnitZ())); };
  std::string csv = "time,body,x,y,z,qw,qx,qy,qz,vx,vy,vz\n";
  for (int k = 0; k <= 10; ++k) {
    const double t = 0.01 * k;
    const Vec<3> x = path(t);
    const rigid::Quat q(turn(t) * placed);
    csv += fmt::format("{},box,{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},0,{:.17g}\n", t, x[0],
                       x[1], x[2], q.w(), q.x(), q.y(), q.z(), 0.1, -t);
  }
  write_file(dir / "poses.csv", csv);
  write_file(dir / "s.yaml", R"(dimension: 3
particle_spacing: 0.02
lattice: square
end_time: 0.1
method: {sound_speed: 10, initial_state: lattice}
fluid:
  phases: [{name: water, rheology: {viscosity: 0.01}}]
  regions: [{type: box, min: [0, 0, 0], max: [0.3, 0.3, 0.3]}]
bodies:
  - name: box
    shape: {type: box, center: [0.15, 0.15, 0.15], size: [0.1, 0.08, 0.06], angles: [0, 15, 0]}
    density: 2000
    motion: prescribed
    prescribed: {type: series, file: poses.csv}
)");
  auto scene = cases::build_scene<3>(cases::load_scene(dir / "s.yaml", {}), "s", dir);
  auto& sim = *scene->simulation;
  auto& bodies = *sim.bodies();
  std::vector<std::pair<std::size_t, Vec<3>>> start;
  for (std::size_t i = 0; i < sim.particles().real_count(); ++i)
    if (sim.particles().body_of(i) == 0) start.emplace_back(sim.particles().id[i], sim.particles().position[i]);
  ASSERT_EQ(start.size(), 60u);
  while (sim.time() < 0.037) {
    auto [dt, limit] = sim.allowed_time_step();
    ASSERT_FALSE(sim.step(dt, limit).has_value());
  }
  const double t = sim.time();
  const auto s = bodies.state(0);
  EXPECT_NEAR((Vec<3>(s.position) - path(t)).norm(), 0.0, 1e-13);
  EXPECT_NEAR((Vec<3>(s.velocity) - Vec<3>(0.1, 0.0, -t)).norm(), 0.0, 1e-13);
  EXPECT_NEAR((Vec<3>(s.angular_velocity) - Vec<3>(0.0, 0.0, omega)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(bodies.absolute_orientation(0).angularDistance(rigid::Quat(turn(t) * placed)), 0.0, 1e-12);
  const auto& P = sim.particles();
  for (const auto& [id, x0] : start) {
    std::size_t i = 0;
    while (P.id[i] != id) ++i;
    const Vec<3> r = turn(t) * rigid::Vec3(x0 - centre);
    ASSERT_NEAR((P.position[i] - (path(t) + r)).norm(), 0.0, 1e-12);
    ASSERT_NEAR((P.velocity[i] - (Vec<3>(0.1, 0.0, -t) + Vec<3>(0.0, 0.0, omega).cross(r))).norm(), 0.0, 1e-11);
  }
  // A series that does not start where the body is put is refused naming the key.
  write_file(dir / "late.csv", "time,x,y,z,qw,qx,qy,qz\n0,0.16,0.15,0.15,1,0,0,0\n1,0.16,0.15,0.15,1,0,0,0\n");
  std::string late = read_file(dir / "s.yaml");
  late.replace(late.find("poses.csv"), 9, "late.csv");
  write_file(dir / "late.yaml", late);
  try {
    cases::build_scene<3>(cases::load_scene(dir / "late.yaml", {}), "s", dir);
    ADD_FAILURE() << "a series starting elsewhere was accepted";
  } catch (const cases::SceneError& e) {
    EXPECT_EQ(e.key_path, "bodies[0].prescribed.file");
    EXPECT_NE(std::string(e.what()).find("starts at (0.16, 0.15, 0.15)"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace slide::testing
