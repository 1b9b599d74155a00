// A body on a rail (rigid/rail_motion.hpp, coupling/rigid_bodies.hpp: motion rail): its one degree of freedom under
// Coulomb friction, alone, in air against the closed form, and through water against the momentum it received.
#include <gtest/gtest.h>

#include <cmath>

#include "cases/scene.hpp"
#include "coupling/rigid_bodies.hpp"
#include "rigid/rail_motion.hpp"
#include "tests/cli_helpers.hpp"
#include "tests/solid_box.hpp"

namespace slide::testing {
namespace {

using rigid::rail_speed_after;

TEST(RailMotion, CoulombFrictionOnTheForceAcross) {
  // Frictionless: v + dt F / m.
  EXPECT_DOUBLE_EQ(rail_speed_after(1.0, 6.0, 100.0, 2.0, 0.0, 0.5), 2.5);
  // At rest, held while |F_along| <= mu |F_across| (0.3 x 20 = 6), either way along.
  EXPECT_EQ(rail_speed_after(0.0, 6.0, 20.0, 2.0, 0.3, 0.5), 0.0);
  EXPECT_EQ(rail_speed_after(0.0, -6.0, -20.0, 2.0, 0.3, 0.5), 0.0);
  // At rest, pushed harder: starts under F_along - mu |F_across| sign(F_along).
  EXPECT_DOUBLE_EQ(rail_speed_after(0.0, 10.0, 20.0, 2.0, 0.3, 0.5), 0.5 * 4.0 / 2.0);
  EXPECT_DOUBLE_EQ(rail_speed_after(0.0, -10.0, 20.0, 2.0, 0.3, 0.5), -0.5 * 4.0 / 2.0);
  // Moving: friction against the motion, whatever the force's sign.
  EXPECT_DOUBLE_EQ(rail_speed_after(3.0, -2.0, 20.0, 2.0, 0.3, 0.5), 3.0 + 0.5 * (-2.0 - 6.0) / 2.0);
  EXPECT_DOUBLE_EQ(rail_speed_after(-3.0, 2.0, 20.0, 2.0, 0.3, 0.5), -3.0 + 0.5 * (2.0 + 6.0) / 2.0);
  // Friction that holds the body stops it within the step (1 m/s, 8 N against it: at rest after 0.25 s of 0.5).
  EXPECT_EQ(rail_speed_after(1.0, -2.0, 20.0, 2.0, 0.3, 0.5), 0.0);
  // A force that beats friction turns it back: at rest after t* = 1 x 2 / (10 + 6) = 0.125 s, then
  // (0.5 - 0.125) (-10 + 6) / 2 = -0.75 m/s.
  EXPECT_DOUBLE_EQ(rail_speed_after(1.0, -10.0, 20.0, 2.0, 0.3, 0.5), -0.75);
  // Without friction, a reversal is v + dt F / m, as between any two instants.
  EXPECT_NEAR(rail_speed_after(1.0, -10.0, 20.0, 2.0, 0.0, 0.5), 1.0 - 0.5 * 10.0 / 2.0, 1e-15);
  EXPECT_NEAR(rail_speed_after(-0.3, 4.0, 20.0, 2.0, 0.0, 0.5), -0.3 + 0.5 * 4.0 / 2.0, 1e-15);
}

// A box on a rail down a 15 degree slope, in air, friction 0.2, held until 0.01 s: from rest it travels
// s_n = a dt^2 n (n + 1) / 2 after n steps (semi-implicit Euler, exact for a constant a), a = g (sin 15 - 0.2 cos 15)
// along the rail, and neither leaves it nor turns.
TEST(RailMotion, ABoxInAirSlidesDownItsRailAsTheClosedFormSays) {
  const double g = 9.81, theta = 15.0 * M_PI / 180.0, mu = 0.2, dt = 1e-3;
  RigidBodies<3> bodies(Vec<3>(0.0, 0.0, -g), 1e-3);
  rigid::SolidSpec spec = solid_box(rigid::Vec3(0.4, 0.3, 0.2), rigid::Vec3(0.3, 0.2, 0.1), 2000.0);
  spec.kinematic = true;
  BodyMotion motion;
  motion.mode = BodyMotion::Mode::rail;
  motion.rail = rigid::Rail{{std::cos(theta), 0.0, -std::sin(theta)}, mu};
  motion.release_time = 0.01;
  bodies.add("box", spec, motion, 2000.0);
  const Vec<3> d(std::cos(theta), 0.0, -std::sin(theta)), start(0.4, 0.3, 0.2);
  for (int k = 0; k < 10; ++k) bodies.advance((k + 1) * dt, dt);  // held: time_after <= 0.01
  EXPECT_EQ((Vec<3>(bodies.state(0).position) - start).norm(), 0.0);
  const int n = 500;
  for (int k = 10; k < 10 + n; ++k) bodies.advance((k + 1) * dt, dt);
  const double a = g * (std::sin(theta) - mu * std::cos(theta));
  const auto s = bodies.state(0);
  const double travel = a * dt * dt * n * (n + 1) / 2.0;
  EXPECT_NEAR((Vec<3>(s.position) - (start + travel * d)).norm(), 0.0, 1e-12 * travel);
  EXPECT_NEAR((Vec<3>(s.velocity) - a * n * dt * d).norm(), 0.0, 1e-12 * a * n * dt);
  EXPECT_EQ(s.angular_velocity.norm(), 0.0);
  EXPECT_EQ(rigid::Quat(s.orientation).angularDistance(rigid::Quat::Identity()), 0.0);
}

// The same in 2-D (the same key, mass and forces per unit width): a box 0.3 x 0.1 of 2000 kg/m^3 on a rail down a 15
// degree slope, friction 0.2, held until 0.01 s, travels the same s_n and keeps its angle.
TEST(RailMotion, ABoxInAirSlidesDownItsRailIn2DAsTheClosedFormSays) {
  const double g = 9.81, theta = 15.0 * M_PI / 180.0, mu = 0.2, dt = 1e-3;
  RigidBodies<2> bodies(Vec<2>(0.0, -g), 1e-3);
  rigid::BodySpec spec;
  spec.outline = {{0.25, 0.15}, {0.55, 0.15}, {0.55, 0.25}, {0.25, 0.25}};
  spec.mass = 2000.0 * 0.3 * 0.1;
  spec.inertia = spec.mass * (0.3 * 0.3 + 0.1 * 0.1) / 12.0;
  spec.kinematic = true;
  BodyMotion motion;
  motion.mode = BodyMotion::Mode::rail;
  motion.rail = rigid::Rail{{std::cos(theta), -std::sin(theta), 0.0}, mu};
  motion.release_time = 0.01;
  bodies.add("box", spec, motion, 2000.0);
  const Vec<2> d(std::cos(theta), -std::sin(theta)), start(0.4, 0.2);
  for (int k = 0; k < 10; ++k) bodies.advance((k + 1) * dt, dt);
  EXPECT_EQ((Vec<2>(bodies.state(0).position) - start).norm(), 0.0);
  const int n = 500;
  for (int k = 10; k < 10 + n; ++k) bodies.advance((k + 1) * dt, dt);
  const double a = g * (std::sin(theta) - mu * std::cos(theta));
  const auto s = bodies.state(0);
  const double travel = a * dt * dt * n * (n + 1) / 2.0;
  EXPECT_NEAR((Vec<2>(s.position) - (start + travel * d)).norm(), 0.0, 1e-12 * travel);
  EXPECT_NEAR((Vec<2>(s.velocity) - a * n * dt * d).norm(), 0.0, 1e-12 * a * n * dt);
  EXPECT_EQ(s.angular_velocity, 0.0);
  EXPECT_EQ(s.angle, 0.0);
}

// A box on a frictionless rail through water (the prescribed test's scene with motion: rail): whatever the water does,
// the box stays on its rail, unturned, and the momentum it has along the rail is exactly what gravity and the water
// gave it there, step by step: m v . d = sum over steps of dt (F_fluid + m g) . d.
TEST(RailMotion, ABoxThroughWaterGainsTheMomentumGravityAndTheWaterGiveAlongItsRail) {
  const auto dir = fresh_directory("rail_3d");
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
    motion: rail
    rail: {direction: [0.9659258, 0, -0.2588190]}
)");
  auto scene = cases::build_scene<3>(cases::load_scene(dir / "s.yaml", {}), "s");
  auto& sim = *scene->simulation;
  ASSERT_TRUE(sim.bodies());
  auto& bodies = *sim.bodies();
  const Vec<3> centre(0.15, 0.15, 0.15), d = Vec<3>(0.9659258, 0.0, -0.2588190).normalized();
  const double mass = bodies.world.mass(0);
  const auto& P0 = sim.particles();
  std::vector<std::pair<std::size_t, Vec<3>>> start;  // body particles and where they began
  for (std::size_t i = 0; i < P0.real_count(); ++i)
    if (P0.body_of(i) == 0) start.emplace_back(P0.id[i], P0.position[i]);
  ASSERT_FALSE(start.empty());
  double impulse = 0.0, largest_force = 0.0;
  for (int k = 0; k < 150; ++k) {
    auto [dt, limit] = sim.allowed_time_step();
    ASSERT_FALSE(sim.step(dt, limit).has_value());
    impulse += dt * (bodies.force[0].total() + mass * Vec<3>(0.0, 0.0, -9.81)).dot(d);
    largest_force = std::max(largest_force, bodies.force[0].total().norm());
  }
  const auto s = bodies.state(0);
  const Vec<3> moved = Vec<3>(s.position) - centre;
  EXPECT_GT(moved.dot(d), 0.001);  // it slid (a twentieth of a spacing at least)
  EXPECT_LT((moved - moved.dot(d) * d).norm(), 1e-15);
  EXPECT_NEAR(mass * Vec<3>(s.velocity).dot(d), impulse, 1e-12 * std::abs(impulse));
  EXPECT_LT((Vec<3>(s.velocity) - Vec<3>(s.velocity).dot(d) * d).norm(), 1e-15);
  EXPECT_EQ(s.angular_velocity.norm(), 0.0);
  EXPECT_GT(largest_force, 1.0);  // the water pushes back, and the box feels it
  const auto& P = sim.particles();  // its particles moved with it
  for (const auto& [id, x0] : start) {
    std::size_t i = 0;
    while (P.id[i] != id) ++i;
    ASSERT_NEAR((P.position[i] - (x0 + moved)).norm(), 0.0, 1e-12);
  }
}

// The 2-D box through water on its rail (a 2-D scene, the same keys): on the rail, unturned, its momentum along the
// rail (per unit width) what gravity and the water gave it there, and its particles moved with it.
TEST(RailMotion, ABoxThroughWaterIn2DGainsTheMomentumGravityAndTheWaterGiveAlongItsRail) {
  const auto dir = fresh_directory("rail_2d");
  write_file(dir / "s.yaml", R"(particle_spacing: 0.01
end_time: 1
method: {sound_speed: 10, initial_state: lattice}
fluid:
  phases: [{name: water, rheology: {viscosity: 0.01}}]
  regions: [{type: below_level, level: 0.3}]
walls:
  - points: [[0, 0.5], [0, 0], [0.4, 0], [0.4, 0.5]]
bodies:
  - name: slide
    shape: {type: box, center: [0.2, 0.15], size: [0.1, 0.06], angle: -15}
    density: 2000
    motion: rail
    rail: {direction: [0.9659258, -0.2588190]}
)");
  auto scene = cases::build_scene<2>(cases::load_scene(dir / "s.yaml", {}), "s");
  auto& sim = *scene->simulation;
  auto& bodies = *sim.bodies();
  const Vec<2> centre(0.2, 0.15), d = Vec<2>(0.9659258, -0.2588190).normalized();
  const double mass = bodies.world.mass(0);
  std::vector<std::pair<std::size_t, Vec<2>>> start;
  for (std::size_t i = 0; i < sim.particles().real_count(); ++i)
    if (sim.particles().body_of(i) == 0) start.emplace_back(sim.particles().id[i], sim.particles().position[i]);
  ASSERT_FALSE(start.empty());
  double impulse = 0.0;
  for (int k = 0; k < 150; ++k) {
    auto [dt, limit] = sim.allowed_time_step();
    ASSERT_FALSE(sim.step(dt, limit).has_value());
    impulse += dt * (bodies.force[0].total() + mass * Vec<2>(0.0, -9.81)).dot(d);
  }
  const auto s = bodies.state(0);
  const Vec<2> moved = Vec<2>(s.position) - centre;
  EXPECT_GT(moved.dot(d), 0.0005);  // it slid (a twentieth of a spacing at least)
  EXPECT_LT((moved - moved.dot(d) * d).norm(), 1e-15);
  EXPECT_NEAR(mass * Vec<2>(s.velocity).dot(d), impulse, 1e-12 * std::abs(impulse));
  EXPECT_EQ(s.angular_velocity, 0.0);
  const auto& P = sim.particles();
  for (const auto& [id, x0] : start) {
    std::size_t i = 0;
    while (P.id[i] != id) ++i;
    ASSERT_NEAR((P.position[i] - (x0 + moved)).norm(), 0.0, 1e-12);
  }
}

TEST(RailMotion, RefusesARailWithoutDirectionIn2DAnd3D) {
  const std::string body3 = R"(dimension: 3
particle_spacing: 0.02
lattice: square
end_time: 1
method: {initial_state: lattice}
fluid:
  phases: [{name: water}]
  regions: [{type: box, min: [0, 0, 0], max: [0.3, 0.3, 0.3]}]
bodies:
  - {name: s, shape: {type: box, center: [0.15, 0.15, 0.15], size: [0.1, 0.08, 0.06]}, density: 2000, )";
  const auto key = [](const std::string& text, int dimension) {
    try {
      const YAML::Node r = cases::load_scene_text(text, {});
      if (dimension == 3) cases::build_scene<3>(r, "s");
      else cases::build_scene<2>(r, "s");
    } catch (const cases::SceneError& e) {
      return e.key_path;
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(key(body3 + "motion: rail, rail: {direction: [1, 0, 0]}}\n", 3), "(accepted)");
  EXPECT_EQ(key(body3 + "motion: rail}\n", 3), "bodies[0].rail");
  EXPECT_EQ(key(body3 + "motion: rail, rail: {direction: [0, 0, 0]}}\n", 3), "bodies[0].rail.direction");
  EXPECT_EQ(key(body3 + "rail: {direction: [1, 0, 0]}}\n", 3), "bodies[0].rail");  // motion free
  EXPECT_EQ(key(body3 + "motion: rail, rail: {direction: [1, 0, 0]}, locked: [x]}\n", 3), "bodies[0].locked");
  // A body a symmetry plane cuts: its rail runs in the plane, without friction (the force across would count the
  // half body's push on the plane).
  const std::string cut = R"(dimension: 3
particle_spacing: 0.02
lattice: square
end_time: 1
method: {initial_state: lattice}
fluid:
  phases: [{name: water}]
  regions: [{type: below_level, level: 0.3}]
walls: [{type: tank, min: [0, 0, 0], max: [0.3, 0.3, 0.4], symmetry: [y_min]}]
bodies:
  - {name: s, shape: {type: box, center: [0.15, 0, 0.15], size: [0.1, 0.08, 0.06]}, density: 2000, )";
  EXPECT_EQ(key(cut + "motion: rail, rail: {direction: [1, 0, 0]}}\n", 3), "(accepted)");
  EXPECT_EQ(key(cut + "motion: rail, rail: {direction: [1, 1, 0]}}\n", 3), "bodies[0].rail.direction");
  EXPECT_EQ(key(cut + "motion: rail, rail: {direction: [1, 0, 0], friction: 0.1}}\n", 3), "bodies[0].rail.friction");
  // 2-D: the same key, its direction in the plane.
  const std::string body2 = std::string(kGoodScene) + "bodies: [{name: b, shape: {type: box, center: [0.4, 0.1], "
                                                      "size: [0.05, 0.05]}, density: 2000, ";
  EXPECT_EQ(key(body2 + "motion: rail, rail: {direction: [1, -1]}}]\n", 2), "(accepted)");
  EXPECT_EQ(key(body2 + "motion: rail}]\n", 2), "bodies[0].rail");
  EXPECT_EQ(key(body2 + "motion: rail, rail: {direction: [0, 0]}}]\n", 2), "bodies[0].rail.direction");
  EXPECT_EQ(key(body2 + "rail: {direction: [1, 0]}}]\n", 2), "bodies[0].rail");
  EXPECT_EQ(key(body2 + "motion: rail, rail: {direction: [1, 0, 0]}}]\n", 2), "bodies[0].rail.direction");
}

}  // namespace
}  // namespace slide::testing
