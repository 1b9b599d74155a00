// The free-surface gauge (coupling/free_surface_gauge.hpp) on flat water of either lattice: it reads the water's
// edge, half a row spacing above the top row, wherever it stands along the row; and the 3-D profiles along a line.
#include <gtest/gtest.h>

#include <cmath>

#include "cases/csv_table.hpp"
#include "coupling/free_surface_gauge.hpp"
#include "tests/cli_helpers.hpp"
#include "tests/scene_runner.hpp"
#include "tests/water_block_scene.hpp"

namespace slide::testing {
namespace {

void expect_gauge_reads_the_edge(const std::string& lattice) {
  auto scene = free_water_block(lattice, "gauge");
  const auto& sim = *scene->simulation;
  const double dp = sim.options.dp;
  double top = -1.0;
  for (std::size_t i = 0; i < sim.particles().size(); ++i) top = std::max(top, sim.particles().position[i][1]);
  const double edge = top + 0.5 * row_spacing(sim.options.lattice, dp);
  // Eleven gauges across one lattice spacing in the middle of the block.
  const double a = nearest_spacing(sim.options.lattice, dp);
  double mean = 0.0;
  for (int k = 0; k <= 10; ++k) {
    const double eta = free_surface_elevation<2>(sim, Vec<2>(0.2 + 0.1 * k * a, 0.0));
    EXPECT_NEAR(eta, edge, 0.06 * dp) << lattice << " gauge " << k;
    mean += eta / 11.0;
  }
  EXPECT_NEAR(mean, edge, 0.04 * dp) << lattice;
  // No water under the line: NaN.
  EXPECT_TRUE(std::isnan(free_surface_elevation<2>(sim, Vec<2>(0.6, 0.0))));
}

TEST(Gauge, ReadsTheEdgeOfASquareLattice) { expect_gauge_reads_the_edge("square"); }
TEST(Gauge, ReadsTheEdgeOfAHexagonalLattice) { expect_gauge_reads_the_edge("hexagonal"); }

// A 3-D profile (profiles: from, to) runs along its line at points evenly spaced (0.06 m at 0.01: 7 points), once per
// time; where it passes a gauge it reads what the gauge reads; still water reads flat. A line of no length is refused
// naming profiles.to.
TEST(Gauge, ProfileIn3DRunsAlongItsLineAndReadsWhatAGaugeReads) {
  const auto dir = fresh_directory("profile_3d");
  const std::string scene = "dimension: 3\nparticle_spacing: 0.01\nend_time: 0.01\n"
                            "method: {initial_state: lattice}\n"
                            "fluid: {phases: [{name: water, density: 1000}], regions: [{type: below_level, level: 0.1}]}\n"
                            "walls: [{type: tank, min: [0, 0, 0], max: [0.1, 0.1, 0.2]}]\n"
                            "gauges: [{name: centre, x: 0.05, y: 0.05}]\n"
                            "output: {snapshots: false}\n";
  write_file(dir / "s.yaml", scene + "profiles: {times: [0, 0.005], from: [0.02, 0.05], to: [0.08, 0.05]}\n");
  const auto run = run_command(slide_binary() + " run " + (dir / "s.yaml").string() + " --out " +
                               (dir / "out").string() + " --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const auto profiles = read_csv(dir / "out" / "profiles.csv");
  const auto gauges = read_csv(dir / "out" / "gauges.csv");
  EXPECT_EQ(profiles.header, (std::vector<std::string>{"time", "x", "y", "eta"}));
  const auto t = profiles.numbers("time"), x = profiles.numbers("x"), y = profiles.numbers("y"),
             eta = profiles.numbers("eta");
  ASSERT_EQ(t.size(), 14u);
  const double centre = gauges.numbers("centre")[0];
  EXPECT_EQ(gauges.numbers("time")[0], 0.0);
  for (std::size_t k = 0; k < t.size(); ++k) {
    EXPECT_NEAR(x[k], 0.02 + 0.01 * double(k % 7), 1e-15);
    EXPECT_EQ(y[k], 0.05);
    EXPECT_NEAR(eta[k], centre, 0.1 * 0.01) << "at x = " << x[k] << ", t = " << t[k];
  }
  EXPECT_EQ(t[0], 0.0);
  EXPECT_GE(t[7], 0.005);
  EXPECT_NEAR(eta[3], centre, 1e-12);  // (0.05, 0.05) at t = 0: the gauge's point
  write_file(dir / "s.yaml", scene + "profiles: {times: [0], from: [0.02, 0.05], to: [0.02, 0.05]}\n");
  const auto refused = run_command(slide_binary() + " run " + (dir / "s.yaml").string() + " --out " +
                                   (dir / "bad").string() + " --quiet");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.output.find("profiles.to"), std::string::npos) << refused.output;
}

}  // namespace
}  // namespace slide::testing
