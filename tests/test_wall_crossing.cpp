// A splash is not a failure (issue 14): a fluid particle that leaves the domain through an open side is taken out
// and counted; one that passes through a wall is an instability. fluid/wall_crossing.hpp against exact answers, then
// whole runs.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "fluid/wall_crossing.hpp"
#include "tests/scene_runner.hpp"

namespace slide::testing {
namespace {

// A floor from (0, 0) to (1, 0), water above, its particles 0.03 m deep; and a wall x = 1 from (1, 0) up to (1, 1),
// water to its left.
WallCrossing floor_and_side() {
  return WallCrossing({{Vec<2>(0, 0), Vec<2>(1, 0), Vec<2>(0, 1)}, {Vec<2>(1, 0), Vec<2>(1, 1), Vec<2>(-1, 0)}}, 0.03,
                      Vec<2>(-0.5, -0.5), Vec<2>(1.5, 1.5), 0.1);
}

TEST(WallCrossing, AMoveIntoTheWallLayersIsNotACrossing) {
  const WallCrossing w = floor_and_side();
  EXPECT_EQ(w.crossed(Vec<2>(0.5, 0.01), Vec<2>(0.5, -0.02)), -1);   // 0.02 into the 0.03 of particles
  EXPECT_EQ(w.crossed(Vec<2>(0.5, 0.01), Vec<2>(0.5, -0.03)), -1);   // onto the back, not past it
  EXPECT_EQ(w.crossed(Vec<2>(0.5, 0.30), Vec<2>(0.6, 0.29)), -1);    // in the open
}

TEST(WallCrossing, AMovePastTheBackOfTheWallIsACrossingOfThatFace) {
  const WallCrossing w = floor_and_side();
  EXPECT_EQ(w.crossed(Vec<2>(0.5, -0.02), Vec<2>(0.5, -0.04)), 0);   // from inside the layers, past the back
  EXPECT_EQ(w.crossed(Vec<2>(0.5, 0.01), Vec<2>(0.52, -0.05)), 0);   // straight through in one move
  EXPECT_EQ(w.crossed(Vec<2>(0.99, 0.5), Vec<2>(1.04, 0.5)), 1);     // through the side wall
  // Only from the fluid's side: coming back out of (or moving about behind) a wall is not a crossing.
  EXPECT_EQ(w.crossed(Vec<2>(0.5, -0.04), Vec<2>(0.5, -0.02)), -1);
  EXPECT_EQ(w.crossed(Vec<2>(0.5, -0.06), Vec<2>(0.5, -0.08)), -1);
}

TEST(WallCrossing, PastAFacesEndIsNotThroughIt) {
  const WallCrossing w = floor_and_side();
  // Over the side wall's top end (y = 1) and down behind it: the back line is met above the face's length.
  EXPECT_EQ(w.crossed(Vec<2>(0.99, 1.02), Vec<2>(1.05, 1.01)), -1);
  EXPECT_EQ(w.crossed(Vec<2>(1.05, 1.01), Vec<2>(1.05, 0.9)), -1);
  // Beyond the floor's end, x > 1 under the side wall: the floor's back line is met outside its length there too,
  // but the side wall's is not crossed either (that move is behind it, moving down).
  EXPECT_EQ(w.crossed(Vec<2>(1.2, 0.01), Vec<2>(1.2, -0.05)), -1);
}

TEST(WallCrossing, TheLowestFaceIndexIsReported) {
  // Two faces on the same line, the second listed first in no bin order: face 0 wins where both match.
  const WallCrossing w({{Vec<2>(0, 0), Vec<2>(1, 0), Vec<2>(0, 1)}, {Vec<2>(0, 0), Vec<2>(1, 0), Vec<2>(0, 1)}}, 0.03,
                       Vec<2>(-0.5, -0.5), Vec<2>(1.5, 1.5), 0.1);
  EXPECT_EQ(w.crossed(Vec<2>(0.5, 0.0), Vec<2>(0.5, -0.1)), 0);
  EXPECT_EQ(WallCrossing().crossed(Vec<2>(0.5, 0.0), Vec<2>(0.5, -0.1)), -1);
}

// An open tank whose water falls upwards (gravity +9.81 m/s^2): it leaves over the top, where there is no wall (and
// nothing holds it, which the scene says it means).
const char* kUpsideDown = R"(particle_spacing: 0.02
checks: {allow_uncontained_fluid: true}
end_time: 0.5
gravity: [0, 9.81]
fluid:
  phases: [{name: water}]
  regions: [{type: rectangle, min: [0, 0], max: [0.2, 0.1]}]
walls:
  - points: [[0, 0.2], [0, 0], [0.2, 0], [0.2, 0.2]]
method: {initial_state: lattice, sound_speed: 20}
output: {snapshot_interval: 0.25}
)";

TEST(LeftTheDomain, WaterLeavingOverAnOpenTopIsTakenOutAndCountedAndTheRunCompletes) {
  const auto dir = fresh_directory("left_the_domain");
  write_file(dir / "s.yaml", kUpsideDown);
  const auto r = run_command(slide_binary() + " run " + (dir / "s.yaml").string() + " --quiet --threads 1 --out " +
                             (dir / "run").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(read_file(dir / "run" / "run.json"));
  EXPECT_EQ(j["status"], "completed");
  // All the water: by t = 0.5 s it has risen 1.2 m, far over the domain's top (0.2 + 0.1 + 4 re).
  const int water = j["particles"]["fluid"].get<int>();
  ASSERT_GT(water, 0);
  EXPECT_EQ(j["left_the_domain"]["count"], water) << j["left_the_domain"].dump();
  const auto& first = j["left_the_domain"]["first"][0];
  EXPECT_GT(first["position"][1].get<double>(), j["derived"]["domain_max"][1].get<double>());
  EXPECT_GT(first["time"].get<double>(), 0.0);
  EXPECT_NE(j["message"].get<std::string>().find(std::to_string(water) + " fluid particles left the domain"),
            std::string::npos)
      << j["message"];
  // The last snapshot holds the walls only; the ids of what remains are the walls' own.
  const auto h5 = run_command("/usr/bin/python3 -c \"import h5py; f = h5py.File('" + (dir / "run" / "particles.h5").string() +
                              "'); print(len(f['snapshots/000000/id']), len(f['snapshots/000002/id']), "
                              "int(f['snapshots/000002/kind'][()].min()))\"");
  if (h5.exit_code == 0) {
    std::istringstream in(h5.output);
    int first_count = 0, last_count = 0, smallest_kind = -1;
    in >> first_count >> last_count >> smallest_kind;
    EXPECT_EQ(first_count - last_count, water);
    EXPECT_EQ(smallest_kind, 1);  // no fluid left
  }
  std::filesystem::remove_all(dir);
}

TEST(LeftTheDomain, AParticleThroughAWallIsAnInstabilityNamingTheWall) {
  auto scene = build_scene_text("through_wall", R"(particle_spacing: 0.02
end_time: 0.1
fluid:
  phases: [{name: water}]
  regions: [{type: rectangle, min: [0, 0], max: [0.2, 0.1]}]
walls:
  - points: [[0, 0.2], [0, 0], [0.2, 0], [0.2, 0.2]]
method: {initial_state: lattice}
)");
  auto& sim = *scene->simulation;
  auto& P = sim.particles();
  // The lowest fluid particle of the left column, thrown down at 1000 m/s: it goes through the floor in one step.
  std::size_t thrown = P.size();
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::fluid && (thrown == P.size() || P.position[i][0] + P.position[i][1] <
                                                             P.position[thrown][0] + P.position[thrown][1]))
      thrown = i;
  P.velocity[thrown] = Vec<2>(0.0, -1000.0);
  const std::uint32_t id = P.id[thrown];
  const auto bad = sim.step(1e-4, TimeStepLimit::cfl);
  ASSERT_TRUE(bad.has_value());
  EXPECT_EQ(bad->particle, id);
  EXPECT_NE(bad->reason.find("passed through a wall"), std::string::npos) << bad->reason;
  EXPECT_NE(bad->reason.find("(0, 0) - (0.2, 0)"), std::string::npos) << bad->reason;  // the floor
  EXPECT_TRUE(sim.left_the_domain().empty());
}

}  // namespace
}  // namespace slide::testing
