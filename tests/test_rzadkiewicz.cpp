// The Rzadkiewicz-type slide (cases/rzadkiewicz_slide_2d.yaml) at a CI resolution (dp = 0.04 m, twice the shipped
// spacing), with both slide models from the same scene: the runs reach 0.8 s without instability, the slide moves
// down the slope, the water makes a wave, and the deformable slide's outputs are there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/cli_helpers.hpp"
#include "cases/csv_table.hpp"

namespace slide::testing {
namespace {

namespace fs = std::filesystem;

CommandResult run_slide(const fs::path& out, const std::vector<std::string>& sets) {
  std::string cmd = slide_binary() + " run " + (source_dir() / "cases" / "rzadkiewicz_slide_2d.yaml").string() +
                    " --quiet --out " + out.string() + " --set particle_spacing=0.04 --set output.snapshots=false";
  for (const auto& s : sets) cmd += " --set " + s;
  return run_command(cmd);
}

// The largest departure of any gauge from its first reading: the wave the slide made.
double largest_wave(const CsvTable& gauges) {
  double most = 0.0;
  for (std::size_t c = 1; c < gauges.header.size(); ++c) {
    const auto eta = gauges.numbers(gauges.header[c]);
    for (double e : eta) most = std::max(most, std::abs(e - eta.front()));
  }
  return most;
}

TEST(Rzadkiewicz, DeformableSlideRunsToItsEndAndFlowsDownTheSlope) {
  const auto dir = fresh_directory("rzadkiewicz_deformable");
  const CommandResult r = run_slide(dir, {});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const CsvTable front = read_csv(dir / "slide_front.csv");
  const auto t = front.numbers("time"), along = front.numbers("front_along"), n = front.numbers("particles");
  EXPECT_NEAR(t.back(), 0.8, 1e-9);
  EXPECT_GT(along.back() - along.front(), 0.3) << "the front should run down the slope";
  EXPECT_EQ(n.front(), n.back());  // no sediment particle lost
  const CsvTable outline = read_csv(dir / "slide_outline.csv");
  const auto ot = outline.numbers("time");
  EXPECT_NEAR(*std::min_element(ot.begin(), ot.end()), 0.4, 0.01);
  EXPECT_NEAR(*std::max_element(ot.begin(), ot.end()), 0.8, 1e-9);
  EXPECT_GT(largest_wave(read_csv(dir / "gauges.csv")), 0.01);
  const std::string json = read_file(dir / "run.json");
  EXPECT_NE(json.find("\"viscous_scheme\": \"implicit\""), std::string::npos);
  EXPECT_NE(json.find("\"viscous\": 0"), std::string::npos);  // the CFL limit set every step
}

TEST(Rzadkiewicz, SameSceneWithARigidSlideRunsToItsEnd) {
  const auto dir = fresh_directory("rzadkiewicz_rigid");
  const CommandResult r = run_slide(dir, {"bodies[0].model=rigid"});
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const CsvTable bodies = read_csv(dir / "bodies.csv");
  const auto t = bodies.numbers("time"), x = bodies.numbers("x"), y = bodies.numbers("y");
  EXPECT_NEAR(t.back(), 0.8, 1e-9);
  const double down_slope = ((x.back() - x.front()) - (y.back() - y.front())) / std::sqrt(2.0);
  EXPECT_GT(down_slope, 0.1) << "the rigid wedge should slide down the slope";
  EXPECT_FALSE(fs::exists(dir / "slide_front.csv"));
  EXPECT_GT(largest_wave(read_csv(dir / "gauges.csv")), 0.01);
  EXPECT_NE(read_file(dir / "run.json").find("\"viscous_scheme\": \"explicit\""), std::string::npos);
}

}  // namespace
}  // namespace slide::testing
