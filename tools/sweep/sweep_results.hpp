#pragma once
// A sweep's results: one row per run read back from its folder (run.json and the outputs its error measure needs).
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "fluid/name_table.hpp"
#include "tools/measures/wave_signature.hpp"
#include "tools/sweep/sweep_file.hpp"

namespace slide::tools {

// completed: ran to its end time (and, with a threshold, its error is within it); inaccurate: completed with an error
// above the sweep's threshold; unstable: stopped by an instability check (exit 3), or its still water went unstable
// while it settled (exit 2 on method.initial_state; note "while settling"); invalid: its scene was refused
// (exit 2: a combination the method does not allow, as the mirror wall model on the hexagonal lattice); interrupted:
// stopped by a signal or still running; failed: exited otherwise (a crash, killed: its exit code in the note);
// missing: no run.json of this run's settings (not run yet, not copied back, or made by an earlier version of the
// sweep file with other settings).
enum class RunOutcome { completed, inaccurate, unstable, invalid, interrupted, failed, missing };

inline constexpr auto run_outcome_names = make_name_table<RunOutcome>(
    std::pair{RunOutcome::completed, "completed"}, std::pair{RunOutcome::inaccurate, "inaccurate"},
    std::pair{RunOutcome::unstable, "unstable"}, std::pair{RunOutcome::invalid, "invalid"},
    std::pair{RunOutcome::interrupted, "interrupted"}, std::pair{RunOutcome::failed, "failed"},
    std::pair{RunOutcome::missing, "missing"});

struct RunResult {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  std::string name;
  std::vector<std::string> values;  // of the varied keys
  RunOutcome outcome = RunOutcome::missing;
  double particles = nan, steps = nan;
  double setup_seconds = nan, wall_seconds = nan, particle_steps_per_second = nan;
  double cpu_seconds = nan, loop_cpu_seconds = nan;  // the whole process's, and the step loop's
  double error = nan;         // the sweep's measure; NaN without one or where it could not be computed
  double largest_number_density_ratio = nan;  // the run's largest n / n0 of any fluid particle (its compression)
  double failure_time = nan;  // s, unstable runs
  std::string failure_check;  // unstable runs: the check that fired
  std::string note;           // why the error is missing, or why the run was refused
};

// A refused run's record (refused.json in its folder: its overrides and the refusal's last line without the scene's
// name), written by the sweep when a run exits 2. The run itself writes nothing, and a refusal after settling (still
// water that went unstable or moved) costs the whole settling time: resuming does not run it again.
void write_refusal(const Sweep& sweep, const SweepRun& run, const std::filesystem::path& run_folder,
                   const std::filesystem::path& log_file);

// Whether a run's folder holds a finished run of these settings (completed, unstable or refused: running it again
// gives the same). A run.json or refused.json whose overrides differ (the sweep file was edited) is not this run's.
bool run_is_finished(const std::filesystem::path& run_folder, const SweepRun& run);

// A run's row from the sweep folder DIR: DIR/runs/<name>/ and, for a refused run, DIR/logs/<name>.exit and .log.
// `finest`: the reference of the finest_run measure (null: none completed).
RunResult collect_run(const Sweep& sweep, const SweepRun& run, const std::filesystem::path& dir,
                      const WaveSignature* finest = nullptr);
std::vector<RunResult> collect_results(const Sweep& sweep, const std::filesystem::path& dir);

// results.csv: run, the varied keys, outcome, particles, steps, setup_seconds, wall_seconds, cpu_seconds,
// loop_cpu_seconds, particle_steps_per_second, error, largest_number_density_ratio, failure_time, failure_check, note. Cells never hold a comma (a list value's
// commas become ';').
void write_results_csv(const Sweep& sweep, const std::vector<RunResult>& results, const std::filesystem::path& file);

}  // namespace slide::tools
