// diagnostics.gauge_records: measured wave-gauge records against a run's gauges (tools/measures/gauge_records.hpp),
// the scene key that names them, and gauge_records.csv at the end of a run.
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <string>

#include "cases/scene.hpp"
#include "tests/cli_helpers.hpp"
#include "tools/measures/gauge_records.hpp"

namespace slide {
namespace {

// gauges.csv as a table: times t, one gauge "g" of values eta.
CsvTable gauge_table(const std::vector<double>& t, const std::vector<double>& eta) {
  CsvTable table;
  table.header = {"time", "g"};
  for (std::size_t k = 0; k < t.size(); ++k)
    table.rows.push_back({fmt::format("{:.17g}", t[k]), fmt::format("{:.17g}", eta[k])});
  return table;
}

// The run's gauge reads 0.5 + 0.01 t (its still level 0.5 at t = 0) at t = k / 8; the record 0.01 t + 0.002 at its
// times t' = 0, 0.5, 1, model time t = t' + 0.25: the record is 0.002 above the run wherever both are, which linear
// interpolation reads exactly. Window [0.25, 1]: the run's samples 0.25 ... 1, 7 of them (binary fractions: exact);
// the record's extremes are its samples in the window, at 0.25 and 0.75.
TEST(GaugeRecords, RmsIsTheOffsetBetweenTwoRampsOverTheTimeBothCover) {
  std::vector<double> t, eta;
  for (int k = 0; k <= 8; ++k) t.push_back(k / 8.0), eta.push_back(0.5 + 0.01 * k / 8.0);
  cases::GaugeRecordsSpec spec{"f", 0.25, 0.0, {0.0, 0.5, 1.0}, {{"g", {}}}};
  for (const double tm : spec.time_measured) spec.gauges[0].elevation.push_back(0.01 * (tm + 0.25) + 0.002);
  const auto c = tools::compare_gauge_records(gauge_table(t, eta), spec);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_EQ(c[0].from, 0.25);
  EXPECT_EQ(c[0].to, 1.0);
  EXPECT_EQ(c[0].samples, 7u);
  EXPECT_NEAR(c[0].rms, 0.002, 1e-15);
  EXPECT_NEAR(c[0].measured_height, 0.005, 1e-15);  // 0.01 x (0.75 - 0.25)
  EXPECT_EQ(c[0].trough.time, 0.25);
  EXPECT_NEAR(c[0].trough.elevation, 0.0025, 1e-15);
  EXPECT_EQ(c[0].measured_trough.time, 0.25);
  EXPECT_EQ(c[0].crest.time, 1.0);
  EXPECT_NEAR(c[0].measured_trough.elevation, 0.0045, 1e-15);
  EXPECT_EQ(c[0].measured_crest.time, 0.75);
  EXPECT_NEAR(c[0].measured_crest.elevation, 0.0095, 1e-15);
  EXPECT_NEAR(tools::gauge_records_error(c), 0.002 / 0.005, 1e-12);
}

// A gauge dry at the start counts from its first wet value, and its dry samples are not compared.
TEST(GaugeRecords, DrySamplesAreLeftOutAndTheFirstWetValueIsTheStillLevel) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto table = gauge_table({0, 1, 2, 3}, {nan, 0.25, 0.75, 0.25});
  const cases::GaugeRecordsSpec spec{"f", 0.0, 0.0, {0, 3}, {{"g", {0.0, 0.0}}}};
  const auto c = tools::compare_gauge_records(table, spec);
  EXPECT_EQ(c[0].samples, 3u);
  EXPECT_NEAR(c[0].rms, std::sqrt(0.25 / 3.0), 1e-15);  // elevations 0, 0.5, 0 against 0
  EXPECT_EQ(c[0].crest.time, 2.0);
}

// `until` ends the window early: the ramps of the first test compared up to t = 0.5 only.
TEST(GaugeRecords, UntilEndsTheWindow) {
  std::vector<double> t, eta;
  for (int k = 0; k <= 8; ++k) t.push_back(k / 8.0), eta.push_back(0.01 * k / 8.0);
  const cases::GaugeRecordsSpec spec{"f", 0.0, 0.5, {0.0, 1.0}, {{"g", {0.001, 0.011}}}};
  const auto c = tools::compare_gauge_records(gauge_table(t, eta), spec);
  EXPECT_EQ(c[0].to, 0.5);
  EXPECT_EQ(c[0].samples, 5u);
  EXPECT_NEAR(c[0].rms, 0.001, 1e-15);
  EXPECT_EQ(c[0].crest.time, 0.5);
}

// A sample a rounding past `until` (times are sums of steps) is the sample at `until`.
TEST(GaugeRecords, ASampleARoundingPastUntilIsCompared) {
  const cases::GaugeRecordsSpec spec{"f", 0.0, 2.0, {0.0, 3.0}, {{"g", {0.0, 0.0}}}};
  const auto c = tools::compare_gauge_records(gauge_table({0.0, 1.0, 2.0000000000000004}, {0.0, 0.0, 0.0}), spec);
  EXPECT_EQ(c[0].samples, 3u);
}

TEST(GaugeRecords, RefusesAGaugeTheRunDoesNotHaveOrRecordsThatShareNoTime) {
  const auto table = gauge_table({0, 1}, {0, 0});
  EXPECT_THROW(tools::compare_gauge_records(table, {"f", 0.0, 0.0, {0, 1}, {{"h", {0, 0}}}}), std::invalid_argument);
  EXPECT_THROW(tools::compare_gauge_records(table, {"f", 5.0, 0.0, {0, 1}, {{"g", {0, 0}}}}), std::invalid_argument);
}

// A sweep's error (measure gauge_records) from a run folder's gauge_records.csv: the largest rms over the largest
// measured height, each over the gauges.
TEST(GaugeRecords, ASweepsErrorIsTheLargestRmsOverTheLargestMeasuredHeight) {
  const auto dir = testing::fresh_directory("gauge_records_error");
  testing::write_file(dir / "gauge_records.csv", "gauge,rms,measured_height\na,0.003,0.02\nb,0.001,0.04\n");
  EXPECT_DOUBLE_EQ(tools::gauge_records_error(dir), 0.003 / 0.04);
  EXPECT_THROW(tools::gauge_records_error(dir / "none"), std::runtime_error);
}

// A still 3-D tank, 0.1 m deep; its one gauge at the centre.
std::string tank(const std::string& diagnostics) {
  return "dimension: 3\n"
         "particle_spacing: 0.01\n"
         "lattice: square\n"
         "end_time: 0.01\n"
         "method: {initial_state: lattice}\n"
         "fluid:\n"
         "  phases: [{name: water, density: 1000}]\n"
         "  regions: [{type: below_level, level: 0.1}]\n"
         "walls: [{type: tank, min: [0, 0, 0], max: [0.1, 0.1, 0.2]}]\n"
         "output: {snapshots: false, gauge_interval: 0.001}\n"
         "gauges: [{name: centre, x: 0.05, y: 0.05}]\n" +
         diagnostics;
}

std::string refusal_key(const std::filesystem::path& dir, const std::string& scene_text) {
  try {
    cases::build_scene<3>(cases::load_scene_text(scene_text, {}), "s", dir);
  } catch (const cases::SceneError& e) {
    return e.key_path;
  }
  return "(accepted)";
}

TEST(GaugeRecordsScene, RefusesRecordsThatDoNotFitTheSceneNamingTheKey) {
  const auto dir = testing::fresh_directory("gauge_records_scene");
  testing::write_file(dir / "ok.csv", "# measured\ntime_s,centre\n0,0\n0.005,0.001\n");
  testing::write_file(dir / "other.csv", "time_s,corner\n0,0\n0.005,0.001\n");
  testing::write_file(dir / "back.csv", "time_s,centre\n0,0\n0,0.001\n");
  testing::write_file(dir / "text.csv", "time_s,centre\n0,0\n0.005,high\n");
  const auto with = [](const std::string& file, double offset = 0.0) {
    return fmt::format("diagnostics: {{gauge_records: {{file: {}, time_offset: {}}}}}\n", file, offset);
  };
  EXPECT_EQ(refusal_key(dir, tank(with("ok.csv"))), "(accepted)");
  EXPECT_EQ(refusal_key(dir, tank(with("other.csv"))), "diagnostics.gauge_records.file");
  EXPECT_EQ(refusal_key(dir, tank(with("back.csv"))), "diagnostics.gauge_records.file");
  EXPECT_EQ(refusal_key(dir, tank(with("text.csv"))), "diagnostics.gauge_records.file");
  EXPECT_EQ(refusal_key(dir, tank(with("missing.csv"))), "diagnostics.gauge_records.file");
  EXPECT_EQ(refusal_key(dir, tank(with("ok.csv", 1.0))), "diagnostics.gauge_records.time_offset");
  EXPECT_EQ(refusal_key(dir, tank("diagnostics: {gauge_records: {file: ok.csv, time_offset: 0.002, until: 0.001}}\n")),
            "diagnostics.gauge_records.until");
  testing::write_file(dir / "junk.csv", "time_s,centre\n0,0\n0.005,0.001x\n");
  EXPECT_EQ(refusal_key(dir, tank(with("junk.csv"))), "diagnostics.gauge_records.file");
  testing::write_file(dir / "crlf.csv", "time_s,centre\r\n0,0\r\n0.005,0.001\r\n");
  EXPECT_EQ(refusal_key(dir, tank(with("crlf.csv"))), "(accepted)");
  // The 2-D diagnostics are named as such in 3-D.
  EXPECT_EQ(refusal_key(dir, tank("diagnostics: {surge_front: {enabled: true}}\n")), "diagnostics.surge_front");
}

// gauge_records.csv at the end of a run: the tank (from the lattice, so its surface moves a little) against a record
// 1 mm above the still level throughout reads an rms within the run's largest elevation of 1 mm (the triangle
// inequality), the same as the measure gives from the run's gauges.csv.
TEST(GaugeRecordsScene, ARunWritesItsComparisonWithTheRecords) {
  const auto dir = testing::fresh_directory("gauge_records_run");
  testing::write_file(dir / "records.csv", "time_s,centre\n0,0.001\n0.01,0.001\n");
  testing::write_file(dir / "tank.yaml", tank("diagnostics: {gauge_records: {file: records.csv}}\n"));
  const auto r = testing::run_command(testing::slide_binary() + " run " + (dir / "tank.yaml").string() + " --out " +
                                      (dir / "out").string() + " --threads 1 2>&1");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const CsvTable written = read_csv(dir / "out" / "gauge_records.csv");
  ASSERT_EQ(written.rows.size(), 1u);
  EXPECT_EQ(written.rows[0][written.column("gauge")], "centre");
  const double rms = written.numbers("rms")[0];
  const auto eta = read_csv(dir / "out" / "gauges.csv").numbers("centre");
  double largest = 0.0;
  for (const double e : eta) largest = std::max(largest, std::abs(e - eta.front()));
  EXPECT_GT(largest, 0.0);
  EXPECT_LE(std::abs(rms - 0.001), largest);
  const cases::GaugeRecordsSpec spec{"records.csv", 0.0, 0.0, {0, 0.01}, {{"centre", {0.001, 0.001}}}};
  EXPECT_EQ(rms, tools::compare_gauge_records(read_csv(dir / "out" / "gauges.csv"), spec)[0].rms);
  EXPECT_EQ(written.numbers("samples")[0], 11.0);
}

}  // namespace
}  // namespace slide
