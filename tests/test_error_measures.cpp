// The error measures that tests and `slide sweep` share (tools/measures/), against values computed by hand.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "cases/csv_table.hpp"
#include "tests/cli_helpers.hpp"
#include "tools/measures/dam_break_front.hpp"
#include "tools/measures/extrema.hpp"
#include "tools/measures/floating_draft.hpp"
#include "tools/measures/poiseuille_profile.hpp"
#include "tools/measures/series.hpp"
#include "tools/measures/wave_signature.hpp"

namespace slide::testing {
namespace {

CsvTable table(std::vector<std::string> header, std::vector<std::vector<std::string>> rows) {
  CsvTable t;
  t.header = std::move(header);
  t.rows = std::move(rows);
  return t;
}

TEST(Series, InterpolatesLinearlyAndHoldsTheEnds) {
  const std::vector<double> x{0.0, 1.0, 3.0}, y{1.0, 3.0, 2.0};
  EXPECT_DOUBLE_EQ(tools::interpolate(x, y, 0.5), 2.0);
  EXPECT_DOUBLE_EQ(tools::interpolate(x, y, 2.0), 2.5);
  EXPECT_DOUBLE_EQ(tools::interpolate(x, y, -1.0), 1.0);
  EXPECT_DOUBLE_EQ(tools::interpolate(x, y, 4.0), 2.0);
}

// A run with Z = 1 + T against reference points (T, Z) = (0, 1), (1, 2.2), (2, 2.5), (3.5, 9): only 0 < T <= 3
// count, so the error is (|2 - 2.2| / 2.2 + |3 - 2.5| / 2.5) / 2 = (1/11 + 1/5) / 2 = 0.145454...
TEST(DamBreakFrontError, MeanRelativeErrorOverTheReferencePointsUpToTMax) {
  const CsvTable run = table({"time", "T", "Z"}, {{"0", "0", "1"}, {"0.1", "2", "3"}, {"0.2", "4", "5"}});
  const CsvTable ref = table({"source_id", "T_dimless_t_sqrt_2g_over_a", "Z_dimless_xfront_over_a"},
                             {{"a", "0", "1"}, {"a", "1", "2.2"}, {"b", "2", "2.5"}, {"b", "3.5", "9"}});
  const tools::FrontError e = tools::dam_break_front_error(run, ref, 3.0);
  EXPECT_EQ(e.points, 2);
  EXPECT_NEAR(e.mean_relative, (1.0 / 11.0 + 1.0 / 5.0) / 2.0, 1e-15);
}

TEST(DamBreakFrontError, RefusesARunThatEndsBeforeTMax) {
  const CsvTable run = table({"T", "Z"}, {{"0", "1"}, {"2.5", "3.5"}});
  const CsvTable ref = table({"T_dimless_t_sqrt_2g_over_a", "Z_dimless_xfront_over_a"}, {{"1", "2"}});
  EXPECT_THROW(tools::dam_break_front_error(run, ref, 3.0), std::runtime_error);
}

// Gauges from a still level of 0.3 m: a crest of +0.02 and a trough of -0.01 at g1; g2 dry at first (NaN), then wet
// at 0.1 and rising to 0.13, falling to 0.095. The first body moves from (0, 0) to (3, 4): travel 5.
TEST(WaveSignature, CrestTroughAndTravelFromTheRunsTables) {
  const CsvTable gauges = table({"time", "g1", "g2"}, {{"0", "0.3", "nan"},
                                                       {"1", "0.32", "0.1"},
                                                       {"2", "0.29", "0.13"},
                                                       {"3", "0.3", "0.095"}});
  const CsvTable bodies = table({"time", "body", "x", "y"},
                                {{"0", "wedge", "0", "0"}, {"0", "other", "9", "9"}, {"1", "wedge", "3", "4"}});
  const tools::WaveSignature s = tools::wave_signature(gauges, nullptr, &bodies);
  ASSERT_EQ(s.gauges, (std::vector<std::string>{"g1", "g2"}));
  EXPECT_NEAR(s.crest[0], 0.02, 1e-15);
  EXPECT_NEAR(s.trough[0], -0.01, 1e-15);
  EXPECT_NEAR(s.crest[1], 0.03, 1e-15);
  EXPECT_NEAR(s.trough[1], -0.005, 1e-15);
  EXPECT_DOUBLE_EQ(s.slide_travel, 5.0);
  const CsvTable front = table({"time", "slide", "front_along"}, {{"0", "mud", "1.0"}, {"1", "mud", "1.75"}});
  EXPECT_DOUBLE_EQ(tools::wave_signature(gauges, &front, nullptr).slide_travel, 0.75);
}

// Reference: crests (0.02, 0.03), troughs (-0.01, -0.005), travel 5: H* = max(0.03, 0.035) = 0.035. A run with crest
// 0.021 at g1 (0.001 / 0.035 = 2.857 %), trough -0.0065 at g2 (0.0015 / 0.035 = 4.286 %) and travel 5.1 (2 %): 4.286 %.
TEST(WaveSignature, ErrorIsTheLargestDifferenceOverTheReferencesWaveHeightOrTravel) {
  tools::WaveSignature ref{{"g1", "g2"}, {0.02, 0.03}, {-0.01, -0.005}, 5.0};
  tools::WaveSignature run{{"g1", "g2"}, {0.021, 0.03}, {-0.01, -0.0065}, 5.1};
  EXPECT_NEAR(tools::wave_signature_error(run, ref), 0.0015 / 0.035, 1e-12);
  run.slide_travel = 5.5;  // 10 %
  EXPECT_NEAR(tools::wave_signature_error(run, ref), 0.1, 1e-12);
  run.gauges = {"g1", "g3"};
  EXPECT_THROW(tools::wave_signature_error(run, ref), std::invalid_argument);
}

// A box 0.1 m high of 500 kg/m^3 in water of 1000 kg/m^3: exact draft 0.05 m. From t = 1 s: the gauges read
// (0.31 + 0.29) / 2 = 0.30 at t = 1 and (0.30 + 0.32) / 2 = 0.31 at t = 2 (t = 3 has no level at one gauge and is
// left out); the box's centre, linear between 0.300 (t = 0) and 0.302 (t = 2), is at 0.301 and 0.302, its bottom
// 0.05 lower: drafts 0.049 and 0.058, trapezoidal mean 0.0535, error 0.0535 / 0.05 - 1 = 0.07. A second body's
// rows do not count.
TEST(FloatingDraft, TimeMeanOfTheGaugesLevelLessTheBoxsBottomAgainstArchimedes) {
  const CsvTable gauges = table({"time", "left", "right"}, {{"0", "0.5", "0.5"},
                                                           {"1", "0.31", "0.29"},
                                                           {"2", "0.30", "0.32"},
                                                           {"3", "nan", "0.3"}});
  const CsvTable bodies = table({"time", "body", "x", "y"}, {{"0", "box", "0.5", "0.300"},
                                                            {"0", "other", "0.1", "9"},
                                                            {"2", "box", "0.5", "0.302"},
                                                            {"2", "other", "0.1", "9"},
                                                            {"3", "box", "0.5", "0.303"}});
  const tools::FloatingDraft d = tools::floating_draft(gauges, bodies, 0.1, 500.0, 1000.0, 1.0);
  EXPECT_NEAR(d.exact_m, 0.05, 1e-15);
  EXPECT_NEAR(d.draft_m, 0.0535, 1e-12);
  EXPECT_NEAR(d.relative_error, 0.07, 1e-10);
  EXPECT_THROW(tools::floating_draft(gauges, bodies, 0.1, 500.0, 1000.0, 2.5), std::runtime_error);
  // Gauge rows beyond the body's rows are not read by holding the body's last position: refused.
  CsvTable short_bodies = bodies;
  short_bodies.rows.resize(3);
  EXPECT_THROW(tools::floating_draft(gauges, short_bodies, 0.1, 500.0, 1000.0, 1.0), std::runtime_error);
}

// From a run folder: the box and densities from run.json's scene (a mass instead of a density: 10 kg/m over
// 0.2 m x 0.1 m is 500 kg/m^3); a box that is not upright is refused.
TEST(FloatingDraft, ReadsTheBoxAndDensitiesFromTheRunsScene) {
  const auto dir = fresh_directory("floating_draft_measure");
  write_file(dir / "gauges.csv", "time,left\n1,0.3\n2,0.3\n");
  write_file(dir / "bodies.csv", "time,body,x,y\n0,box,0.5,0.3\n2,box,0.5,0.3\n");
  write_file(dir / "run.json", R"({"scene": {"fluid": {"phases": [{"density": 1000}]},
    "bodies": [{"mass": 10, "density": 0, "shape": {"type": "box", "size": [0.2, 0.1], "angle": 0}}]}})");
  const tools::FloatingDraft d = tools::floating_draft(dir, 0.0);
  EXPECT_NEAR(d.exact_m, 0.05, 1e-15);
  EXPECT_NEAR(d.draft_m, 0.05, 1e-15);
  write_file(dir / "run.json", R"({"scene": {"fluid": {"phases": [{"density": 1000}]},
    "bodies": [{"density": 500, "shape": {"type": "box", "size": [0.2, 0.1], "angle": 10}}]}})");
  EXPECT_THROW(tools::floating_draft(dir, 0.0), std::runtime_error);
}

// Newtonian K = 1 Pa s, G = 8 N/m^3, H = 0.5 m: u = 4 (0.25 - y^2), u_max = 1 m/s, centre 1 m. The last profile
// (t = 2): rows 0.75 m (2 particles, u 0.80 against 0.75), 1.0 m (1, exact) and 1.25 m (1, 0.70 against 0.75): rms
// sqrt((2 x 0.05^2 + 0.05^2) / 4) = 0.0433; the t = 1 rows do not count.
TEST(PoiseuilleProfile, RmsOfTheLastProfileWeightedByParticlesAgainstTheClosedForm) {
  const CsvTable profile = table({"time", "y", "u", "v", "particles"}, {{"1", "1.0", "0.1", "0", "4"},
                                                                       {"2", "0.75", "0.80", "0", "2"},
                                                                       {"2", "1.0", "1.0", "0", "1"},
                                                                       {"2", "1.25", "0.70", "0", "1"}});
  const HbPoiseuille exact{1.0, 1.0, 0.0, 8.0, 0.5};
  const tools::PoiseuilleProfileError e = tools::poiseuille_profile_error(profile, exact, 1.0);
  EXPECT_DOUBLE_EQ(e.time, 2.0);
  EXPECT_EQ(e.particles, 4);
  EXPECT_NEAR(e.rms, std::sqrt(3.0 * 0.05 * 0.05 / 4.0), 1e-12);
  EXPECT_NEAR(e.centreline, 0.0, 1e-15);
  // Rows straddling the centre (0.9 and 1.1 m, 0.96 and 0.90 m/s against 0.96 exact): the centreline is their mean,
  // 0.93, 7 % below u_max.
  const CsvTable straddling = table({"time", "y", "u", "v", "particles"}, {{"2", "0.9", "0.96", "0", "3"},
                                                                          {"2", "1.1", "0.90", "0", "3"}});
  EXPECT_NEAR(tools::poiseuille_profile_error(straddling, exact, 1.0).centreline, -0.07, 1e-12);
}

// From a run folder: cases/hb_poiseuille_2d.yaml's channel (walls at 0 and 0.1 m, G = 1000 x 1, K = 10, n = 0.5,
// tau0 = 10) read from run.json, against a profile at the reference table's velocities (u_max 0.06 m/s at n = 0.5,
// cases/reference/hb_plane_poiseuille_analytic.csv): zero error. A Mohr-Coulomb phase is refused.
TEST(PoiseuilleProfile, ReadsTheChannelAndRheologyFromTheRunsScene) {
  const auto dir = fresh_directory("poiseuille_measure");
  const CsvTable ref = read_csv(source_dir() / "cases/reference/hb_plane_poiseuille_analytic.csv");
  std::string rows = "time,y,u,v,particles\n";
  const auto n = ref.numbers("n_flow_index"), y = ref.numbers("y_from_centreline_m"), u = ref.numbers("u_m_per_s");
  for (std::size_t k = 0; k < n.size(); ++k)
    if (n[k] == 0.5) rows += fmt::format("8,{:.17g},{:.17g},0,1\n", 0.05 + y[k], u[k]);
  write_file(dir / "velocity_profile.csv", rows);
  const std::string scene = R"({"scene": {"gravity": [1.0, 0.0],
    "walls": [{"points": [[0.0025, 0.0], [0.0375, 0.0]]}, {"points": [[0.0375, 0.1], [0.0025, 0.1]]}],
    "fluid": {"phases": [{"density": 1000, "rheology": RHEOLOGY}]}}})";
  auto with = [&](const std::string& rheology) {
    std::string s = scene;
    s.replace(s.find("RHEOLOGY"), 8, rheology);
    return s;
  };
  write_file(dir / "run.json", with(R"({"model": "herschel_bulkley", "yield_stress": 10, "consistency": 10,
    "flow_index": 0.5})"));
  const tools::PoiseuilleProfileError e = tools::poiseuille_profile_error(dir);
  EXPECT_GT(e.particles, 5);
  EXPECT_LT(e.rms, 1e-8);
  write_file(dir / "run.json", with(R"({"model": "mohr_coulomb", "cohesion": 0, "friction_angle": 30})"));
  EXPECT_THROW(tools::poiseuille_profile_error(dir), std::runtime_error);
}

// Turning points: exact on a series made of parabolas; O(h^2) on a sampled cosine; none where the series does not turn.
TEST(TurningPoints, ParabolasExactlyACosineToItsSamplingError) {
  const std::vector<double> x{0.0, 0.1, 0.25, 0.45, 0.55, 0.6, 0.8};
  std::vector<double> y;
  for (const double t : x) y.push_back(t < 0.5 ? 2.0 - (t - 0.3) * (t - 0.3) : 1.0 + 3.0 * (t - 0.65) * (t - 0.65));
  const auto p = tools::turning_points(x, y);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_NEAR(p[0].x, 0.3, 1e-14);
  EXPECT_NEAR(p[0].y, 2.0, 1e-14);
  EXPECT_NEAR(p[1].x, 0.65, 1e-14);
  EXPECT_NEAR(p[1].y, 1.0, 1e-14);
  std::vector<double> t, c;
  for (int k = 0; k <= 180; ++k) t.push_back(0.01 * k), c.push_back(std::exp(-0.2 * t.back()) * std::cos(2 * M_PI * t.back()));
  const auto q = tools::turning_points(t, c, 0.2);
  ASSERT_EQ(q.size(), 3u);  // the trough near 0.5, the crest near 1, the trough near 1.5
  for (int k = 0; k < 3; ++k) {
    // The vertex of e^{-0.2 t} cos(2 pi t): tan(2 pi t) = -0.2 / (2 pi).
    const double exact = 0.5 * (k + 1) - std::atan(0.2 / (2 * M_PI)) / (2 * M_PI);
    EXPECT_NEAR(q[k].x, exact, 2e-4);
    EXPECT_NEAR(q[k].y, std::exp(-0.2 * exact) * std::cos(2 * M_PI * exact), 1e-4);
  }
  EXPECT_TRUE(tools::turning_points(x, std::vector<double>(x.size(), 1.0)).empty());
}

}  // namespace
}  // namespace slide::testing
