// Bad input as a user meets it (issue 14): every one exits 2 with a message naming the key, option or path, before
// anything is run or written.
#include <gtest/gtest.h>

#include <set>

#include "cases/scene_geometry.hpp"
#include "tests/cli_helpers.hpp"

namespace slide::testing {
namespace {

namespace fs = std::filesystem;

std::set<std::string> listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(dir)) names.insert(e.path().string());
  return names;
}

void expect_refused(const CommandResult& r, const std::vector<std::string>& said) {
  EXPECT_EQ(r.exit_code, 2) << r.output;
  for (const auto& s : said) EXPECT_NE(r.output.find(s), std::string::npos) << "no \"" << s << "\" in: " << r.output;
}

// An output folder that is a file, lies under a file, or where nothing can be created (/proc): exit 2 naming --out
// and the path, and the folder holding the scene is as it was (nothing written, not even a partial folder).
TEST(BadInput, AnOutputFolderThatCannotBeWrittenIsRefusedBeforeAnythingRuns) {
  const fs::path dir = fresh_directory("bad_out");
  write_file(dir / "scene.yaml", kGoodScene);
  write_file(dir / "afile", "not a folder\n");
  const auto before = listing(dir);
  const std::string run = slide_binary() + " run " + (dir / "scene.yaml").string() + " --quiet --out ";
  expect_refused(run_command(run + (dir / "afile").string()), {"--out", "afile", "is a file, not a folder"});
  expect_refused(run_command(run + (dir / "afile/sub").string()), {"--out", "afile/sub", "is a file, not a folder"});
  expect_refused(run_command(run + "/proc/slide_out"), {"--out", "/proc/slide_out", "cannot create anything in /proc"});
  EXPECT_EQ(listing(dir), before);
  EXPECT_EQ(read_file(dir / "afile"), "not a folder\n");
}

// Command-line values out of range: exit 2 naming the option.
TEST(BadInput, OutOfRangeCommandLineValuesAreRefused) {
  const fs::path dir = fresh_directory("bad_args");
  write_file(dir / "scene.yaml", kGoodScene);
  const std::string scene = (dir / "scene.yaml").string();
  const auto before = listing(dir);
  for (const char* threads : {"0", "-2", "100000", "two"})
    expect_refused(run_command(slide_binary() + " run " + scene + " --quiet --out " + (dir / "out").string() +
                               " --threads " + threads),
                   {"--threads"});
  expect_refused(run_command(slide_binary() + " sweep " + scene + " --jobs 0"), {"--jobs"});
  expect_refused(run_command(slide_binary() + " check " + scene + " --target-error 0 --with " + dir.string()),
                 {"--target-error"});
  EXPECT_EQ(listing(dir), before);
}

// A key given twice, in the scene (top level or nested), in a --set value, by two --set, or in a sweep file: yaml-cpp
// would keep the first silently; slide names the key and both lines.
TEST(BadInput, AKeyGivenTwiceIsRefusedNamingIt) {
  const fs::path dir = fresh_directory("bad_duplicate");
  write_file(dir / "top.yaml", std::string(kGoodScene) + "end_time: 0.02\n");
  write_file(dir / "nested.yaml", std::string(kGoodScene) + "time_step: {cfl: 0.2, cfl: 0.3}\n");
  write_file(dir / "scene.yaml", kGoodScene);
  const std::string check = slide_binary() + " check ";
  expect_refused(run_command(check + (dir / "top.yaml").string()), {"end_time: appears twice (lines 2 and 9)"});
  expect_refused(run_command(check + (dir / "nested.yaml").string()), {"time_step.cfl: appears twice"});
  const std::string scene = (dir / "scene.yaml").string();
  expect_refused(run_command(check + scene + " --set end_time=1 --set end_time=2"), {"end_time is set twice"});
  expect_refused(run_command(check + scene + " --set 'time_step={cfl: 0.1, cfl: 0.2}'"), {"cfl appears twice"});
  write_file(dir / "s.yaml", "scene: scene.yaml\nvary: {particle_spacing: [0.02]}\nvary: {particle_spacing: [0.01]}\n");
  expect_refused(run_command(slide_binary() + " sweep " + (dir / "s.yaml").string() + " --plan-only"),
                 {"vary: appears twice (lines 2 and 3)"});
}

// A scene whose particles would not fit the memory limit (here SLIDE_MEMORY_LIMIT, as a cluster job's share) or
// slide's 2^32 index: exit 2 on particle_spacing, stating the estimate and the limit, before any particle is made.
TEST(BadInput, ASceneThatDoesNotFitTheMemoryIsRefused) {
  const fs::path dir = fresh_directory("bad_memory");
  write_file(dir / "scene.yaml", kGoodScene);
  const std::string check = slide_binary() + " check " + (dir / "scene.yaml").string();
  expect_refused(run_command("SLIDE_MEMORY_LIMIT=50k " + check),
                 {"particle_spacing", "more than the 0.05 MB available (SLIDE_MEMORY_LIMIT)"});
  expect_refused(run_command(check + " --set particle_spacing=1e-6"), {"particle_spacing", "2^32 - 1"});
  // Its particles fit 15 MB, its run does not (some 20 MB at its peak, the program's own 12 MB included): refused on
  // the run's estimate, which slide check prints, once the particles are made and before anything runs.
  expect_refused(run_command("SLIDE_MEMORY_LIMIT=15M " + check),
                 {"particle_spacing", "would need about", "at its peak, more than the 15 MB available"});
  expect_refused(run_command("SLIDE_MEMORY_LIMIT=lots " + check), {"SLIDE_MEMORY_LIMIT"});
  EXPECT_EQ(run_command("SLIDE_MEMORY_LIMIT=1G " + check).exit_code, 0);
}

TEST(BadInput, FluidThatNothingHoldsIsRefusedOnItsRegionUnlessAllowed) {
  const auto dir = fresh_directory("uncontained");
  // The small scene's tank, with a second column of water beside it, over nothing.
  std::string scene = kGoodScene;
  scene.replace(scene.find("regions: [{type: rectangle, min: [0, 0], max: [0.2, 0.2]}]"),
                std::string("regions: [{type: rectangle, min: [0, 0], max: [0.2, 0.2]}]").size(),
                "regions: [{type: rectangle, min: [0, 0], max: [0.2, 0.2]}, "
                "{type: rectangle, min: [0.8, 0.1], max: [0.9, 0.2]}]");
  write_file(dir / "s.yaml", scene);
  const auto r = run_command(slide_binary() + " run " + (dir / "s.yaml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("fluid.regions[1]: "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("have no wall or body below them along gravity"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("checks.allow_uncontained_fluid"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
  const auto allowed = run_command(slide_binary() + " check " + (dir / "s.yaml").string() +
                                   " --set checks.allow_uncontained_fluid=true");
  EXPECT_EQ(allowed.exit_code, 0) << allowed.output;
  std::filesystem::remove_all(dir);
}

TEST(SceneGeometry, ARayMeetsASegmentOnlyAheadOfItAndWithinItsEnds) {
  using cases::ray_meets_segment;
  const Vec<2> down(0, -9.81);
  EXPECT_TRUE(ray_meets_segment(Vec<2>(0.5, 1), down, Vec<2>(0, 0), Vec<2>(1, 0)));
  EXPECT_TRUE(ray_meets_segment(Vec<2>(1, 1), down, Vec<2>(0, 0), Vec<2>(1, 0)));     // at the end
  EXPECT_FALSE(ray_meets_segment(Vec<2>(1.01, 1), down, Vec<2>(0, 0), Vec<2>(1, 0)));  // past the end
  EXPECT_FALSE(ray_meets_segment(Vec<2>(0.5, -1), down, Vec<2>(0, 0), Vec<2>(1, 0)));  // behind the ray
  EXPECT_TRUE(ray_meets_segment(Vec<2>(0.5, 2), down, Vec<2>(0, 0), Vec<2>(1, 1)));    // a slope, at y = 0.5
  EXPECT_TRUE(ray_meets_segment(Vec<2>(0, 2), down, Vec<2>(0, 0), Vec<2>(0, 1)));      // along a vertical wall
  EXPECT_FALSE(ray_meets_segment(Vec<2>(0, 2), down, Vec<2>(0, 3), Vec<2>(0, 4)));     // behind, on its line
  EXPECT_FALSE(ray_meets_segment(Vec<2>(0.5, 2), down, Vec<2>(0, 0), Vec<2>(0, 1)));   // parallel, off the line
}

TEST(BadInput, WaterThatLeavesTheDomainWhileItSettlesIsRefused) {
  // A heap of water at the open end of a floor (held from below, so the scene is not refused for that): settling, it
  // runs off the end and out of the domain, which water at rest does not do. The domain's side 1 dp past the floor's
  // end: the water leaves it (at 0.12 s) before it has moved as far as the check while it settles refuses (stop 65).
  const auto dir = fresh_directory("leaves_while_settling");
  write_file(dir / "s.yaml", R"(particle_spacing: 0.02
end_time: 0.01
fluid:
  phases: [{name: water}]
  regions: [{type: rectangle, min: [0.3, 0], max: [0.6, 0.2]}]
walls:
  - points: [[0, 0.4], [0, 0], [0.6, 0]]
domain: {min: [-0.1, -0.1], max: [0.62, 0.5]}
method: {initial_state: settled, settling_time: 1.5}
)");
  const auto r = run_command(slide_binary() + " run " + (dir / "s.yaml").string() + " --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("method.initial_state: "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("left the domain while the water settled"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace slide::testing
namespace slide::testing {
namespace {

// Issue 30's smaller ones: each exits 2 naming the option or key, and nothing is written.
TEST(BadInput, FoldersThatAreNotASweepsAreRefused) {
  const fs::path dir = fresh_directory("bad_sweep_folders");
  write_file(dir / "scene.yaml", kGoodScene);
  write_file(dir / "sweep.yaml", "scene: scene.yaml\nvary: {end_time: [0.01, 0.02]}\n");
  write_file(dir / "afile", "x\n");
  fs::create_directories(dir / "empty");
  fs::create_directories(dir / "broken");
  write_file(dir / "broken" / "plan.json", "{");
  const auto before = listing(dir);
  const std::string sweep = slide_binary() + " sweep ";
  expect_refused(run_command(sweep + (dir / "sweep.yaml").string() + " --plan-only --out " + (dir / "afile").string()),
                 {"--out", "afile", "is a file, not a folder"});
  expect_refused(run_command(sweep + "--collect " + (dir / "missing").string()), {"--collect", "does not exist"});
  expect_refused(run_command(sweep + "--collect " + (dir / "afile").string()), {"--collect", "is not a folder"});
  expect_refused(run_command(sweep + "--collect " + (dir / "empty").string()),
                 {"--collect", "is not a sweep folder: it has no plan.json"});
  expect_refused(run_command(sweep + "--collect " + (dir / "broken").string()), {"--collect", "plan.json", "parse"});
  EXPECT_EQ(listing(dir), before);
}

TEST(BadInput, StopAtThatIsNotATimeIsRefused) {
  const fs::path dir = fresh_directory("bad_stop_at");
  write_file(dir / "scene.yaml", kGoodScene);
  for (const char* t : {"nan", "-1", "soon"})
    expect_refused(run_command(slide_binary() + " run " + (dir / "scene.yaml").string() + " --quiet --out " +
                               (dir / "out").string() + " --stop-at " + t),
                   {"--stop-at", "must be a time >= 0 s"});
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// A combination given twice would run twice; a grid of 10^7 runs is refused from its lists' lengths at once (it
// spent hours being checked run by run), unless max_runs is raised.
TEST(BadInput, SweepsThatRepeatARunOrExceedMaxRunsAreRefused) {
  const fs::path dir = fresh_directory("bad_sweep_runs");
  write_file(dir / "scene.yaml", kGoodScene);
  const auto plan = [&](const std::string& name, const std::string& text) {
    write_file(dir / name, "scene: scene.yaml\n" + text);
    return run_command(slide_binary() + " sweep " + (dir / name).string() + " --plan-only --out " +
                       (dir / ("out_" + name)).string());
  };
  expect_refused(plan("grid.yaml", "vary: {end_time: [0.01, 0.02, 0.01]}\n"),
                 {"vary.end_time: value 0.01 appears twice"});
  expect_refused(plan("list.yaml", "combinations: [{end_time: 0.01}, {end_time: 0.02}, {end_time: 0.01}]\n"),
                 {"combinations[2]: is combinations[0] again"});
  std::string huge = "vary:\n";
  for (int k = 0; k < 7; ++k)
    huge += "  " + std::string(k < 1 ? "end_time" : "particle_spacing") + (k < 2 ? "" : std::to_string(k)) +
            ": [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]\n";
  expect_refused(plan("huge.yaml", huge), {"vary: stands for 10000000 runs, more than max_runs (1000)"});
  expect_refused(plan("two.yaml", "max_runs: 1\nvary: {end_time: [0.01, 0.02]}\n"),
                 {"vary: stands for 2 runs, more than max_runs (1)"});
  expect_refused(plan("zero.yaml", "max_runs: 0\nvary: {end_time: [0.01]}\n"), {"max_runs: must be a whole number"});
  const auto raised = plan("raised.yaml", "max_runs: 2\nvary: {end_time: [0.01, 0.02]}\n");
  EXPECT_EQ(raised.exit_code, 0) << raised.output;
  for (const char* refused : {"grid", "list", "huge", "two", "zero"})
    EXPECT_FALSE(fs::exists(dir / (std::string("out_") + refused + ".yaml")));
}

}  // namespace
}  // namespace slide::testing
