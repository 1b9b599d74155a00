// A splash is not a failure (issue 14): a fluid particle that leaves the domain through an open side is taken out
// and counted; one that passes through a wall is an instability. fluid/wall_crossing.hpp against exact answers, then
// whole runs.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "fluid/wall_crossing.hpp"
#include "tests/scene_runner.hpp"

namespace slide::testing {
namespace {

// A floor from (0, 0) to (1, 0), water above, its particles 0.03 m deep; and a wall x = 1 from (1, 0) up to (1, 1),
// water to its left.
WallCrossing<2> floor_and_side() {
  return WallCrossing<2>({{{Vec<2>(0, 0), Vec<2>(1, 0)}, Vec<2>(0, 1), 0.03},
                          {{Vec<2>(1, 0), Vec<2>(1, 1)}, Vec<2>(-1, 0), 0.03}},
                         Vec<2>(-0.5, -0.5), Vec<2>(1.5, 1.5), 0.1);
}

TEST(WallCrossing, AMoveIntoTheWallLayersIsNotACrossing) {
  const WallCrossing<2> w = floor_and_side();
  EXPECT_EQ(w.crossed(Vec<2>(0.5, 0.01), Vec<2>(0.5, -0.02)), -1);   // 0.02 into the 0.03 of particles
  EXPECT_EQ(w.crossed(Vec<2>(0.5, 0.01), Vec<2>(0.5, -0.03)), -1);   // onto the back, not past it
  EXPECT_EQ(w.crossed(Vec<2>(0.5, 0.30), Vec<2>(0.6, 0.29)), -1);    // in the open
}

TEST(WallCrossing, AMovePastTheBackOfTheWallIsACrossingOfThatFace) {
  const WallCrossing<2> w = floor_and_side();
  EXPECT_EQ(w.crossed(Vec<2>(0.5, -0.02), Vec<2>(0.5, -0.04)), 0);   // from inside the layers, past the back
  EXPECT_EQ(w.crossed(Vec<2>(0.5, 0.01), Vec<2>(0.52, -0.05)), 0);   // straight through in one move
  EXPECT_EQ(w.crossed(Vec<2>(0.99, 0.5), Vec<2>(1.04, 0.5)), 1);     // through the side wall
  // Only from the fluid's side: coming back out of (or moving about behind) a wall is not a crossing.
  EXPECT_EQ(w.crossed(Vec<2>(0.5, -0.04), Vec<2>(0.5, -0.02)), -1);
  EXPECT_EQ(w.crossed(Vec<2>(0.5, -0.06), Vec<2>(0.5, -0.08)), -1);
}

TEST(WallCrossing, PastAFacesEndIsNotThroughIt) {
  const WallCrossing<2> w = floor_and_side();
  // Over the side wall's top end (y = 1) and down behind it: the back line is met above the face's length.
  EXPECT_EQ(w.crossed(Vec<2>(0.99, 1.02), Vec<2>(1.05, 1.01)), -1);
  EXPECT_EQ(w.crossed(Vec<2>(1.05, 1.01), Vec<2>(1.05, 0.9)), -1);
  // Beyond the floor's end, x > 1 under the side wall: the floor's back line is met outside its length there too,
  // but the side wall's is not crossed either (that move is behind it, moving down).
  EXPECT_EQ(w.crossed(Vec<2>(1.2, 0.01), Vec<2>(1.2, -0.05)), -1);
}

TEST(WallCrossing, TheLowestFaceIndexIsReported) {
  // Two faces on the same line, the second listed first in no bin order: face 0 wins where both match.
  const WallCrossing<2> w({{{Vec<2>(0, 0), Vec<2>(1, 0)}, Vec<2>(0, 1), 0.03},
                           {{Vec<2>(0, 0), Vec<2>(1, 0)}, Vec<2>(0, 1), 0.03}},
                          Vec<2>(-0.5, -0.5), Vec<2>(1.5, 1.5), 0.1);
  EXPECT_EQ(w.crossed(Vec<2>(0.5, 0.0), Vec<2>(0.5, -0.1)), 0);
  EXPECT_EQ(WallCrossing<2>().crossed(Vec<2>(0.5, 0.0), Vec<2>(0.5, -0.1)), -1);
}

// A triangle of floor (0, 0, 0), (1, 0, 0), (0, 1, 0), water above, its particles 0.03 m deep.
TEST(WallCrossing, ATriangleIsCrossedOnlyBehindItself) {
  const WallCrossing<3> w({{{Vec<3>(0, 0, 0), Vec<3>(1, 0, 0), Vec<3>(0, 1, 0)}, Vec<3>(0, 0, 1), 0.03}},
                          Vec<3>(-0.5, -0.5, -0.5), Vec<3>(1.5, 1.5, 1.5), 0.1);
  EXPECT_EQ(w.crossed(Vec<3>(0.2, 0.2, 0.01), Vec<3>(0.2, 0.2, -0.05)), 0);   // through, behind the triangle
  EXPECT_EQ(w.crossed(Vec<3>(0.2, 0.2, -0.02), Vec<3>(0.21, 0.2, -0.04)), 0); // from the layers, past the back
  EXPECT_EQ(w.crossed(Vec<3>(0.2, 0.2, 0.01), Vec<3>(0.2, 0.2, -0.02)), -1);  // into the layers only
  EXPECT_EQ(w.crossed(Vec<3>(0.6, 0.6, 0.01), Vec<3>(0.6, 0.6, -0.05)), -1);  // beyond the long side x + y = 1
  EXPECT_EQ(w.crossed(Vec<3>(0.2, 0.2, -0.06), Vec<3>(0.2, 0.2, -0.02)), -1); // back out from behind
  EXPECT_EQ(WallCrossing<3>().crossed(Vec<3>(0.2, 0.2, 0.01), Vec<3>(0.2, 0.2, -0.05)), -1);
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

// In 3-D a tank's floor and sides and a terrain are checked; a side of symmetry is not a wall (what crosses it comes
// back as its mirror image), nor is the open top. A tank 0.2 m square with a terrain ramp from 0.06 m at x = 0 down
// to 0 at x = 0.2 m, on the fcc lattice (its walls' particles reach re = 2.1 dp behind their faces). Each move is
// shorter than the grid's cell (re), as a step's is.
TEST(LeftTheDomain, In3DAMoveThroughATankOrATerrainIsACrossingAndNotThroughASideOfSymmetry) {
  const auto dir = fresh_directory("through_wall_3d");
  write_file(dir / "ramp.csv", "y\\x,0,0.2\n0,0.06,0\n0.2,0.06,0\n");
  auto scene = build_scene_text<3>("through_wall_3d_scene", fmt::format(R"(dimension: 3
particle_spacing: 0.02
end_time: 0.1
fluid:
  phases: [{{name: water}}]
  regions: [{{type: below_level, level: 0.15}}]
walls:
  - {{type: tank, min: [0, 0, 0], max: [0.2, 0.2, 0.3], symmetry: [y_min]}}
  - {{type: terrain, file: {}/ramp.csv}}
method: {{initial_state: lattice}}
)", dir.string()));
  auto& sim = *scene->simulation;
  const auto& w = sim.wall_crossing;
  const auto inward = [&](int k) { return w.face(k).inward; };
  const int floor = w.crossed(Vec<3>(0.19, 0.1, 0.01), Vec<3>(0.19, 0.1, -0.05));
  ASSERT_GE(floor, 0);
  EXPECT_EQ(inward(floor), Vec<3>(0, 0, 1));
  const int side = w.crossed(Vec<3>(0.19, 0.1, 0.2), Vec<3>(0.25, 0.1, 0.2));
  ASSERT_GE(side, 0);
  EXPECT_EQ(inward(side), Vec<3>(-1, 0, 0));
  EXPECT_EQ(w.crossed(Vec<3>(0.19, 0.1, 0.32), Vec<3>(0.25, 0.1, 0.31)), -1);  // over the side's top
  EXPECT_EQ(w.crossed(Vec<3>(0.1, 0.01, 0.1), Vec<3>(0.1, -0.05, 0.1)), -1);   // across the plane of symmetry
  EXPECT_GE(w.crossed(Vec<3>(0.1, 0.19, 0.1), Vec<3>(0.1, 0.25, 0.1)), 0);     // the other side is a wall
  // The ramp's surface is 0.03 m high at x = 0.1, its back 0.042 m behind it (0.0120 m lower down along the
  // vertical at its slope of 0.3): past it, above the floor's back.
  const int ramp = w.crossed(Vec<3>(0.1, 0.1, 0.01), Vec<3>(0.1, 0.1, -0.02));
  ASSERT_GE(ramp, 0);
  EXPECT_NEAR(inward(ramp)[0], 0.3 / std::sqrt(1.09), 1e-12);
  EXPECT_EQ(w.crossed(Vec<3>(0.1, 0.1, 0.035), Vec<3>(0.1, 0.1, 0.0)), -1);  // into its layers only
  // A whole step: the lowest water particle thrown down at 1000 m/s goes through in one step.
  auto& P = sim.particles();
  std::size_t thrown = P.size();
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::fluid && (thrown == P.size() || P.position[i][2] < P.position[thrown][2])) thrown = i;
  ASSERT_LT(thrown, P.size());
  P.velocity[thrown] = Vec<3>(0.0, 0.0, -1000.0);
  const std::uint32_t id = P.id[thrown];
  const auto bad = sim.step(1e-4, TimeStepLimit::cfl);
  ASSERT_TRUE(bad.has_value());
  EXPECT_EQ(bad->particle, id);
  EXPECT_NE(bad->reason.find("passed through a wall"), std::string::npos) << bad->reason;
  EXPECT_TRUE(sim.left_the_domain().empty());
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace slide::testing
