#pragma once
// `slide sweep SWEEP.yaml [--jobs N] [--out DIR]` and `slide sweep --collect DIR`.
#include <filesystem>

namespace slide::tools {

struct SweepArguments {
  std::filesystem::path sweep_file;  // empty with --collect
  std::filesystem::path out;         // default runs/<sweep name>
  std::filesystem::path collect;     // --collect DIR: results from the run folders in DIR/runs, nothing run
  int jobs = 1;                      // runs at once; each gets max(1, cores / jobs) threads
  bool plan_only = false;            // write plan.json and jobs.txt (for other machines), run nothing
};

// Writes DIR/results.csv, then the charts (tools/plot_sweep.py: accuracy_cost.png, stability_map.png) when Debian's
// /usr/bin/python3 with matplotlib is there (else it says so and goes on).
// Exit codes: 0 every run finished (completed, inaccurate or unstable) or was refused (invalid, as the results say);
// 1 some run failed otherwise (its log in DIR/logs/); 2 a bad sweep file or argument (nothing run); 130 interrupted
// (finished runs are kept: run the same command again to resume).
int sweep_command(const SweepArguments& args);

}  // namespace slide::tools
