// Deformable slides at rest and in motion (issue 11, section 3): a sediment block of its own phase (bodies[] with a
// model other than rigid) on a flat floor under water, with and without a yield stress, and a Mohr-Coulomb layer on
// slopes either side of its friction angle. Coarse spacings, so that each test runs in well under a minute on one
// core.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include "coupling/slide_front.hpp"
#include "fluid/lattice.hpp"
#include "tests/cli_helpers.hpp"
#include "tests/scene_runner.hpp"
#include "tests/sediment_block.hpp"

namespace slide::testing {
namespace {


// A 0.2 m x 0.1 m block of 1950 kg/m^3 on the floor of a 0.8 m tank under 0.2 m of still water, dp = 0.02 m,
// Bingham with the given yield stress and consistency; the water settles around the held block for 0.5 s.
std::string block_on_floor(double yield_stress, double consistency) {
  return fmt::format(R"(particle_spacing: 0.02
end_time: 1.0
fluid:
  phases: [{{name: water, density: 1000, rheology: {{model: newtonian, viscosity: 1.0e-3}}}}]
  regions: [{{type: below_level, level: 0.2}}]
walls: [{{name: tank, points: [[0, 0.3], [0, 0], [0.8, 0], [0.8, 0.3]]}}]
bodies:
  - name: block
    model: herschel_bulkley
    shape: {{type: box, center: [0.4, 0.05], size: [0.2, 0.1]}}
    density: 1950
    rheology: {{yield_stress: {}, consistency: {}, flow_index: 1}}
method: {{gradient: variational, initial_state: settled, settling_time: 0.5}}
output: {{snapshots: false}}
)",
                     yield_stress, consistency);
}

// The block's own buoyant weight per area as a shear stress scale: rho' g h = (1950 - 1000) 9.81 0.1 = 932 Pa. On a
// flat floor nothing shears it at rest but its own sides' pressure: the largest shear stress in a rectangle of
// Bingham material standing on a floor is of order rho' g h / 2.
constexpr double buoyant_weight_per_area = (1950.0 - 1000.0) * g * 0.1;

TEST(SedimentBlock, WithEnoughYieldStressStaysPut) {
  const double tau_y = 3000.0;  // 3.2 rho' g h
  auto scene = build_scene_text("block_stays", block_on_floor(tau_y, 1.0));
  ASSERT_EQ(scene->slides.size(), 1u);
  const std::uint8_t phase = scene->slides[0].phase;
  auto& sim = *scene->simulation;
  const double dp = sim.options.dp;
  const auto start = slide_positions(sim.particles(), phase);
  double most = 0.0;
  ASSERT_TRUE(run_scene(*scene, [&](const Simulation<2>& s) {
    most = std::max(most, largest_displacement(s.particles(), phase, start));
  }));
  std::printf("tau_y %.0f Pa = %.2f rho' g h (%.0f Pa): largest displacement over 1 s %.3g m = %.3f dp, %zu particles, "
              "%ld steps, %ld solves, %ld unconverged\n",
              tau_y, tau_y / buoyant_weight_per_area, buoyant_weight_per_area, most, most / dp, start.size(),
              sim.step_count(), sim.viscous_solves().solves, sim.viscous_solves().unconverged);
  EXPECT_LT(most, 0.5 * dp);
}

// slide check warns that a slide its own weight cannot yield is cheaper as a rigid body: tau_y at or above
// rho' g H (932 Pa here), and only then.
TEST(SedimentBlock, CheckWarnsWhenTheYieldStressKeepsTheSlideRigidAtRest) {
  const auto dir = fresh_directory("block_rigid_at_rest");
  for (const double tau_y : {3000.0, 932.0, 900.0}) {
    write_file(dir / "s.yaml", block_on_floor(tau_y, 1.0));
    const CommandResult r = run_command(slide_binary() + " check " + (dir / "s.yaml").string());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    const bool warned = r.output.find("warning: bodies[0]: its strength at rest") != std::string::npos;
    EXPECT_EQ(warned, tau_y >= 932.0) << tau_y << " Pa: " << r.output;
    if (warned) {
      EXPECT_NE(r.output.find("bodies[0].model: rigid"), std::string::npos) << r.output;
    }
  }
}

// The same block without a yield stress, a viscous fluid of 0.1 Pa s twice as dense as the water: it slumps, its
// thickness (the largest column thickness, 2 dp columns as slide_front.csv) drops and its front moves out.
TEST(SedimentBlock, WithoutYieldStressSlumps) {
  auto scene = build_scene_text("block_slumps", block_on_floor(0.0, 0.1));
  const std::uint8_t phase = scene->slides[0].phase;
  auto& sim = *scene->simulation;
  const double dp = sim.options.dp;
  const Vec<2> right(1.0, 0.0);
  const SlideFront before = measure_slide_front(sim.particles(), phase, right, dp, 2.0 * dp);
  SlideFront at_half;
  bool half = false;
  ASSERT_TRUE(run_scene(*scene, [&](const Simulation<2>& s) {
    if (!half && s.time() >= 0.5) at_half = measure_slide_front(s.particles(), phase, right, dp, 2.0 * dp), half = true;
  }));
  const SlideFront after = measure_slide_front(sim.particles(), phase, right, dp, 2.0 * dp);
  std::printf("tau_y 0, K 0.1 Pa s: thickness %.3f -> %.3f (0.5 s) -> %.3f m (1 s), front x %.3f -> %.3f -> %.3f m, "
              "%ld steps\n",
              before.thickness_max, at_half.thickness_max, after.thickness_max, before.front[0], at_half.front[0],
              after.front[0], sim.step_count());
  EXPECT_LT(after.thickness_max, 0.75 * before.thickness_max);
  EXPECT_GT(after.front[0] - before.front[0], 5.0 * dp);
}

// A Mohr-Coulomb layer (cohesion 0, phi = 30 degrees, K = 1 Pa s, 1950 kg/m^3) on an infinite slope: 0.1 m deep on
// a floor, periodic along it (0.204 m period), gravity tilted by the slope angle a. The textbook criterion of a
// cohesionless infinite slope (e.g. Craig's Soil Mechanics, 7th ed., 9.8): shear stress rho g z sin a against the
// strength rho g z cos a tan phi at every depth z, so the layer stands for a < phi and slides for a > phi, where the
// layer's centre of mass starts with the acceleration of a rigid block with friction tan phi, g (sin a - cos a
// tan phi) (the consistency's stress is zero at rest). Why a layer and not a block: a cohesionless block's free end
// faces collapse on any slope (their own angle of repose), so a block cannot test the criterion. dp = 0.01 m, hexagonal
// lattice (still water's stable packing), settled for 1 s (the sediment as a fluid: coupling/relaxation.hpp), c0 20 m/s.
struct SlopeRun {
  double largest_particle = 0.0;  // m, largest displacement of a particle over the run
  double along_0_2 = 0.0;         // m, down-slope distance of the centre of mass at 0.2 s
  double moved = 0.0;             // m, down-slope distance of the centre of mass at the end
  double dp = 0.0;
  long steps = 0;
};

SlopeRun layer_on_slope(double slope_deg, double end_time) {
  // The period holds a whole number of the hexagonal lattice's columns (19 columns, 0.2042 m), so the layer and the
  // floor join across the seam (cases/build_options.cpp, check_period).
  const double a = slope_deg * M_PI / 180.0, period = 19.0 * nearest_spacing(LatticeKind::hexagonal, 0.01);
  const std::string yaml = fmt::format(R"(particle_spacing: 0.01
end_time: {end}
gravity: [{gx}, {gy}]
lattice: hexagonal
domain: {{min: [0, -0.05], max: [{period:.17g}, 0.3], periodic_x: true}}
fluid:
  phases: [{{name: sand, density: 1950, rheology: {{model: mohr_coulomb, cohesion: 0, friction_angle: 30, consistency: 1}}}}]
  regions: [{{type: rectangle, min: [0, 0], max: [{period:.17g}, 0.1]}}]
walls: [{{name: floor, points: [[-0.05, 0], [{floor_end}, 0]]}}]
method: {{gradient: variational, wall_pressure: extrapolated, sound_speed: 20, initial_state: settled, settling_time: 1.0}}
output: {{snapshots: false}}
)",
                                       fmt::arg("end", end_time), fmt::arg("gx", g * std::sin(a)),
                                       fmt::arg("gy", -g * std::cos(a)), fmt::arg("period", period), fmt::arg("floor_end", period + 0.05));
  auto scene = build_scene_text(fmt::format("mc_layer_{:.0f}", slope_deg), yaml);
  auto& sim = *scene->simulation;
  // Down-slope displacement with the periodic wrap undone: particles are followed by id, step by step.
  std::unordered_map<std::uint32_t, Vec<2>> start = slide_positions(sim.particles(), 0), last = start, unwrapped = start;
  SlopeRun r;
  r.dp = sim.options.dp;
  auto mean_along = [&] {
    double sum = 0.0;
    for (const auto& [id, x] : unwrapped) sum += x[0] - start.at(id)[0];
    return sum / unwrapped.size();
  };
  bool sampled = false;
  EXPECT_TRUE(run_scene(*scene, [&](const Simulation<2>& s) {
    const auto& P = s.particles();
    for (std::size_t i = 0; i < P.real_count(); ++i) {
      if (P.kind[i] != Kind::fluid) continue;
      Vec<2> step = P.position[i] - last.at(P.id[i]);
      step[0] -= period * std::round(step[0] / period);
      unwrapped[P.id[i]] += step;
      last[P.id[i]] = P.position[i];
      r.largest_particle = std::max(r.largest_particle, (unwrapped[P.id[i]] - start.at(P.id[i])).norm());
    }
    if (!sampled && s.time() >= 0.2) r.along_0_2 = mean_along(), sampled = true;
  }));
  r.moved = mean_along();
  r.steps = sim.step_count();
  return r;
}

TEST(SedimentBlock, MohrCoulombLayerStandsOnASlopeGentlerThanPhi) {
  const SlopeRun r = layer_on_slope(20.0, 1.0);
  std::printf("20 deg (phi 30): centre of mass moved %.3g m down the slope in 1 s, largest particle %.3g m = %.3f dp, "
              "%ld steps\n",
              r.moved, r.largest_particle, r.largest_particle / r.dp, r.steps);
  EXPECT_LT(r.largest_particle, 0.5 * r.dp);
}

// Measured: -8.5 % at dp 0.01 with the period a whole number of columns (-9.0 % with the former 0.2 m period, whose
// seam left a gap of 1.6 columns in every row; -14 % with that seam and the points on the period's ends both kept).
// With the former seam (all the figures below): -8.6 % at dp 0.005 (the same run as a scene); the floor holds the
// layer with 4 % more than its weight's p tan(phi) (881 Pa against 846 Pa per m^2 of floor), at both spacings, so it
// is not resolution; the consistency is not it either (K = 0.01 Pa s: -8.4 %), nor mostly the time step (CFL 0.1 and
// 0.05: -8.3 % and -8.0 %). With the floor's friction bounded at tan(phi) itself (basal_friction_angle: 30,
// fluid/basal_friction.hpp) it is -6.0 %: a third of the excess is the no-slip floor's (the wall pairs take the
// particle's viscosity, from its own shear rate), the rest is inside the layer. Not pinned down further; the stiff
// block on a Coulomb floor (tests/test_basal_friction.cpp) shows a like excess (-2.8 %).
TEST(SedimentBlock, MohrCoulombLayerSlidesOnASlopeSteeperThanPhi) {
  const double a = 40.0 * M_PI / 180.0;
  const double rigid = g * (std::sin(a) - std::cos(a) * std::tan(30.0 * M_PI / 180.0));
  const SlopeRun r = layer_on_slope(40.0, 0.2);
  const double acceleration = 2.0 * r.along_0_2 / (0.2 * 0.2);
  std::printf("40 deg (phi 30): centre of mass moved %.4f m down the slope in 0.2 s: mean acceleration %.3f m/s^2, "
              "rigid block with friction tan phi %.3f m/s^2 (%+.1f %%), %ld steps\n",
              r.along_0_2, acceleration, rigid, 100.0 * (acceleration / rigid - 1.0), r.steps);
  EXPECT_GT(r.along_0_2, 2.0 * r.dp);
  EXPECT_NEAR(acceleration, rigid, 0.1 * rigid);
}

}  // namespace
}  // namespace slide::testing
