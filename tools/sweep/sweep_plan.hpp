#pragma once
// A sweep's folder: plan.json (the expanded sweep: what `--collect` reads back, wherever the runs were made),
// jobs.txt (one shell command per run, for xargs -d '\n' -P, GNU parallel or a cluster's job array) and runs/<name>/ (each
// run's own folder).
#include <filesystem>
#include <optional>
#include <string>
#include <string>

#include "tools/sweep/sweep_file.hpp"

namespace slide::tools {

void write_plan(const Sweep& sweep, const std::filesystem::path& dir);
// std::runtime_error when DIR holds no readable plan.json.
Sweep read_plan(const std::filesystem::path& dir);

// Why `dir` is not a sweep folder that read_plan can read (missing, not a folder, no plan.json), or nothing.
std::optional<std::string> sweep_folder_problem(const std::filesystem::path& dir);

// The command that makes one run, its arguments quoted for a POSIX shell.
std::string run_command_line(const std::filesystem::path& program, const Sweep& sweep, const SweepRun& run,
                             const std::filesystem::path& dir, int threads);
void write_jobs(const std::filesystem::path& program, const Sweep& sweep, const std::filesystem::path& dir,
                int threads);

inline std::filesystem::path run_folder(const std::filesystem::path& dir, const SweepRun& run) {
  return dir / "runs" / run.name;
}

}  // namespace slide::tools
