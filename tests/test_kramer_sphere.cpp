// Kramer et al. (2021) floating sphere, heave decay (cases/kramer2021_sphere_3d.yaml, data in
// cases/reference/kramer2021_sphere_heave_decay_01D.csv): the sphere released H0 = 0.03 m above where it floats at
// rest, its heave over H0 against the mean of the experiment's repeats, as the experiment measured it: from its own
// rest. The model's rest is found as the experiment's was, by letting the sphere float free while the water settles
// (the model's water stands lower than the stated level by its compression under its weight, and the sphere a little
// below its Archimedes position: docs/three-d.md); the drop then holds it H0 above that rest while the water settles
// again, and lets it go at t = 0.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cases/csv_table.hpp"
#include "coupling/rigid_bodies.hpp"
#include "tests/scene_runner.hpp"
#include "tools/measures/extrema.hpp"

namespace slide::testing {
namespace {

constexpr double H0 = 0.03;     // m, the drop (0.1 D)
constexpr double Te0 = 0.7561;  // s, the data's time scale

struct Heave {
  double rest_z = 0.0;                      // m, the centre's height at rest
  std::vector<tools::Extremum> extrema;     // (t / Te0, (z - rest) / H0) after t / Te0 = 0.2
};

Heave heave_at(double dp) {
  const std::string spacing = "particle_spacing=" + std::to_string(dp);
  Heave h;
  {
    auto rest = load_shipped_scene<3>("kramer2021_sphere_3d.yaml", {spacing, "bodies[0].during_settling=free"});
    h.rest_z = rest->simulation->bodies()->state(0).position[2];
  }
  char center[96];
  std::snprintf(center, sizeof center, "bodies[0].shape.center=[0, 0, %.9f]", h.rest_z + H0);
  auto scene = load_shipped_scene<3>("kramer2021_sphere_3d.yaml", {spacing, center});
  auto& bodies = *scene->simulation->bodies();
  // Sampled every 5 ms, as bodies.csv is (a step's noise would add turning points of its own).
  std::vector<double> t, x3;
  double next_sample = 0.0;
  EXPECT_TRUE(run_scene<3>(*scene, [&](const Simulation<3>& s) {
    if (s.time() < next_sample) return;
    next_sample += 0.005;
    t.push_back(s.time() / Te0);
    x3.push_back((bodies.state(0).position[2] - h.rest_z) / H0);
  }));
  h.extrema = tools::turning_points(t, x3, 0.2);
  return h;
}

// The data's first four extrema, from the same turning points of its mean.
std::vector<tools::Extremum> data_extrema() {
  const CsvTable ref = read_csv(source_dir() / "cases/reference/kramer2021_sphere_heave_decay_01D.csv");
  return tools::turning_points(ref.numbers("t_over_Te0_dimless"), ref.numbers("x3_over_H0m_mean_dimless"), 0.2);
}

// Issue 31: the first period within 5 % and the first trough within 10 % of the drop. The period is taken as the time
// of the first crest (the sphere is released at one); the first four extrema are printed against the data.
// Measured at stop 42 (the same runs through `slide run`, bodies.csv every 5 ms): rest at 0.899181 m; extrema -0.738 /
// +0.699 / -0.295 / +0.283 at t/Te0 0.510 / 1.027 / 1.548 / 2.045, against the data's -0.854 / +0.630 / -0.455 /
// +0.333 at 0.510 / 1.016 / 1.522 / 2.018: the period +1.0 % (met), the first trough 0.115 of the drop short (the
// issue's 0.10 not met: this test fails by that much at dp 0.02).
TEST(LongKramerSphere, HeaveDecayAtDp0_02FollowsTheExperiment) {
  const Heave h = heave_at(0.02);
  const auto data = data_extrema();
  ASSERT_GE(data.size(), 4u);
  ASSERT_GE(h.extrema.size(), 3u) << "the sphere does not oscillate";
  std::printf("Kramer sphere, dp 0.02: rest at z = %.5f m\n", h.rest_z);
  for (std::size_t k = 0; k < 4 && k < h.extrema.size(); ++k)
    std::printf("  extremum %zu: t/Te0 %.3f (data %.3f, %+.1f %%), x3/H0 %+.3f (data %+.3f, %+.3f of the drop)\n", k + 1,
                h.extrema[k].x, data[k].x, 100 * (h.extrema[k].x / data[k].x - 1), h.extrema[k].y, data[k].y,
                h.extrema[k].y - data[k].y);
  EXPECT_LT(h.extrema[0].y, 0.0);  // the first is the trough
  EXPECT_NEAR(h.extrema[1].x, data[1].x, 0.05 * data[1].x);
  EXPECT_NEAR(h.extrema[0].y, data[0].y, 0.10);
}

}  // namespace
}  // namespace slide::testing
