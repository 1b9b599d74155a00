#include "tools/sweep/sweep_command.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <fmt/format.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <csignal>
#include <cstring>
#include <iostream>
#include <map>
#include <thread>

#include "cases/schema.hpp"
#include "tools/atomic_file.hpp"
#include "tools/output_folder.hpp"
#include "tools/plot_scripts.hpp"
#include "tools/sweep/sweep_plan.hpp"
#include "tools/sweep/sweep_results.hpp"

extern char** environ;

namespace slide::tools {
namespace {

using Clock = std::chrono::steady_clock;

std::filesystem::path this_program() { return std::filesystem::read_symlink("/proc/self/exe"); }

// Starts `slide run` for one run, its output and errors into DIR/logs/<name>.log. Returns the child's pid.
pid_t spawn_run(const std::filesystem::path& program, const Sweep& s, const SweepRun& r,
                const std::filesystem::path& dir, int threads) {
  std::vector<std::string> argv{program.string(), "run", s.scene.string(), "--out", run_folder(dir, r).string(),
                                "--quiet", "--threads", std::to_string(threads)};
  for (const auto& o : r.overrides) argv.insert(argv.end(), {"--set", o});
  std::vector<char*> cargv;
  for (auto& a : argv) cargv.push_back(a.data());
  cargv.push_back(nullptr);
  const std::string log = (dir / "logs" / (r.name + ".log")).string();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  pid_t pid = 0;
  const int err = posix_spawn(&pid, program.c_str(), &actions, nullptr, cargv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (err != 0) throw std::runtime_error(fmt::format("cannot start {}: {}", program.string(), std::strerror(err)));
  return pid;
}

volatile std::sig_atomic_t sweep_interrupted = 0;
extern "C" void on_sweep_interrupt(int) { sweep_interrupted = 1; }

// SIGINT and SIGTERM set `sweep_interrupted` for as long as it lives, without SA_RESTART, so that waitpid returns to the
// loop; the earlier handlers come back after.
class InterruptHandlers {
 public:
  InterruptHandlers() {
    struct sigaction a {};
    a.sa_handler = on_sweep_interrupt;
    sigemptyset(&a.sa_mask);
    a.sa_flags = 0;
    sweep_interrupted = 0;
    sigaction(SIGINT, &a, &previous_int_);
    sigaction(SIGTERM, &a, &previous_term_);
  }
  ~InterruptHandlers() {
    sigaction(SIGINT, &previous_int_, nullptr);
    sigaction(SIGTERM, &previous_term_, nullptr);
  }
  InterruptHandlers(const InterruptHandlers&) = delete;
  InterruptHandlers& operator=(const InterruptHandlers&) = delete;

 private:
  struct sigaction previous_int_ {}, previous_term_ {};
};

using RunningRuns = std::map<pid_t, std::pair<const SweepRun*, Clock::time_point>>;

// Asks the running runs to stop as Ctrl-C stops them, and waits for them: nothing is left running behind an error.
void stop_and_wait(const RunningRuns& running) {
  for (const auto& [pid, run] : running) kill(pid, SIGINT);
  for (const auto& [pid, run] : running)
    while (waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
    }
}

// Runs the pending runs, `jobs` at a time. Returns the exit code (0, 1 or 130). A run that cannot be started (or its
// folder cleared) stops the running ones before the error goes up.
int run_pending(const Sweep& s, const std::filesystem::path& dir, int jobs, int threads) {
  std::vector<const SweepRun*> pending;
  for (const auto& r : s.runs)
    if (!run_is_finished(run_folder(dir, r), r)) pending.push_back(&r);
  std::cerr << fmt::format("slide sweep {}: {} runs, {} finished already, {} to run ({} at once, {} threads each)\n",
                           s.name, s.runs.size(), s.runs.size() - pending.size(), pending.size(), jobs, threads);
  const auto program = this_program();
  RunningRuns running;
  std::size_t next = 0, done = 0;
  int code = 0;
  const InterruptHandlers handlers;
  bool forwarded = false;
  while (next < pending.size() || !running.empty()) {
    // Interrupted (Ctrl-C reaches the runs too; a scheduler's SIGTERM may reach only us): the running runs are asked
    // to stop as Ctrl-C stops them (a final snapshot, exit 130), and are waited for.
    if (sweep_interrupted && !forwarded) {
      for (const auto& [pid, run] : running) kill(pid, SIGINT);
      forwarded = true;
    }
    while (!sweep_interrupted && next < pending.size() && running.size() < std::size_t(jobs)) {
      const SweepRun& r = *pending[next++];
      try {
        std::filesystem::remove_all(run_folder(dir, r));  // what an unfinished attempt left
        std::filesystem::remove(dir / "logs" / (r.name + ".exit"));
        running[spawn_run(program, s, r, dir, threads)] = {&r, Clock::now()};
      } catch (...) {
        stop_and_wait(running);
        throw;
      }
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;
      break;
    }
    const auto it = running.find(pid);
    if (it == running.end()) continue;
    const auto [run, start] = it->second;
    running.erase(it);
    const int exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    write_file_atomically(dir / "logs" / (run->name + ".exit"), std::to_string(exit_code) + "\n");
    if (exit_code == 2) write_refusal(s, *run, run_folder(dir, *run), dir / "logs" / (run->name + ".log"));
    const char* what = exit_code == 0     ? "completed"
                       : exit_code == 2   ? "refused"
                       : exit_code == 3   ? "unstable"
                       : exit_code == 130 ? "interrupted"
                                          : "failed";
    std::cerr << fmt::format("  [{}/{}] {} {} (exit {}) in {:.1f} s{}\n", ++done, pending.size(), run->name, what,
                             exit_code, seconds,
                             exit_code == 0 || exit_code == 3 ? "" : "; log: " + (dir / "logs" / (run->name + ".log")).string());
    if (exit_code == 130 || exit_code == 128 + SIGINT || exit_code == 128 + SIGTERM) code = 130;
    else if (exit_code != 0 && exit_code != 2 && exit_code != 3 && code == 0) code = 1;
  }
  return sweep_interrupted ? 130 : code;
}

int collect(const Sweep& s, const std::filesystem::path& dir) {
  const auto results = collect_results(s, dir);
  write_results_csv(s, results, dir / "results.csv");
  std::map<RunOutcome, int> count;
  for (const auto& r : results) ++count[r.outcome];
  std::string summary;
  for (const auto& [o, n] : count) summary += fmt::format("{}{} {}", summary.empty() ? "" : ", ", n, run_outcome_names.name(o));
  std::cerr << fmt::format("slide sweep {}: {} ({})\n", s.name, (dir / "results.csv").string(), summary);
  run_plot_script("plot_sweep.py", dir);
  return 0;
}

// `--collect DIR`: a folder that is not a sweep's, or a plan.json that cannot be read, is bad input (exit 2).
int collect_folder(const std::filesystem::path& dir) {
  if (const auto why = sweep_folder_problem(dir)) {
    std::cerr << "slide sweep: --collect " << dir.string() << ": " << *why << "\n";
    return 2;
  }
  Sweep s;
  try {
    s = read_plan(dir);
  } catch (const std::runtime_error& e) {
    std::cerr << "slide sweep: --collect " << dir.string() << ": " << e.what() << "\n";
    return 2;
  }
  return collect(s, dir);
}

}  // namespace

int sweep_command(const SweepArguments& args) {
  try {
    if (!args.collect.empty()) return collect_folder(args.collect);
    if (args.jobs < 1) throw cases::SceneError("--jobs", "must be at least 1");
    const Sweep s = load_sweep(args.sweep_file);
    const std::filesystem::path dir = args.out.empty() ? std::filesystem::path("runs") / s.name : args.out;
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    const int threads = std::max(1, int(cores) / args.jobs);
    if (const auto why = output_folder_problem(dir)) {
      std::cerr << "slide sweep: --out " << dir.string() << ": " << *why << "; nothing was run or written\n";
      return 2;
    }
    std::filesystem::create_directories(dir / "logs");
    std::filesystem::create_directories(dir / "runs");
    write_plan(s, dir);
    write_jobs(this_program(), s, dir, threads);
    if (args.plan_only) {
      std::cerr << fmt::format("slide sweep {}: {} runs planned: {} (collect with slide sweep --collect {})\n", s.name,
                               s.runs.size(), (dir / "jobs.txt").string(), dir.string());
      return 0;
    }
    const int code = run_pending(s, dir, args.jobs, threads);
    collect(s, dir);
    return code;
  } catch (const cases::SceneError& e) {
    std::cerr << "slide: invalid sweep "
              << (args.collect.empty() ? args.sweep_file.string() : (args.collect / "plan.json").string()) << ": "
              << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "slide: error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace slide::tools
