// slide: landslide-generated waves with weakly compressible MPS. See README.md and cases/SCHEMA.md.
#include <CLI/CLI.hpp>

#include <cstdlib>
#include <iostream>

#include <memory>
#include <optional>

#include "cases/particle_budget.hpp"
#include "mpi/mpi_communicator.hpp"
#include "cases/scene.hpp"
#include "tools/large_blocks_to_system.hpp"
#include "tools/report.hpp"
#include "tools/run_driver.hpp"
#include "tools/sweep/sweep_command.hpp"

namespace {
int run_main(int argc, char** argv, std::shared_ptr<const slide::Communicator> world) {
  CLI::App app{"slide: weakly compressible MPS simulator of landslides falling into water"};
  app.require_subcommand(1);
  slide::tools::RunArguments args;
  std::string scene;

  auto* run = app.add_subcommand("run", "run a scene");
  run->add_option("scene", scene, "scene file (YAML); with --resume, optional (it must then be the checkpoint's)");
  auto* out_option = run->add_option("--out", args.out, "output folder (default runs/<case name>)");
  std::string resume_dir;
  auto* resume = run->add_option("--resume", resume_dir,
                                 "continue the run in this folder from its checkpoint (checkpoint.bin), bit for bit");
  resume->excludes(out_option);
  run->add_option("--stop-at", args.stop_at,
                  "stop at this simulated time (s) with a checkpoint and a final snapshot, exit 0; --resume continues")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            // CLI::NonNegativeNumber lets nan through (every comparison with it is false): it would stop at t = 0.
            char* end = nullptr;
            const double t = std::strtod(text.c_str(), &end);
            if (end == text.c_str() || *end != '\0' || !(t >= 0.0)) return "must be a time >= 0 s, not " + text;
            return "";
          },
          "TIME >= 0"));
  run->add_option("--set", args.overrides, "override a scene key: key.path=value (repeatable)");
  run->add_option("--threads", args.threads, "number of threads (default: all)")->check(CLI::Range(1, 1024));
  run->add_flag("--quiet", args.quiet, "no progress line");

  auto* check = app.add_subcommand("check", "validate a scene and print what it would run; runs nothing");
  check->add_option("scene", scene, "scene file (YAML)")->required();
  check->add_option("--set", args.overrides, "override a scene key: key.path=value (repeatable)");
  auto* target = check->add_option("--target-error", args.target_error,
                                   "with --with: name the cheapest configuration of that sweep whose error is at most this")
                    ->check(CLI::PositiveNumber);
  std::string with_dir;
  auto* with = check->add_option("--with", with_dir, "a finished sweep's folder (slide sweep) of the same kind of scene");
  target->needs(with);
  with->needs(target);

  app.add_subcommand("schema", "print the scene reference (every key with unit, default and range)");

  slide::tools::SweepArguments sweep_args;
  std::string sweep_file, sweep_out, sweep_collect;
  std::string report_dir;
  auto* report = app.add_subcommand("report", "write report.html (one self-contained page) into a run or sweep folder");
  report->add_option("dir", report_dir, "run folder (run.json) or sweep folder (plan.json)")->required();

  auto* sweep = app.add_subcommand("sweep", "run a scene many times with keys varied (a sweep file, tools/sweep/"
                                            "sweep_file.hpp) and write results.csv; resumes where it stopped");
  sweep->add_option("sweep", sweep_file, "sweep file (YAML)");
  sweep->add_option("--out", sweep_out, "sweep folder (default runs/<sweep name>)");
  sweep->add_option("--jobs", sweep_args.jobs, "runs at once, each with cores / jobs threads (default 1)")
      ->check(CLI::Range(1, 1024));
  sweep->add_flag("--plan-only", sweep_args.plan_only,
                  "write plan.json and jobs.txt (one command per run, for xargs -P or a cluster's job array); run "
                  "nothing");
  sweep->add_option("--collect", sweep_collect,
                    "build results.csv from the run folders in this sweep folder (made anywhere); runs nothing");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  args.scene = scene;
  args.resume = resume_dir;
  args.world = world;
  if (world && world->rank() > 0) args.quiet = true;
  // The commands other than run do not split their work: on several processes the first runs them alone.
  if (world && world->size() > 1 && !app.got_subcommand("run")) {
    if (world->rank() > 0) return 0;
  }
  if (app.got_subcommand("run") && scene.empty() && resume_dir.empty()) {
    std::cerr << "slide run: give a scene file, or --resume DIR\n";
    return 2;
  }
  if (app.got_subcommand("schema")) {
    std::cout << slide::cases::scene_reference();
    return 0;
  }
  if (app.got_subcommand("check")) {
    args.sweep_dir = with_dir;
    return slide::tools::check_command(args);
  }
  if (app.got_subcommand("report")) return slide::tools::report_command(report_dir);
  if (app.got_subcommand("sweep")) {
    if (sweep_file.empty() == sweep_collect.empty()) {
      std::cerr << "slide sweep: give a sweep file or --collect DIR (one of them)\n";
      return 2;
    }
    sweep_args.sweep_file = sweep_file;
    sweep_args.out = sweep_out;
    sweep_args.collect = sweep_collect;
    return slide::tools::sweep_command(sweep_args);
  }
  return slide::tools::run_command(args);
}
}  // namespace

// Nothing escapes: whatever a command did not expect ends the process with exit 1 and one line (a run in its step
// loop has already written its last good state and run.json by then: tools/run_driver.cpp).
//
// Started by mpirun (or srun), the program starts MPI (mpi/mpi_communicator.hpp). One process runs as without it.
// Several run `slide run` together (tools/run_driver.cpp; the other commands run on the first alone): the first
// speaks and writes, and where one process fails alone (exit 1) it stops them all with its code, since the others
// may be waiting for it.
int main(int argc, char** argv) {
  slide::tools::large_blocks_to_system();
  slide::cases::program_resident_bytes();  // the program's own memory, taken before any scene (particle_budget.hpp)
  std::optional<slide::mpi::MpiSession> mpi;
  bool several = false;
  try {
    if (slide::mpi::launched_by_mpi()) mpi.emplace(argc, argv);
    const long joined = mpi ? mpi->world()->size() : 1;
    if (const auto said = slide::mpi::launcher_process_count(); said && said->processes != joined) {
      std::cerr << "slide: the launcher started " << said->processes << " processes (" << said->variable << "="
                << said->processes << ") but MPI joined " << joined
                << (joined == 1 ? " (this one alone): each would run the whole scene into the same folder"
                                : ": they are not one run")
                << "; start slide with the mpirun of the MPI it was built with (Open MPI), or srun with PMI "
                   "support (srun --mpi=pmix); nothing was run or written\n";
      return 2;
    }
    several = mpi && mpi->world()->size() > 1;
    if (several && mpi->world()->rank() > 0) slide::tools::keep_quiet();
    const int code = run_main(argc, argv, mpi ? mpi->world() : nullptr);
    if (several && code == 1) slide::mpi::abort_all(code);
    return code;
  } catch (const std::exception& e) {
    slide::tools::speak_up();
    std::cerr << "slide: error: " << e.what() << "\n";
  } catch (...) {
    slide::tools::speak_up();
    std::cerr << "slide: error: unknown exception\n";
  }
  if (several) slide::mpi::abort_all(1);
  return 1;
}
