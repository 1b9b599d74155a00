#pragma once
// The `slide run` and `slide check` commands, as functions returning the process exit code
// (0 completed, 2 invalid scene or arguments, 3 unstable, 130 interrupted by SIGINT, 143 by SIGTERM).
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace slide::tools {

struct RunArguments {
  std::filesystem::path scene;
  std::filesystem::path out;  // empty: runs/<case name>
  std::vector<std::string> overrides;
  int threads = 0;            // 0: OpenMP's default
  bool quiet = false;
  // check --target-error E --with SWEEP_DIR: the cheapest configuration of a finished sweep within E (NaN: not asked)
  double target_error = std::numeric_limits<double>::quiet_NaN();
  std::filesystem::path sweep_dir;
  // run --resume DIR: continue the run in DIR from its checkpoint (scene: empty, or the same scene as the checkpoint's)
  std::filesystem::path resume;
  // run --stop-at T: stop at the first step boundary at or after simulated time T with a checkpoint, as an
  // interrupted run does, but exit 0 (a job with a wall-time limit runs its part and the next job resumes)
  double stop_at = std::numeric_limits<double>::infinity();
};

int run_command(const RunArguments& args);
int check_command(const RunArguments& args);

}  // namespace slide::tools
