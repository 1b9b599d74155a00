// bodies.csv states a body's angle as the scene states orientations (issue 14): a box placed at 10 degrees reads
// 10 degrees, not 0; and a prescribed series, in the same convention, replays bodies.csv.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cases/csv_table.hpp"
#include "tests/cli_helpers.hpp"

namespace slide::testing {
namespace {

// A box tilted 10 degrees in still water, held for the whole run (release_time after end_time).
std::string tilted_box_scene(const std::string& motion) {
  return std::string(R"(particle_spacing: 0.02
end_time: 0.02
fluid:
  phases: [{name: water}]
  regions: [{type: rectangle, min: [0, 0], max: [0.6, 0.2]}]
walls:
  - points: [[0, 0.6], [0, 0], [0.6, 0], [0.6, 0.6]]
bodies:
  - name: box
    shape: {type: box, center: [0.3, 0.4], size: [0.16, 0.08], angle: 10}
    density: 500
)") + motion + R"(
method: {initial_state: lattice}
output: {snapshots: false}
)";
}

std::vector<double> angles(const std::filesystem::path& bodies_csv) {
  const CsvTable t = read_csv(bodies_csv);
  const int column = t.find_column("angle");
  EXPECT_GE(column, 0);
  std::vector<double> out;
  for (const auto& row : t.rows) out.push_back(std::stod(row.at(static_cast<std::size_t>(column))));
  return out;
}

TEST(BodyAngle, BodiesCsvStatesTheAngleTheSceneStates) {
  const auto dir = fresh_directory("body_angle");
  write_file(dir / "held.yaml", tilted_box_scene("    release_time: 1.0"));
  const auto held = run_command(slide_binary() + " run " + (dir / "held.yaml").string() + " --quiet --out " +
                                (dir / "held").string());
  ASSERT_EQ(held.exit_code, 0) << held.output;
  const auto held_angles = angles(dir / "held" / "bodies.csv");
  ASSERT_GE(held_angles.size(), 2u);
  const double ten_degrees = 10.0 * M_PI / 180.0;
  for (double a : held_angles) EXPECT_NEAR(a, ten_degrees, 1e-12);

  // The same box prescribed by the held run's bodies.csv: the series starts at the placed angle, so it is accepted,
  // and the replay states the same angles.
  write_file(dir / "replay.yaml",
             tilted_box_scene("    motion: prescribed\n    prescribed: {type: series, file: held/bodies.csv}"));
  const auto replay = run_command(slide_binary() + " run " + (dir / "replay.yaml").string() + " --quiet --out " +
                                  (dir / "replay").string());
  ASSERT_EQ(replay.exit_code, 0) << replay.output;
  const auto replay_angles = angles(dir / "replay" / "bodies.csv");
  ASSERT_EQ(replay_angles.size(), held_angles.size());
  for (std::size_t k = 0; k < held_angles.size(); ++k) EXPECT_NEAR(replay_angles[k], held_angles[k], 1e-12);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace slide::testing
