// coupling/rigid_bodies: boundary-particle kinematics from the Bullet pose, and Newton's third law between the
// fluid and a body.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/rigid_bodies.hpp"
#include "tests/cli_helpers.hpp"
#include "tests/scene_runner.hpp"

namespace slide::testing {
namespace {

TEST(RigidCoupling, BodyParticlesFollowThePoseAfterManySteps) {
  RigidBodies<2> bodies(Vec<2>::Zero(), 1e-3);
  rigid::BodySpec spec;
  spec.outline = {rigid::Vec2(0.2, 0.1), rigid::Vec2(0.6, 0.1), rigid::Vec2(0.2, 0.4)};
  spec.mass = 30.0;
  spec.inertia = 0.4;
  const int b = bodies.add("wedge", spec, BodyMotion{}, 500.0);
  const Vec<2> centre(1.0 / 3.0, 0.2);  // centroid of the triangle
  Particles<2> P;
  std::vector<Vec<2>> start;
  for (int k = 0; k < 50; ++k) {
    const Vec<2> x = centre + Vec<2>(0.01 * std::cos(0.7 * k) * (1 + k % 5), 0.01 * std::sin(1.3 * k) * (1 + k % 3));
    const std::size_t i = P.add(x, Kind::wall, 0, 500.0, 0.0);
    P.attach_to_body(i, b, x - centre, Vec<2>(1.0, 0.0));
    start.push_back(x);
  }
  const Vec<2> v(0.3, -0.2);
  const double omega = 3.0, dt = 2e-4;
  bodies.world.set_velocity(b, rigid::Vec2(v[0], v[1]), omega);
  const int steps = 10000;
  for (int k = 0; k < steps; ++k) {
    bodies.advance((k + 1) * dt, dt);
    bodies.place_particles(P, (k + 1) * dt);
  }
  // Closed form: X = X0 + V t, R = rotation by omega t; every particle at X + R (x0 - X0), its velocity V + w x r.
  const double t = steps * dt, c = std::cos(omega * t), s = std::sin(omega * t);
  const Vec<2> X = centre + t * v;
  double worst = 0.0, worst_v = 0.0, worst_a = 0.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Vec<2> r0 = start[i] - centre;
    const Vec<2> r(c * r0[0] - s * r0[1], s * r0[0] + c * r0[1]);
    worst = std::max(worst, (P.position[i] - (X + r)).norm());
    worst_v = std::max(worst_v, (P.velocity[i] - (v + omega * Vec<2>(-r[1], r[0]))).norm());
    // Uniform spin: only the centripetal acceleration -omega^2 r.
    worst_a = std::max(worst_a, (P.acceleration[i] + (omega * omega) * r).norm());
    EXPECT_NEAR((P.wall_normal[i] - Vec<2>(c, s)).norm(), 0.0, 1e-9);
  }
  EXPECT_LT(worst, 1e-9);
  EXPECT_LT(worst_v, 1e-9);
  EXPECT_LT(worst_a, 1e-9);
}

// A falling, spun-up body: its particles carry the rigid acceleration g + alpha x r - omega^2 r, here with alpha = 0.
TEST(RigidCoupling, BodyParticlesCarryTheRigidAcceleration) {
  const Vec<2> g(0.0, -9.81);
  RigidBodies<2> bodies(g, 1e-3);
  rigid::BodySpec spec;
  spec.outline = {rigid::Vec2(0.0, 0.0), rigid::Vec2(0.2, 0.0), rigid::Vec2(0.2, 0.1), rigid::Vec2(0.0, 0.1)};
  spec.mass = 10.0;
  spec.inertia = 10.0 * (0.04 + 0.01) / 12.0;
  const int b = bodies.add("box", spec, BodyMotion{}, 500.0);
  Particles<2> P;
  for (const Vec<2>& x : {Vec<2>(0.0, 0.0), Vec<2>(0.2, 0.1), Vec<2>(0.05, 0.1)}) {
    const std::size_t i = P.add(x, Kind::wall, 0, 500.0, 0.0);
    P.attach_to_body(i, b, x - Vec<2>(0.1, 0.05), Vec<2>(1.0, 0.0));
  }
  const double omega = 2.0, dt = 1e-4;
  bodies.world.set_velocity(b, rigid::Vec2(0.0, 0.0), omega);
  bodies.place_particles(P, 0.0);
  // Nothing to difference at the first placement: only the centripetal part.
  for (std::size_t i = 0; i < P.size(); ++i)
    EXPECT_LT((P.acceleration[i] + (omega * omega) * (P.position[i] - Vec<2>(0.1, 0.05))).norm(), 1e-12);
  for (int k = 1; k <= 100; ++k) {
    bodies.advance(k * dt, dt);
    bodies.place_particles(P, k * dt);
  }
  const auto st = bodies.state(b);
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Vec<2> r = P.position[i] - Vec<2>(st.position[0], st.position[1]);
    EXPECT_LT((P.acceleration[i] - (g - (omega * omega) * r)).norm(), 1e-8) << i;
  }
}

// A block held above a slab of water, no gravity: for the time-step limits of moving bodies.
std::unique_ptr<cases::Scene<2>> block_above_still_water(const std::string& name) {
  const auto dir = fresh_directory(name);
  write_file(dir / "s.yaml", R"(particle_spacing: 0.01
end_time: 1
gravity: [0, 0]
method: {sound_speed: 10, initial_state: lattice}
fluid:
  phases: [{name: water}]
  regions: [{type: rectangle, min: [0, 0], max: [0.4, 0.1]}]
bodies:
  - name: block
    shape: {type: box, center: [0.2, 0.2], size: [0.1, 0.05]}
    density: 800
)");
  return cases::build_scene<2>(cases::load_scene(dir / "s.yaml", {}), "s");
}

// A body faster than sound in the water still limits the time step: the CFL limit counts boundary particles' speeds.
TEST(RigidCoupling, MovingBodyEntersTheCflLimit) {
  auto scene = block_above_still_water("cfl_body");
  auto& sim = *scene->simulation;
  const double at_rest = sim.allowed_time_step().first;
  const double speed = 40.0;
  sim.bodies()->world.set_velocity(0, rigid::Vec2(speed, 0.0), 0.0);
  sim.bodies()->place_particles(sim.particles(), sim.time());
  const auto [dt, limit] = sim.allowed_time_step();
  EXPECT_EQ(limit, TimeStepLimit::cfl);
  EXPECT_NEAR(dt, sim.options.cfl * sim.options.dp / (sim.options.sound_speed + speed), 1e-12);
  EXPECT_LT(dt, 0.5 * at_rest);
}

// A body decelerating hard limits the time step through the force limit: its particles' rigid acceleration counts.
TEST(RigidCoupling, AcceleratingBodyEntersTheForceLimit) {
  auto scene = block_above_still_water("force_body");
  auto& sim = *scene->simulation;
  EXPECT_NE(sim.allowed_time_step().second, TimeStepLimit::force);  // at rest, no gravity: no acceleration at all
  // 2 m/s lost in 1e-5 s: 2e5 m/s^2, whose force limit 0.25 sqrt(dp / a) = 5.6e-5 s is below the CFL limit.
  const double dv = 2.0, interval = 1e-5;
  sim.bodies()->world.set_velocity(0, rigid::Vec2(dv, 0.0), 0.0);
  sim.bodies()->place_particles(sim.particles(), 0.0);
  sim.bodies()->world.set_velocity(0, rigid::Vec2(0.0, 0.0), 0.0);
  sim.bodies()->place_particles(sim.particles(), interval);
  const auto [dt, limit] = sim.allowed_time_step();
  EXPECT_EQ(limit, TimeStepLimit::force);
  EXPECT_NEAR(dt, sim.options.force_number * std::sqrt(sim.options.dp / (dv / interval)), 1e-9 * dt);
}

// Water around a free body, no gravity and no walls: the body is pushed through the water, and the total momentum
// of water and body stays what it was to round-off, step after step.
void expect_momentum_conserved(const std::string& name, ViscousScheme scheme, const std::vector<Phase>& phases) {
  const auto dir = fresh_directory(name);
  write_file(dir / "s.yaml", R"(particle_spacing: 0.01
end_time: 1
gravity: [0, 0]
method: {sound_speed: 10, initial_state: lattice}
fluid:
  phases: [{name: water, rheology: {viscosity: 0.01}}]
  regions:
    - {type: rectangle, min: [0, 0], max: [0.4, 0.1]}
    - {type: rectangle, min: [0, 0.2], max: [0.4, 0.3]}
    - {type: rectangle, min: [0, 0.1], max: [0.1, 0.2]}
    - {type: rectangle, min: [0.3, 0.1], max: [0.4, 0.2]}
bodies:
  - name: block
    shape: {type: box, center: [0.2, 0.15], size: [0.19, 0.09]}
    density: 800
)");
  auto scene = cases::build_scene<2>(cases::load_scene(dir / "s.yaml", {}), "s");
  auto& sim = *scene->simulation;
  ASSERT_TRUE(sim.bodies());
  sim.options.viscous_scheme = scheme;
  if (!phases.empty()) {
    sim.phases = phases;
    sim.initialise();
  }
  auto& bodies = *sim.bodies();
  bodies.world.set_velocity(0, rigid::Vec2(0.5, 0.2), 1.0);
  const double volume = sim.options.dp * sim.options.dp;
  auto momentum = [&]() {
    // Two scalars rather than a Vec<2> sum: GCC 12 warns (falsely) of an uninitialised vector register otherwise.
    double mx = 0.0, my = 0.0;
    const auto& P = sim.particles();
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.kind[i] == Kind::fluid) {
        mx += P.density[i] * volume * P.velocity[i][0];
        my += P.density[i] * volume * P.velocity[i][1];
      }
    const auto s = bodies.state(0);
    return Vec<2>(mx + bodies.world.mass(0) * s.velocity[0], my + bodies.world.mass(0) * s.velocity[1]);
  };
  const Vec<2> m0 = momentum();
  const double scale = m0.norm();
  double worst = 0.0, body_force = 0.0;
  for (int k = 0; k < 300; ++k) {
    auto [dt, limit] = sim.allowed_time_step();
    ASSERT_FALSE(sim.step(dt, limit).has_value());
    worst = std::max(worst, (momentum() - m0).norm() / scale);
    body_force = std::max(body_force, bodies.force[0].total().norm());
  }
  // The exchange is real (the water decelerates the body) and exactly shared.
  EXPECT_GT(body_force, 1.0);
  EXPECT_LT(bodies.state(0).velocity[0], 0.49);
  EXPECT_LT(worst, 1e-12);
  if (scheme == ViscousScheme::implicit) {
    EXPECT_EQ(sim.viscous_solves().solves, 300);
    EXPECT_EQ(sim.viscous_solves().unconverged, 0);
    EXPECT_EQ(sim.limit_counts()[int(TimeStepLimit::viscous)], 0);
    double most = 0.0;
    for (std::size_t i = 0; i < sim.particles().size(); ++i)
      if (sim.particles().kind[i] == Kind::fluid) most = std::max(most, sim.particles().viscosity[i]);
    EXPECT_GT(most, 100.0);  // the rheology set it (the scene made the particles with 0.01 Pa s)
  }
}

TEST(RigidCoupling, FluidAndBodyConserveMomentumTogether) {
  expect_momentum_conserved("momentum", ViscousScheme::explicit_, {});
}

// The same with the semi-implicit viscous stage and a Herschel-Bulkley sediment around the body (viscosity from the
// shear rate each step, up to 1e3 Pa s where it is at rest, where the explicit viscous limit would allow 1e-5 s
// against the CFL step's 2e-4 s).
TEST(RigidCoupling, BodyInSedimentConservesMomentumWithTheImplicitViscousStep) {
  const HerschelBulkley sediment{50.0, 2.0, 0.5, BiViscosity{1e3}, 1e3};
  expect_momentum_conserved("momentum_implicit", ViscousScheme::implicit, {Phase{"water", 1000.0, sediment}});
}

}  // namespace
}  // namespace slide::testing
