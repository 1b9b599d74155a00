// slide check's estimate at rest (cases/build_bodies.cpp, finish_slide_report) and the solver agree (issue 29, item 4):
// dry, a cohesionless Mohr-Coulomb slide (phi = 30 degrees) as an infinite layer on a slope, periodic along it (gravity
// tilted by the slope angle, the floor flat), on slopes gentler (20 deg) and steeper (40 deg) than phi; under water, a
// granular slide on a real slope with a friction below and above the slope's, and with the frictional strength on the
// total pressure (method.pore_pressure none, the model before issue 29, where the water's head holds it). Where the
// check says "stands", nothing moves half a spacing in 0.3 s; where it says "flows", the centre of mass moves more than
// two spacings.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <unordered_map>

#include <fmt/format.h>

#include "fluid/lattice.hpp"
#include "tests/scene_runner.hpp"
#include "tests/sediment_block.hpp"

namespace slide::testing {
namespace {


struct LayerRun {
  std::string criterion;      // slide check's
  double largest = 0.0;       // m, largest particle displacement along the slope after t = 0
  double centre = 0.0;        // m, the centre of mass's
  double rise = 0.0;          // m, the centre of mass's upward motion
  double dp = 0.0;
};

// What slide check says of the scene's first slide, before it runs.
LayerRun checked(const cases::Scene<2>& scene, double dp) {
  LayerRun r;
  r.dp = dp;
  r.criterion = scene.slides[0].criterion;
  return r;
}

// The dry layer: 0.1 m of sand (1950 kg/m^3, c = 0, phi = 30 deg, K = 1 Pa s) on the floor; dp = 0.02 m on the default
// lattice, the period 10 of its columns. (Not under water: water on an infinite slope is not at rest, it flows down it.)
LayerRun layer(double slope_deg) {
  const double dp = 0.02, a = slope_deg * M_PI / 180.0;
  const double period = 10.0 * nearest_spacing(LatticeKind::hexagonal, dp);
  const std::string yaml = fmt::format(R"(particle_spacing: {dp}
end_time: 0.3
gravity: [{gx:.17g}, {gy:.17g}]
domain: {{min: [0, -0.1], max: [{period:.17g}, 0.5], periodic_x: true}}
fluid:
  phases: [{{name: water, density: 1000, rheology: {{model: newtonian, viscosity: 1.0e-3}}}}]
  regions: []
walls: [{{name: floor, points: [[-0.1, 0], [{floor_end:.17g}, 0]]}}]
bodies:
  - name: sand
    model: mohr_coulomb
    shape: {{type: box, center: [{half:.17g}, 0.05], size: [{period:.17g}, 0.1]}}
    density: 1950
    rheology: {{cohesion: 0, friction_angle: 30, consistency: 1}}
method: {{sound_speed: 20, initial_state: settled, settling_time: 0.5}}
output: {{snapshots: false}}
)",
                                       fmt::arg("dp", dp), fmt::arg("gx", g * std::sin(a)),
                                       fmt::arg("gy", -g * std::cos(a)), fmt::arg("period", period),
                                       fmt::arg("half", 0.5 * period), fmt::arg("floor_end", period + 0.1));
  auto scene = build_scene_text(fmt::format("layer_{:.0f}", slope_deg), yaml);
  auto& sim = *scene->simulation;
  const std::uint8_t phase = scene->slides[0].phase;
  LayerRun r = checked(*scene, dp);
  // Along the slope with the periodic wrap undone: particles followed by id, step by step.
  std::unordered_map<std::uint32_t, Vec<2>> start = slide_positions(sim.particles(), phase), last = start,
                                             unwrapped = start;
  EXPECT_TRUE(run_scene(*scene, [&](const Simulation<2>& s) {
    const auto& P = s.particles();
    for (std::size_t i = 0; i < P.real_count(); ++i) {
      if (P.kind[i] != Kind::fluid || P.phase[i] != phase) continue;
      Vec<2> step = P.position[i] - last.at(P.id[i]);
      step[0] -= period * std::round(step[0] / period);
      unwrapped[P.id[i]] += step;
      last[P.id[i]] = P.position[i];
      r.largest = std::max(r.largest, (unwrapped[P.id[i]] - start.at(P.id[i])).norm());
    }
  }));
  double sum = 0.0;
  for (const auto& [id, x] : unwrapped) sum += x[0] - start.at(id)[0];
  r.centre = sum / unwrapped.size();
  std::printf("%2.0f deg, dry: layer's centre of mass moved %.4f m (%.2f dp), largest particle %.4f m; slide check: "
              "%s\n",
              slope_deg, r.centre, r.centre / dp, r.largest, r.criterion.c_str());
  return r;
}

void expect_agreement(const LayerRun& r) {
  const bool stands = r.criterion.find("stands at rest") != std::string::npos;
  ASSERT_TRUE(stands || r.criterion.find("flows") != std::string::npos) << r.criterion;
  if (stands) EXPECT_LT(r.largest, 0.5 * r.dp) << r.criterion;
  else EXPECT_GT(r.centre, 2.0 * r.dp) << r.criterion;
}

TEST(SlideCheckAgreement, DryLayerGentlerThanPhiStands) {
  const LayerRun r = layer(20.0);
  EXPECT_NE(r.criterion.find("stands at rest"), std::string::npos);
  expect_agreement(r);
}

TEST(SlideCheckAgreement, DryLayerSteeperThanPhiFlows) {
  const LayerRun r = layer(40.0);
  EXPECT_NE(r.criterion.find("flows"), std::string::npos);
  expect_agreement(r);
}

// Under water: the Grilli et al. (2017) triangle (cases/grilli2017_granular_slide_2d.yaml, 1915 kg/m^3) on its 35 degree
// slope under 0.33 m of water, dp = 0.01 m, no basal friction bound (the no-slip wall), 0.5 s after release, of the
// given rheology. Its free vertical front (9 cm) is not an infinite slope: a cohesionless front slumps to its own
// angle of repose on any slope, so the slide that must stand has a cohesion that holds such a face (250 Pa: the
// critical height of a vertical cut 3.83 c / (rho' g) = 10.7 cm) and "stands" is held to its centre of mass.
LayerRun submerged_triangle(const std::string& rheology, const std::string& pore_pressure, double density = 1915) {
  const double dp = 0.01;
  const std::string yaml = fmt::format(R"(particle_spacing: {dp}
end_time: 0.5
fluid:
  phases: [{{name: water, density: 1000, rheology: {{model: newtonian, viscosity: 1.0e-3}}}}]
  regions: [{{type: below_level, level: 0.33}}]
walls: [{{name: slope, points: [[-0.35, 0.75622], [0.73, 0], [1.2, 0], [1.2, 0.45]]}}]
bodies:
  - name: beads
    shape: {{type: polygon, points: [[0.3187, 0.288], [0.448, 0.288], [0.448, 0.19746]]}}
    density: {density}
    {rheology}
    front_direction: [1, 0]
method: {{initial_state: settled, settling_time: 0.3, pore_pressure: {pore}}}
output: {{snapshots: false}}
)",
                                       fmt::arg("dp", dp), fmt::arg("rheology", rheology),
                                       fmt::arg("pore", pore_pressure), fmt::arg("density", density));
  auto scene = build_scene_text(fmt::format("triangle_{}_{}", pore_pressure, density), yaml);
  auto& sim = *scene->simulation;
  const std::uint8_t phase = scene->slides[0].phase;
  LayerRun r = checked(*scene, dp);
  const Vec<2> c0 = centre_of_mass(sim.particles(), phase), down_slope(std::cos(35.0 * M_PI / 180.0),
                                                                      -std::sin(35.0 * M_PI / 180.0));
  EXPECT_TRUE(run_scene(*scene, [](const Simulation<2>&) {}));
  r.centre = (centre_of_mass(sim.particles(), phase) - c0).dot(down_slope);
  r.rise = centre_of_mass(sim.particles(), phase)[1] - c0[1];
  std::printf("triangle under water, pore_pressure %s: centre of mass moved %.4f m (%.2f dp) down the slope in "
              "0.5 s; slide check: %s\n",
              pore_pressure.c_str(), r.centre, r.centre / dp, r.criterion.c_str());
  return r;
}

void expect_agreement_of_the_centre(const LayerRun& r) {
  const bool stands = r.criterion.find("stands at rest") != std::string::npos;
  ASSERT_TRUE(stands || r.criterion.find("flows") != std::string::npos) << r.criterion;
  if (stands) EXPECT_LT(std::abs(r.centre), 0.5 * r.dp) << r.criterion;
  else EXPECT_GT(r.centre, 2.0 * r.dp) << r.criterion;
}

const std::string beads = R"(model: granular
    rheology: {mu_s: 0.41, mu_2: 0.76, i0: 0.1, grain_diameter: 0.004, grain_density: 2500})";

// The beads, mu_s 0.41 (22 deg) on 35 deg: flows.
TEST(SlideCheckAgreement, SubmergedSlideSteeperThanItsFrictionFlows) {
  const LayerRun r = submerged_triangle(beads, "hydrostatic");
  EXPECT_NE(r.criterion.find("flows"), std::string::npos);
  expect_agreement_of_the_centre(r);
}

// Mohr-Coulomb, c = 250 Pa, phi = 30 deg: at its base it holds 250 + 545 tan 30 = 565 Pa against 382 Pa: stands.
TEST(SlideCheckAgreement, SubmergedSlideStrongerThanItsWeightStands) {
  const LayerRun r = submerged_triangle(R"(model: mohr_coulomb
    rheology: {cohesion: 250, friction_angle: 30, consistency: 1})",
                                        "hydrostatic");
  EXPECT_NE(r.criterion.find("stands at rest"), std::string::npos);
  expect_agreement_of_the_centre(r);
}

// On the total pressure (method.pore_pressure none, the model before issue 29) the water's head holds the same slide
// that flows above: check and solver agree on that too.
TEST(SlideCheckAgreement, SubmergedSlideOnTotalPressureStands) {
  const LayerRun r = submerged_triangle(beads, "none");
  EXPECT_NE(r.criterion.find("stands at rest"), std::string::npos);
  expect_agreement_of_the_centre(r);
}

// Lighter than water (800 kg/m^3, issue 30): the check compared a negative shear stress with the strength and said
// "stands at rest", and the slide then moved. It says that the slide floats up, and it does: its centre of mass rises.
TEST(SlideCheckAgreement, SubmergedSlideLighterThanWaterFloatsUp) {
  const LayerRun r = submerged_triangle(beads, "hydrostatic", 800);
  EXPECT_NE(r.criterion.find("floats up"), std::string::npos) << r.criterion;
  EXPECT_EQ(r.criterion.find("stands"), std::string::npos) << r.criterion;
  std::printf("lighter than water: centre of mass rose %.4f m (%.2f dp) in 0.5 s\n", r.rise, r.rise / r.dp);
  EXPECT_GT(r.rise, 2.0 * r.dp);
}

}  // namespace
}  // namespace slide::testing
