// The error measures that tests and `slide sweep` share (tools/measures/), against values computed by hand.
#include <gtest/gtest.h>

#include <stdexcept>

#include "cases/csv_table.hpp"
#include "tools/measures/dam_break_front.hpp"
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

}  // namespace
}  // namespace slide::testing
