// The error measures that tests and `slide sweep` share (tools/measures/), against values computed by hand.
#include <gtest/gtest.h>

#include <stdexcept>

#include "cases/csv_table.hpp"
#include "tools/measures/dam_break_front.hpp"
#include "tools/measures/series.hpp"

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

}  // namespace
}  // namespace slide::testing
