#pragma once
// The `slide run` and `slide check` commands, as functions returning the process exit code
// (0 completed, 2 invalid scene or arguments, 3 unstable, 130 interrupted by SIGINT, 143 by SIGTERM).
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "fluid/communicator.hpp"

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
  // The processes mpirun started (null: one process). On several, every process runs the command alike; the first
  // writes the outputs (tools/observer_copy.hpp) and speaks.
  std::shared_ptr<const Communicator> world;
};

// On several processes only the first speaks (progress, refusals and the final message would be said by all alike):
// the others keep quiet, and speak up where one has something of its own to say (its own failure).
void keep_quiet();
void speak_up();

int run_command(const RunArguments& args);
int check_command(const RunArguments& args);

}  // namespace slide::tools
