// `slide sweep` (tools/sweep/): expansion of a sweep file, a tiny dam-break sweep end to end (runs, outcomes, resume,
// --collect from copied run folders, jobs.txt), and a bad sweep refused before anything is written.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <set>

#include "cases/csv_table.hpp"
#include "cases/schema.hpp"
#include "tests/cli_helpers.hpp"
#include "tools/sweep/sweep_file.hpp"

namespace slide::testing {
namespace {

namespace fs = std::filesystem;

std::string dam_break_scene() { return (source_dir() / "cases/dam_break_2d.yaml").string(); }
std::string martin_moyce() { return (source_dir() / "cases/reference/martin_moyce_1952_surge_front.csv").string(); }

TEST(SweepFile, AGridVariesTheLastKeyFastestAndChecksEveryRun) {
  const fs::path dir = fresh_directory("sweep_grid");
  write_file(dir / "s.yaml", fmt::format(R"(scene: {}
set: {{end_time: 0.01}}
vary:
  particle_spacing: [0.01, 0.005]
  method.gradient: [symmetric, variational, difference]
  gravity: [[0, -9.81]]
)",
                                         dam_break_scene()));
  const tools::Sweep s = tools::load_sweep(dir / "s.yaml");
  EXPECT_EQ(s.name, "s");
  ASSERT_EQ(s.runs.size(), 6u);
  EXPECT_EQ(s.varied_keys, (std::vector<std::string>{"particle_spacing", "method.gradient", "gravity"}));
  EXPECT_EQ(s.runs[0].name, "run_001");
  EXPECT_EQ(s.runs[0].values, (std::vector<std::string>{"0.01", "symmetric", "[0, -9.81]"}));
  EXPECT_EQ(s.runs[1].values[1], "variational");
  EXPECT_EQ(s.runs[3].values[0], "0.005");
  EXPECT_EQ(s.runs[5].overrides, (std::vector<std::string>{"end_time=0.01", "particle_spacing=0.005",
                                                           "method.gradient=difference", "gravity=[0, -9.81]"}));
  EXPECT_EQ(s.error.measure, tools::ErrorMeasure::none);
}

TEST(SweepFile, CombinationsKeepTheBaseValueWhereARunDoesNotNameAKey) {
  const fs::path dir = fresh_directory("sweep_list");
  write_file(dir / "s.yaml", fmt::format(R"(scene: {}
combinations:
  - {{particle_spacing: 0.01}}
  - {{method.gradient: variational, particle_spacing: 0.005}}
)",
                                         dam_break_scene()));
  const tools::Sweep s = tools::load_sweep(dir / "s.yaml");
  ASSERT_EQ(s.runs.size(), 2u);
  EXPECT_EQ(s.varied_keys, (std::vector<std::string>{"particle_spacing", "method.gradient"}));
  EXPECT_EQ(s.runs[0].values, (std::vector<std::string>{"0.01", ""}));
  EXPECT_EQ(s.runs[0].overrides, (std::vector<std::string>{"particle_spacing=0.01"}));
  EXPECT_EQ(s.runs[1].values, (std::vector<std::string>{"0.005", "variational"}));
}

TEST(SweepFile, ABadValueIsRefusedNamingTheKeyAndTheRun) {
  const fs::path dir = fresh_directory("sweep_bad");
  write_file(dir / "s.yaml", fmt::format("scene: {}\nvary: {{method.gradient: [symmetric, sideways]}}\n",
                                         dam_break_scene()));
  try {
    tools::load_sweep(dir / "s.yaml");
    FAIL() << "no error";
  } catch (const cases::SceneError& e) {
    EXPECT_EQ(e.key_path, "method.gradient");
    EXPECT_NE(e.message.find("run_002"), std::string::npos) << e.message;
  }
  write_file(dir / "t.yaml", fmt::format("scene: {}\nvary: {{particle_spacing: [0.01]}}\nerror: {{measure: x}}\n",
                                         dam_break_scene()));
  EXPECT_THROW(tools::load_sweep(dir / "t.yaml"), cases::SceneError);
}

// The stability map's panels: a varied key, or none (one panel); anything else is refused naming the key.
TEST(SweepFile, MapPanelsAreAVariedKeyOrNone) {
  const fs::path dir = fresh_directory("sweep_panels");
  const std::string base = fmt::format("scene: {}\nvary: {{particle_spacing: [0.01, 0.02], method.gradient: [pmin]}}\n",
                                       dam_break_scene());
  write_file(dir / "s.yaml", base + "plots: {map: {x: particle_spacing, y: method.gradient, panels: none}}\n");
  EXPECT_EQ(tools::load_sweep(dir / "s.yaml").plots.map_panels, "none");
  write_file(dir / "t.yaml", base + "plots: {map: {panels: lattice}}\n");
  try {
    tools::load_sweep(dir / "t.yaml");
    FAIL() << "no error";
  } catch (const cases::SceneError& e) {
    EXPECT_EQ(e.key_path, "plots.map.panels");
  }
}

// Four runs of the dam break at a/5 and a/10 (about a second each): the symmetric gradient completes, the standard
// one (seed eq. 3) goes unstable; with a threshold of 8 % a completed run is `inaccurate` or `completed` by its error.
TEST(Sweep, ATinyDamBreakSweepRunsResumesAndCollects) {
  const fs::path dir = fresh_directory("sweep_tiny");
  write_file(dir / "tiny.yaml", fmt::format(R"(scene: {}
set: {{end_time: 0.17, output.snapshots: false}}
vary:
  particle_spacing: [0.011430, 0.005715]
  method.gradient: [symmetric, standard]
error: {{measure: dam_break_front, reference: {}, threshold: 0.08}}
)",
                                            dam_break_scene(), martin_moyce()));
  const std::string sweep = slide_binary() + " sweep " + (dir / "tiny.yaml").string() + " --jobs 2 --out ";
  const fs::path out = dir / "out";
  CommandResult r = run_command(sweep + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;

  const CsvTable t = read_csv(out / "results.csv");
  EXPECT_EQ(t.header, (std::vector<std::string>{"run", "particle_spacing", "method.gradient", "outcome", "particles",
                                                "steps", "setup_seconds", "wall_seconds", "cpu_seconds",
                                                "loop_cpu_seconds", "particle_steps_per_second", "error",
                                                "largest_number_density_ratio", "failure_time", "failure_check",
                                                "note"}));
  ASSERT_EQ(t.rows.size(), 4u);
  const auto cell = [&](int row, const std::string& column) { return t.rows[row].at(t.column(column)); };
  // The completed runs' front errors are chaotic at the 1 % level: at a/10, changing c0 by 1e-7 of itself gave 7.3,
  // 7.5, 7.5 and 9.0 % (stop 24, with the same binary). So the outcome must follow the error and the threshold, and
  // the error lie in that band, rather than equal a figure measured once (a/5 measured 8.9 %, a/10 7.5 % at stop 20).
  for (const int row : {0, 2}) {
    const double error = std::stod(cell(row, "error"));
    EXPECT_EQ(cell(row, "outcome"), error > 0.08 ? "inaccurate" : "completed") << error;
    EXPECT_GT(error, 0.06);
    EXPECT_LT(error, 0.11);
  }
  for (const int row : {1, 3}) {
    EXPECT_EQ(cell(row, "outcome"), "unstable");
    EXPECT_GT(std::stod(cell(row, "failure_time")), 0.0);
    EXPECT_LT(std::stod(cell(row, "failure_time")), 0.17);
    EXPECT_NE(cell(row, "failure_check").find("number-density collapse"), std::string::npos);
    EXPECT_EQ(cell(row, "error"), "");
    // The collapse the check found is the run's largest compression (the scene's checks.max_number_density_ratio).
    EXPECT_GT(std::stod(cell(row, "largest_number_density_ratio")), 1.5);
  }
  for (const int row : {0, 2}) {  // completed: compressed, never as far as a collapse
    EXPECT_GT(std::stod(cell(row, "largest_number_density_ratio")), 1.0);
    EXPECT_LT(std::stod(cell(row, "largest_number_density_ratio")), 1.5);
  }
  for (int row = 0; row < 4; ++row) {
    EXPECT_GT(std::stod(cell(row, "particles")), 0.0);
    EXPECT_GT(std::stod(cell(row, "cpu_seconds")), 0.0);
  }

  // The charts (tools/plot_sweep.py; CI installs Debian's python3-matplotlib): PNG files.
  for (const char* png : {"accuracy_cost.png", "stability_map.png"})
    EXPECT_EQ(read_file(out / png).substr(0, 8), "\x89PNG\r\n\x1a\n") << png << "\n" << r.output;

  // jobs.txt: one shell command per run.
  const std::string jobs = read_file(out / "jobs.txt");
  EXPECT_EQ(std::count(jobs.begin(), jobs.end(), '\n'), 4);
  EXPECT_NE(jobs.find("--out '" + fs::absolute(out / "runs" / "run_004").string() + "'"), std::string::npos) << jobs;

  // Resume: only the run whose folder is gone runs again; the results are the same.
  const auto first_run_time = fs::last_write_time(out / "runs/run_001/run.json");
  fs::remove_all(out / "runs/run_003");
  r = run_command(sweep + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("3 finished already, 1 to run"), std::string::npos) << r.output;
  EXPECT_EQ(fs::last_write_time(out / "runs/run_001/run.json"), first_run_time);
  const CsvTable again = read_csv(out / "results.csv");
  for (int row = 0; row < 4; ++row) {
    EXPECT_EQ(again.rows[row][t.column("outcome")], t.rows[row][t.column("outcome")]);
    EXPECT_EQ(again.rows[row][t.column("error")], t.rows[row][t.column("error")]);  // bit-identical runs
  }

  // --collect from run folders copied elsewhere gives the same table.
  const fs::path elsewhere = dir / "elsewhere";
  fs::create_directories(elsewhere);
  fs::copy(out / "runs", elsewhere / "runs", fs::copy_options::recursive);
  fs::copy(out / "plan.json", elsewhere / "plan.json");
  r = run_command(slide_binary() + " sweep --collect " + elsewhere.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(read_file(elsewhere / "results.csv"), read_file(out / "results.csv"));

  // slide check --target-error E --with DIR: the cheapest run within E, and its cost scaled to the checked scene.
  // E just above the a/10 run's error: that run is within it, and the a/5 run (run_001, cheaper) only if its own
  // error is no larger.
  const double error_a5 = std::stod(cell(0, "error")), error_a10 = std::stod(cell(2, "error"));
  const double target = error_a10 + 0.001;
  const std::string cheapest = error_a5 <= target ? "run_001 (" : "run_003 (particle_spacing=0.005715 method.gradient=symmetric)";
  const std::string check = slide_binary() + " check " + dam_break_scene() + " --with " + out.string();
  r = run_command(check + fmt::format(" --target-error {:.6f}", target));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("cheapest within it: " + cheapest), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("this scene with those settings"), std::string::npos) << r.output;
  r = run_command(check + " --target-error 0.01");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find(fmt::format("no run is within it; the smallest error measured is {:.4g}",
                                      std::min(error_a5, error_a10))),
            std::string::npos)
      << r.output;
  EXPECT_EQ(run_command(slide_binary() + " check " + dam_break_scene() + " --target-error 0.01").exit_code, 2);
}

// A combination the scene builder refuses (the mirror wall model on the hexagonal lattice) is `invalid`, with the
// run's own message; the sweep goes on and exits 0.
TEST(Sweep, ARefusedCombinationIsInvalidWithItsMessage) {
  const fs::path dir = fresh_directory("sweep_invalid");
  write_file(dir / "s.yaml", fmt::format(R"(scene: {}
set: {{end_time: 0.001, output.snapshots: false}}
combinations:
  - {{particle_spacing: 0.011430}}
  - {{particle_spacing: 0.011430, lattice: hexagonal, method.wall_pressure: mirror, method.initial_state: settled}}
)",
                                         dam_break_scene()));
  const CommandResult r = run_command(slide_binary() + " sweep " + (dir / "s.yaml").string() + " --out " +
                                      (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const CsvTable t = read_csv(dir / "out/results.csv");
  ASSERT_EQ(t.rows.size(), 2u);
  EXPECT_EQ(t.rows[0][t.column("outcome")], "completed");
  EXPECT_EQ(t.rows[1][t.column("outcome")], "invalid");
  EXPECT_NE(t.rows[1][t.column("note")].find("method.wall_pressure"), std::string::npos) << t.rows[1][t.column("note")];
}

// Still water that goes unstable while it settles (the difference gradient behind the gated dam break's gate, at
// a/10: n/n0 passes 1.5 at 0.165 s of settling) is `unstable` with the settling time and the check, not `invalid`:
// the method fails on this scene.
TEST(Sweep, AMethodThatGoesUnstableWhileSettlingIsUnstable) {
  const fs::path dir = fresh_directory("sweep_settling");
  write_file(dir / "s.yaml", fmt::format(R"(scene: {}
set: {{particle_spacing: 0.011430, end_time: 0.001, output.snapshots: false}}
vary:
  method.gradient: [difference]
)",
                                         (source_dir() / "cases/dam_break_gated_2d.yaml").string()));
  const CommandResult r = run_command(slide_binary() + " sweep " + (dir / "s.yaml").string() + " --out " +
                                      (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const CsvTable t = read_csv(dir / "out/results.csv");
  ASSERT_EQ(t.rows.size(), 1u);
  const auto& row = t.rows[0];
  EXPECT_EQ(row[t.column("outcome")], "unstable");
  EXPECT_NEAR(std::stod(row[t.column("failure_time")]), 0.165098, 1e-6);
  EXPECT_NE(row[t.column("failure_check")].find("number-density collapse"), std::string::npos);
  EXPECT_NE(row[t.column("note")].find("while settling"), std::string::npos);

  // The refusal is recorded in the run's folder: resuming does not settle it again, and --collect from the run
  // folders alone (no logs) classifies it the same.
  const CommandResult again = run_command(slide_binary() + " sweep " + (dir / "s.yaml").string() + " --out " +
                                          (dir / "out").string());
  ASSERT_EQ(again.exit_code, 0) << again.output;
  EXPECT_NE(again.output.find("1 finished already, 0 to run"), std::string::npos) << again.output;
  const fs::path elsewhere = dir / "elsewhere";
  fs::create_directories(elsewhere);
  fs::copy(dir / "out/runs", elsewhere / "runs", fs::copy_options::recursive);
  fs::copy(dir / "out/plan.json", elsewhere / "plan.json");
  ASSERT_EQ(run_command(slide_binary() + " sweep --collect " + elsewhere.string()).exit_code, 0);
  EXPECT_EQ(read_file(elsewhere / "results.csv"), read_file(dir / "out/results.csv"));
}

// A run folder made with other settings (the sweep file was edited since) is not taken as finished: it runs again.
TEST(Sweep, AnEditedSweepRunsAgainWhatChanged) {
  const fs::path dir = fresh_directory("sweep_edited");
  const auto write = [&](const std::string& spacings) {
    write_file(dir / "s.yaml", fmt::format("scene: {}\nset: {{end_time: 0.005, output.snapshots: false}}\n"
                                           "vary: {{particle_spacing: [{}]}}\n",
                                           dam_break_scene(), spacings));
  };
  const std::string sweep = slide_binary() + " sweep " + (dir / "s.yaml").string() + " --out " + (dir / "out").string();
  write("0.011430, 0.005715");
  ASSERT_EQ(run_command(sweep).exit_code, 0);
  write("0.011430, 0.008");  // run_002 now means something else
  const CommandResult r = run_command(sweep);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("1 finished already, 1 to run"), std::string::npos) << r.output;
  const CsvTable t = read_csv(dir / "out/results.csv");
  EXPECT_EQ(t.rows[1][t.column("particle_spacing")], "0.008");
  EXPECT_EQ(t.rows[1][t.column("outcome")], "completed");
}

TEST(Sweep, ABadSweepExitsTwoAndWritesNothing) {
  const fs::path dir = fresh_directory("sweep_refused");
  write_file(dir / "s.yaml", fmt::format("scene: {}\nvary: {{particle_spacing: [-1]}}\n", dam_break_scene()));
  const CommandResult r = run_command(slide_binary() + " sweep " + (dir / "s.yaml").string() + " --out " +
                                      (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("particle_spacing"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
  EXPECT_EQ(run_command(slide_binary() + " sweep --collect " + (dir / "nowhere").string()).exit_code, 2);  // issue 30
  // Wrong YAML types exit 2 naming the key, not an exception's text.
  write_file(dir / "t.yaml", "scene: [a, b]\nvary: {particle_spacing: [0.01]}\n");
  const CommandResult t = run_command(slide_binary() + " sweep " + (dir / "t.yaml").string() + " --out " +
                                      (dir / "out").string());
  EXPECT_EQ(t.exit_code, 2) << t.output;
  EXPECT_NE(t.output.find("scene: must be a single value"), std::string::npos) << t.output;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
}  // namespace slide::testing
