// The command line as a user meets it: bad scenes exit 2 naming the key, unstable runs exit 3 leaving a readable
// snapshot, Ctrl-C exits 130 with a snapshot, and results do not depend on the thread count.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <nlohmann/json.hpp>
#include <thread>

#include "cases/csv_table.hpp"
#include "tests/cli_helpers.hpp"

namespace slide::testing {
namespace {

namespace fs = std::filesystem;

CommandResult check_scene(const std::string& text, const std::string& extra = "") {
  const fs::path dir = fresh_directory("scene");
  write_file(dir / "scene.yaml", text);
  return run_command(slide_binary() + " check " + (dir / "scene.yaml").string() + " " + extra);
}

void expect_invalid(const CommandResult& r, const std::string& key, const std::string& what) {
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(key), std::string::npos) << "message does not name " << key << ": " << r.output;
  EXPECT_NE(r.output.find(what), std::string::npos) << "message does not say " << what << ": " << r.output;
}

TEST(Cli, GoodSceneChecks) {
  const CommandResult r = check_scene(kGoodScene);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  // The 10 dp x 10 dp column holds the hexagonal lattice's points whose centre lies inside: rows 0.9306 dp apart
  // from 0.465 dp (11 rows up to 9.77 dp), columns 1.0746 dp apart (9 in each row), so 99 for its 100 dp^2.
  EXPECT_NE(r.output.find(": 99 fluid"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("10 sqrt(g H)"), std::string::npos) << r.output;
}

TEST(Cli, UnknownKey) { expect_invalid(check_scene(std::string(kGoodScene) + "end_tme: 1\n"), "end_tme", "unknown key"); }

TEST(Cli, MissingKey) {
  std::string s = kGoodScene;
  s.erase(0, s.find('\n') + 1);  // drop particle_spacing
  expect_invalid(check_scene(s), "particle_spacing", "missing required key");
}

TEST(Cli, WrongType) {
  expect_invalid(check_scene(kGoodScene, "--set particle_spacing=abc"), "particle_spacing", "expected a number");
}

TEST(Cli, OutOfRange) {
  expect_invalid(check_scene(kGoodScene, "--set method.kernel_radius=9"), "method.kernel_radius", "out of range");
}

TEST(Cli, WaterOverlappingWall) {
  expect_invalid(check_scene(kGoodScene, "--set 'fluid.regions[0].min=[-0.1, 0]'"), "fluid.regions[0]",
                 "water overlaps walls[0]");
}

TEST(Cli, EmptyRegion) {
  expect_invalid(check_scene(kGoodScene, "--set 'fluid.regions[0].max=[0.01, 0.01]'"), "fluid.regions[0]",
                 "holds no particle");
}

TEST(Cli, WaterInsideABody) {
  // The block covers part of the water rectangle: explicit regions must keep clear of bodies.
  expect_invalid(check_scene(std::string(kGoodScene) + "bodies:\n  - {name: block, shape: {type: box, center: [0.1, "
                                                        "0.15], size: [0.1, 0.1]}, density: 500}\n"),
                 "fluid.regions[0]", "inside body bodies[0]");
}

TEST(Cli, BodyNeedsDensityOrMass) {
  expect_invalid(check_scene(std::string(kGoodScene) + "bodies:\n  - {name: block, shape: {type: box, center: [0.4, "
                                                        "0.3], size: [0.1, 0.1]}}\n"),
                 "bodies[0].density", "exactly one of density and mass");
}

TEST(Cli, BodyOutlineMustBeConvex) {
  expect_invalid(check_scene(std::string(kGoodScene) + "bodies:\n  - {name: block, density: 500, shape: {type: "
                                                        "polygon, points: [[0.3, 0.3], [0.5, 0.3], [0.4, 0.32], "
                                                        "[0.4, 0.4]]}}\n"),
                 "bodies[0].shape", "convex");
}

// A 0.2 m x 0.1 m block of 500 kg/m^3 at its draft in 0.3 m of water, its bottom half a spacing above a row.
const char* kFloatingBlockScene = R"(particle_spacing: 0.01
end_time: 0.01
fluid:
  phases: [{name: water}]
  regions: [{type: below_level, level: 0.3}]
walls:
  - points: [[0, 0.5], [0, 0], [1.0, 0], [1.0, 0.5]]
bodies:
  - {name: block, shape: {type: box, center: [0.5, 0.3], size: [0.2, 0.1]}, density: 500}
)";

TEST(Cli, CheckReportsBodyMassAndBuoyancy) {
  const CommandResult r = check_scene(kFloatingBlockScene);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("mass            10 kg/m (lattice sum 10)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("displaced below the still-water level 0.01 m^2, buoyancy / weight 1"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("2878 fluid"), std::string::npos) << r.output;  // the block's volume is left dry
}

// The mean gap between a body's faces and its water at t = 0, in dp, from slide check's "water gap" line.
double reported_water_gap(const CommandResult& r) {
  const std::size_t at = r.output.find("water gap");
  if (at == std::string::npos) {
    ADD_FAILURE() << "no water gap line: " << r.output;
    return NAN;
  }
  return std::stod(r.output.substr(at + std::string("water gap").size()));
}

// slide check says how far the water stands off a body. On the hexagonal lattice (the default) the rows are moved
// to meet the block's bottom, so the water meets it wherever it is put (measured +0.036 and +0.035 dp). On the
// square lattice, a block whose bottom lies half a spacing above a row has its water there (measured +0.028 dp: the
// edge measure's own offset); lowered by 0.3 dp, the row under it is closer than dp/2 and left out, and the water
// stands 0.6 dp off (measured +0.608).
TEST(Cli, CheckReportsTheWaterGapAtABodysFaces) {
  const std::string lowered = " --set bodies[0].shape.center=[0.5,0.297]";
  for (const std::string& where : {std::string(), lowered}) {
    const CommandResult r = check_scene(kFloatingBlockScene, where);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NEAR(reported_water_gap(r), 0.035, 0.02) << where;
  }
  const std::string square = " --set lattice=square --set method.initial_state=hydrostatic";
  const CommandResult on_row = check_scene(kFloatingBlockScene, square);
  EXPECT_EQ(on_row.exit_code, 0) << on_row.output;
  EXPECT_NEAR(reported_water_gap(on_row), 0.03, 0.01);
  const CommandResult off_row = check_scene(kFloatingBlockScene, square + lowered);
  EXPECT_EQ(off_row.exit_code, 0) << off_row.output;
  EXPECT_NEAR(reported_water_gap(off_row), 0.61, 0.03);
}

TEST(Cli, BadOverride) { expect_invalid(check_scene(kGoodScene, "--set nonsense"), "--set", "="); }

TEST(Cli, RunOfInvalidSceneWritesNothing) {
  const fs::path out = fresh_directory("invalid_out") / "run";
  const fs::path dir = fresh_directory("invalid_scene");
  write_file(dir / "scene.yaml", std::string(kGoodScene) + "bogus: 1\n");
  const CommandResult r = run_command(slide_binary() + " run " + (dir / "scene.yaml").string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

// Reads the time attribute of the last snapshot through particles.h5 (its external links).
double last_snapshot_time(const fs::path& out, int& count) {
  const hid_t file = H5Fopen((out / "particles.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) return -1.0;
  const hid_t times = H5Dopen2(file, "/times", H5P_DEFAULT);
  const hid_t space = H5Dget_space(times);
  hsize_t n = 0;
  H5Sget_simple_extent_dims(space, &n, nullptr);
  std::vector<double> t(n);
  H5Dread(times, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, t.data());
  // The last snapshot's pressure dataset must be readable too.
  char name[64];
  std::snprintf(name, sizeof name, "/snapshots/%06d/pressure", static_cast<int>(n) - 1);
  const hid_t pressure = H5Dopen2(file, name, H5P_DEFAULT);
  const bool readable = pressure >= 0;
  if (readable) H5Dclose(pressure);
  H5Sclose(space);
  H5Dclose(times);
  H5Fclose(file);
  count = static_cast<int>(n);
  return readable && n > 0 ? t.back() : -1.0;
}

TEST(Cli, UnstableRunExits3WithSnapshot) {
  const fs::path out = fresh_directory("unstable");
  // A sound speed far too low for the water depth (10 sqrt(g H) would be 10.6 m/s): the water collapses into
  // itself. (The hydrostatic start itself would already refuse it, with exit 2, so start from the lattice.)
  const CommandResult r = run_command(slide_binary() + " run " + (source_dir() / "cases/dam_break_2d.yaml").string() +
                                      " --out " + out.string() +
                                      " --quiet --set method.sound_speed=0.3 --set method.initial_state=lattice");
  ASSERT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("unstable at t ="), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("particle"), std::string::npos) << r.output;
  const auto run = nlohmann::json::parse(read_file(out / "run.json"));
  EXPECT_EQ(run["status"], "unstable");
  const double failed_at = run["instability"]["time"];
  int count = 0;
  const double t = last_snapshot_time(out, count);
  EXPECT_GE(count, 2);
  EXPECT_GE(t, 0.0);
  EXPECT_LT(t, failed_at);
  EXPECT_DOUBLE_EQ(t, run["instability"]["last_good_time"].get<double>());
}

TEST(Cli, StandardGradientIsUnstableInTheDamBreak) {
  const fs::path out = fresh_directory("standard");
  const CommandResult r = run_command(slide_binary() + " run " + (source_dir() / "cases/dam_break_2d.yaml").string() +
                                      " --out " + out.string() + " --quiet --set method.gradient=standard");
  EXPECT_EQ(r.exit_code, 3) << r.output;
  EXPECT_NE(r.output.find("unstable at t = 0.01"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("last good snapshot"), std::string::npos) << r.output;
  int count = 0;
  EXPECT_GE(last_snapshot_time(out, count), 0.0);
}

TEST(Cli, InterruptWritesFinalSnapshot) {
  const fs::path out = fresh_directory("sigint");
  const std::string scene = (source_dir() / "cases/dam_break_2d.yaml").string();
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    const std::string bin = slide_binary(), out_s = out.string();
    ::freopen("/dev/null", "w", stderr);
    execl(bin.c_str(), bin.c_str(), "run", scene.c_str(), "--out", out_s.c_str(), "--quiet", "--set",
          "particle_spacing=0.000714375", static_cast<char*>(nullptr));
    _exit(127);
  }
  // Wait until the run has written its initial snapshot, then interrupt it.
  for (int i = 0; i < 600 && !fs::exists(out / "run.json"); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));
  kill(pid, SIGINT);
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  const auto run = nlohmann::json::parse(read_file(out / "run.json"));
  EXPECT_EQ(run["status"], "interrupted");
  int count = 0;
  EXPECT_GT(last_snapshot_time(out, count), 0.0);
  EXPECT_EQ(count, 2);  // the initial snapshot and the final one
}

// The same scene with 1 and 2 threads: every output file identical byte for byte. The still tank has enough
// particles (5558) for its loops to run in parallel (fluid/parallel.hpp runs short loops on one thread).
TEST(Cli, OneAndTwoThreadsGiveIdenticalFiles) {
  const std::string scene = (source_dir() / "cases/hydrostatic_2d.yaml").string();
  // Both free-surface pressures: the extrapolated one is a pass of its own (fluid/free_surface_pressure.hpp).
  for (const std::string surface : {"zero", "extrapolated"}) {
    std::vector<fs::path> outs;
    for (int threads : {1, 2}) {
      const fs::path out = fresh_directory("threads" + std::to_string(threads) + surface);
      const CommandResult r =
          run_command(slide_binary() + " run " + scene + " --out " + out.string() + " --quiet --threads " +
                      std::to_string(threads) +
                      " --set end_time=0.06 --set output.snapshot_interval=0.02 --set method.settling_time=0.05" +
                      " --set method.surface_pressure=" + surface);
      ASSERT_TRUE(fs::exists(out / "gauges.csv"));
      ASSERT_EQ(r.exit_code, 0) << r.output;
      outs.push_back(out);
    }
    std::vector<fs::path> files{"gauges.csv", "particles.h5", "particles.xdmf"};
    for (const auto& entry : fs::directory_iterator(outs[0] / "snapshots")) files.push_back(fs::path("snapshots") / entry.path().filename());
    EXPECT_EQ(files.size(), 7u);  // 4 snapshots: t = 0, 0.02, 0.04, 0.06
    for (const auto& f : files) {
      const std::string a = read_file(outs[0] / f), b = read_file(outs[1] / f);
      EXPECT_FALSE(a.empty()) << f;
      EXPECT_TRUE(a == b) << f << " differs between 1 and 2 threads, surface pressure " << surface;
    }
  }
}

// A run whose end time falls on the sample schedule samples it once: every time in gauges.csv and in bodies.csv
// (one body) comes once, in increasing order, and the last is the end time. (Before, gauges.csv had the end twice.)
TEST(Cli, TheEndTimeIsSampledOnce) {
  const fs::path out = fresh_directory("sampled_once");
  const CommandResult r = run_command(
      slide_binary() + " run " + (source_dir() / "cases/floating_block_2d.yaml").string() + " --out " + out.string() +
      " --quiet --set particle_spacing=0.02 --set method.settling_time=0.05 --set end_time=0.02" +
      " --set output.snapshots=false --set output.gauge_interval=0.01 --set output.body_interval=0.01");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const std::string file : {"gauges.csv", "bodies.csv"}) {
    const auto times = read_csv(out / file).numbers("time");
    ASSERT_GE(times.size(), 3u) << file;
    for (std::size_t k = 1; k < times.size(); ++k) EXPECT_LT(times[k - 1], times[k]) << file << " row " << k;
    EXPECT_NEAR(times.back(), 0.02, 1e-12) << file;
  }
}

}  // namespace
}  // namespace slide::testing
