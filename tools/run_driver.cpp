#include "tools/run_driver.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <fmt/format.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <cmath>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <nlohmann/json.hpp>

#include "cases/check_report.hpp"
#include "cases/particle_budget.hpp"
#include "cases/observed_particles.hpp"
#include "cases/scene.hpp"
#include "cases/yaml_text.hpp"
#include "coupling/free_surface_gauge.hpp"
#include "coupling/position_text.hpp"
#include "coupling/relaxation.hpp"
#include "coupling/rigid_bodies.hpp"
#include "coupling/surge_front.hpp"
#include "fluid/listed_pairs.hpp"
#include "fluid/parallel.hpp"
#include "tools/atomic_file.hpp"
#include "tools/checkpoint.hpp"
#include "tools/shared_checkpoint.hpp"
#include "tools/observer_copy.hpp"
#include "tools/snapshot_rows.hpp"
#include "tools/output_folder.hpp"
#include "tools/run_outputs.hpp"
#include "tools/sweep/recommendation.hpp"
#include "tools/snapshot_writer.hpp"

namespace slide::tools {

namespace {
// CPU time of this process so far, all threads, user and system (setup included).
double process_cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}
// The largest resident size this process has had so far, bytes (Linux reports ru_maxrss in KiB).
double peak_resident_bytes() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return 1024.0 * double(u.ru_maxrss);
}
}  // namespace
namespace {
std::streambuf* own_stderr = nullptr;  // where standard error went before keep_quiet
std::stringbuf held_stderr;             // what a quiet process said since
bool refused_elsewhere = false;         // this process stopped because another refused (cases::RefusedOnAnotherProcess)
}  // namespace

void keep_quiet() {
  if (!own_stderr) own_stderr = std::cerr.rdbuf(&held_stderr);
}
void speak_up() {
  if (own_stderr) std::cerr.rdbuf(own_stderr);
  std::cerr.clear();
  own_stderr = nullptr;
}

namespace {
// Several processes: whether any refused (exit 2) at this point of a run's preparation, agreed by all (a process that
// went on alone would wait for the others for ever). What the first process refuses it has said; a refusal of another
// process alone (a file it cannot read: the run's folder is not shared; its own memory limit) it says now, with its
// number.
bool refused_anywhere(const RunArguments& args, bool refused_here) {
  if (!args.world || args.world->size() == 1) return refused_here;
  if (std::exchange(refused_elsewhere, false)) refused_here = false;  // the process that refused says why
  const auto& world = *args.world;
  std::vector<std::int64_t> refused(static_cast<std::size_t>(world.size()), 0);
  refused[static_cast<std::size_t>(world.rank())] = refused_here ? 1 : 0;
  world.sum(refused.data(), refused.size());
  if (refused_here && world.rank() > 0 && refused[0] == 0) {
    const std::string said = held_stderr.str();
    speak_up();
    std::cerr << "slide: process " << world.rank() << " of " << world.size() << " (alone: in its part of a 3-D "
              << "scene, or where its files or environment are not the first's: is the folder shared by every "
              << "process?): "
              << (said.rfind("slide: ", 0) == 0 ? said.substr(7) : said);
    keep_quiet();
  }
  held_stderr.str("");
  return std::any_of(refused.begin(), refused.end(), [](std::int64_t r) { return r != 0; });
}
}  // namespace

namespace {

// The signal that asked the run to stop (SIGINT: Ctrl-C; SIGTERM: what schedulers send before they kill a job), or 0.
volatile std::sig_atomic_t interrupted = 0;
extern "C" void on_stop_signal(int signal) { interrupted = signal; }

using Clock = std::chrono::steady_clock;
using nlohmann::json;

// The resolved scene as JSON: scalars become booleans, numbers or strings.
json to_json(const YAML::Node& n) {
  if (n.IsMap()) {
    json j = json::object();
    for (const auto& kv : n) j[kv.first.as<std::string>()] = to_json(kv.second);
    return j;
  }
  if (n.IsSequence()) {
    json j = json::array();
    for (const auto& v : n) j.push_back(to_json(v));
    return j;
  }
  if (!n.IsScalar()) return nullptr;
  const std::string s = n.Scalar();
  if (s == "true") return true;
  if (s == "false") return false;
  try {
    std::size_t used = 0;
    const double d = std::stod(s, &used);
    if (used == s.size()) {
      if (s.find_first_of(".eE") == std::string::npos && std::abs(d) < 9e15) return static_cast<long long>(d);
      return d;
    }
  } catch (const std::exception&) {
  }
  return s;
}

std::string limit_summary(const std::array<long, time_step_limit_count>& counts) {
  std::string s;
  for (std::size_t k = 0; k < counts.size(); ++k)
    if (counts[k] > 0) s += fmt::format("{}{} {}", s.empty() ? "" : ", ", to_string(TimeStepLimit(k)), counts[k]);
  return s;
}

// Reads and checks the scene file with the overrides (nothing built yet); on a scene error prints it and returns
// nothing (the caller exits 2).
std::optional<YAML::Node> resolve_or_report(const RunArguments& args) {
  try {
    return cases::load_scene(args.scene, args.overrides);
  } catch (const cases::SceneError& e) {
    std::cerr << "slide: invalid scene " << args.scene.string() << ": " << e.what() << "\n";
    return std::nullopt;
  }
}

// What a refused scene's message begins with: the scene file's, or a resumed run's checkpoint's.
std::string refusal_of_scene(const RunArguments& args) {
  return args.resume.empty() ? "slide: invalid scene " + args.scene.string() + ": "
                             : "slide: --resume " + args.resume.string() + ": the checkpoint's scene is refused: ";
}

// Builds the resolved scene; on a scene error prints it and returns null (the caller exits 2).
template <int D>
std::unique_ptr<cases::Scene<D>> build_or_report(const RunArguments& args, const YAML::Node& resolved,
                                                 cases::StartOfRun start = cases::StartOfRun::settle_now,
                                                 const cases::ForProcesses& for_processes = {}) {
  try {
    return cases::build_scene<D>(resolved, args.scene.stem().string(),
                              args.scene.parent_path().empty() ? "." : args.scene.parent_path(), start,
                              for_processes);
  } catch (const cases::RefusedOnAnotherProcess&) {
    refused_elsewhere = true;
    return nullptr;
  } catch (const cases::SceneError& e) {
    std::cerr << refusal_of_scene(args) << e.what() << "\n";
    return nullptr;
  }
}

template <int D>
int check_scene(const RunArguments& args, const YAML::Node& resolved) {
  const std::unique_ptr<cases::Scene<D>> scene = build_or_report<D>(args, resolved);
  if (!scene) return 2;
  std::cout << cases::check_report(*scene);
  if (!args.sweep_dir.empty()) {
    const auto& sim = *scene->simulation;
    const double steps = scene->end_time / sim.allowed_time_step().first;
    try {
      const double fluid = double(scene->fluid_count);
      std::cout << recommendation_report(args.sweep_dir, args.target_error, fluid,
                                         double(sim.particles().real_count()) - fluid, steps, sim.options.dp, D);
    } catch (const std::exception& e) {
      std::cerr << "slide: --with " << args.sweep_dir.string() << ": " << e.what() << "\n";
      return 2;
    }
  }
  return 0;
}

}  // namespace

int check_command(const RunArguments& args) {
  const auto resolved = resolve_or_report(args);
  if (!resolved) return 2;
  return cases::scene_dimension(*resolved) == 3 ? check_scene<3>(args, *resolved) : check_scene<2>(args, *resolved);
}

namespace {

// SIGINT or SIGTERM stops the loop before the next step, and so does reaching --stop-at. On several processes every
// one stops at the same step: the signal any of them got (the larger number, SIGTERM before SIGINT) counts for all.
template <int D>
class InterruptWatch : public StepObserver<D> {
 public:
  InterruptWatch(double stop_at, const Communicator* world) : stop_at_(stop_at), world_(world) {}
  bool before_step(const Simulation<D>& sim) override {
    if (world_ && world_->size() > 1) {
      std::int64_t signal = interrupted;
      world_->max(&signal, 1);
      interrupted = static_cast<std::sig_atomic_t>(signal);
    }
    return interrupted == 0 && sim.time() < stop_at_;
  }

 private:
  double stop_at_;
  const Communicator* world_;
};

// The state a failed run leaves as its last good snapshot: every `every` steps, before the step, what a snapshot
// holds (a third of the particles' arrays: a whole copy had been 160 of the bench case's 560 heap bytes a particle).
template <int D>
class LastGoodState : public StepObserver<D> {
 public:
  explicit LastGoodState(const Simulation<D>& sim) : snapshot(sim.particles()), time(sim.time()), step(sim.step_count()) {}
  bool before_step(const Simulation<D>& sim) override {
    if (sim.step_count() % every == 0) {
      snapshot.assign(sim.particles());
      time = sim.time();
      step = sim.step_count();
    }
    return true;
  }
  static constexpr long every = 10;
  IdOrdered<D> snapshot;
  double time;
  long step;
};

// One progress line on standard error, refreshed every second.
template <int D>
class ProgressLine : public StepObserver<D> {
 public:
  // Rates and the ETA count from where this loop started (a resumed run's, the checkpoint).
  ProgressLine(Clock::time_point loop_start, double end_time, const Simulation<D>& sim, std::string label = "")
      : start_(loop_start), end_(end_time), start_step_(sim.step_count()), start_time_(sim.time()),
        label_(std::move(label)) {}
  void after_step(Simulation<D>& sim, double dt) override {
    if (Clock::now() < next_) return;
    next_ = Clock::now() + std::chrono::seconds(1);
    const double wall = std::chrono::duration<double>(Clock::now() - start_).count();
    const double rate = double(sim.particles().real_count()) * double(sim.step_count() - start_step_) / wall;
    const double eta = wall / (sim.time() - start_time_) * (end_ - sim.time());
    const std::size_t left = sim.left_the_domain().size();
    std::cerr << fmt::format("\r{}t = {:.5f} / {:.5g} s  dt = {:.3e} s  {:.3g} M particle-steps/s  ETA {:.0f} s{}   ",
                             label_, sim.time(), end_, dt, rate / 1e6, eta,
                             left ? fmt::format("  {} left the domain", left) : std::string())
              << std::flush;
  }

 private:
  Clock::time_point start_, next_ = Clock::now() + std::chrono::seconds(1);
  double end_;
  long start_step_;
  double start_time_;
  std::string label_;
};

// run.json's account of the particles taken out of the run (Simulation::left_the_domain): how many, and the first
// hundred with when and where.
template <int D>
json left_the_domain_json(const Simulation<D>& sim) {
  const auto& left = sim.left_the_domain();
  json listed = json::array();
  for (std::size_t k = 0; k < std::min<std::size_t>(left.size(), 100); ++k)
    listed.push_back({{"id", left[k].id}, {"time", left[k].time}, {"position", left[k].position}});
  return {{"count", left.size()}, {"first", listed}};
}

// The completed message's note of them, empty when none left.

template <int D>
std::string left_the_domain_note(const Simulation<D>& sim) {
  const auto& left = sim.left_the_domain();
  if (left.empty()) return "";
  const auto& first = left.front();
  return fmt::format("; {} fluid particle{} left the domain through an open side and {} taken out (the first, {}, "
                     "at t = {:.6g} s at {}; run.json lists them)",
                     left.size(), left.size() == 1 ? "" : "s", left.size() == 1 ? "was" : "were", first.id,
                     first.time, position_text(first.position));
}

// A run ready to step: its scene built, its output folder checked, and for a resumed run the checkpoint's state.
template <int D>
struct PreparedRun {
  std::unique_ptr<cases::Scene<D>> scene;  // its start (settling, gates) left to settle_before_the_run
  std::filesystem::path out;
  CheckpointHeader header;  // what its checkpoints will say
  std::optional<Checkpoint> resumed_from;    // a checkpoint of the run (after t = 0) to continue from
  std::optional<Checkpoint> settling_from;   // a checkpoint taken while the water settled, to settle on from
  // A run on several processes: the first's observers' copy (tools/observer_copy.hpp), built before the scene so
  // that the building's passing memory is not taken on top of the running share (null elsewhere: distribute_run).
  std::unique_ptr<cases::Scene<D>> observers_copy;
};

// A 3-D scene on several processes is built in parts (cases/build_share.hpp), new or resumed: no process makes the
// whole scene, and a resumed run's processes each read a part of the checkpoint's particles (read_resumed_checkpoint).
bool built_in_parts(const RunArguments& args, int dimension) {
  return dimension == 3 && args.world && args.world->size() > 1;
}

// The observers' copy of a scene built in parts: every process builds its part (a collective), the first keeps it.
// Returns false where the build was refused (on any process: every one returns false).
template <int D>
bool build_copy_in_parts(const RunArguments& args, const YAML::Node& resolved, const cases::SameMachine& machine,
                         PreparedRun<D>& run) {
  auto copy = build_or_report<D>(args, resolved, cases::StartOfRun::left_to_caller, {args.world, true, machine});
  if (refused_anywhere(args, !copy)) return false;
  if (args.world->rank() == 0) {
    run.observers_copy = std::move(copy);
    run.observers_copy->simulation->drop_copy_particles();
  }
  return true;
}

// A new run of its resolved scene: check the output folder, build (its settling is the run's: settle_before_the_run).
template <int D>
std::optional<PreparedRun<D>> prepare_new_run(const RunArguments& args, const std::optional<YAML::Node>& resolved,
                                              const cases::SameMachine& machine) {
  // The output folder is checked before anything is built or written (the case's name may come from the scene).
  const std::string name = (*resolved)["name"].as<std::string>();
  PreparedRun<D> run;
  run.out = args.out.empty() ? std::filesystem::path("runs") / (name.empty() ? args.scene.stem().string() : name)
                             : args.out;
  const bool writes = !args.world || args.world->rank() == 0;  // the others write nothing (tools/observer_copy.hpp)
  const auto why = writes ? output_folder_problem(run.out) : std::nullopt;
  if (why) std::cerr << "slide: --out " << run.out.string() << ": " << *why << "; nothing was run or written\n";
  const bool several = args.world && args.world->size() > 1;
  if (built_in_parts(args, D)) {
    if (refused_anywhere(args, why.has_value())) return std::nullopt;
    if (!build_copy_in_parts(args, *resolved, machine, run)) return std::nullopt;
  } else {
    const bool copy = !why && writes && several;
    if (copy) {
      run.observers_copy =
          build_or_report<D>(args, *resolved, cases::StartOfRun::left_to_caller, {nullptr, true, machine});
      if (run.observers_copy) run.observers_copy->simulation->drop_copy_particles();
    }
    // The build shares the scene (a collective): every process builds, or none.
    if (refused_anywhere(args, why.has_value() || (copy && !run.observers_copy))) return std::nullopt;
  }
  // Several processes: each keeps and lists its share of the scene (cases::ForProcesses).
  run.scene = build_or_report<D>(args, *resolved, cases::StartOfRun::left_to_caller, {args.world, false, machine});
  if (!run.scene) return std::nullopt;
  run.header = {checkpoint_writer(), std::filesystem::absolute(args.scene).string(), args.overrides,
                YAML::Dump(*resolved)};
  return run;
}

// The first line where two texts differ, for a refusal's message.
std::string first_difference(const std::string& a, const std::string& b) {
  std::istringstream sa(a), sb(b);
  std::string la, lb;
  for (int line = 1;; ++line) {
    const bool more_a = static_cast<bool>(std::getline(sa, la)), more_b = static_cast<bool>(std::getline(sb, lb));
    if (!more_a && !more_b) return "none";
    if (la != lb || more_a != more_b)
      return fmt::format("line {} of the resolved scene: \"{}\" against the checkpoint's \"{}\"", line,
                         more_a ? la : "", more_b ? lb : "");
  }
}

// Whether the checkpoint can be resumed with these arguments: its version is this slide's, and a scene given is its
// own with its --set; else says why (exit 2).
bool resumes_as_given(const RunArguments& args, const CheckpointHeader& h) {
  if (h.version != checkpoint_writer()) {
    std::cerr << fmt::format("slide: --resume {}: the checkpoint was written by slide {} and this is slide {}: its "
                             "state is not this version's; resume it with the slide that wrote it or run the scene "
                             "again\n",
                             args.resume.string(), h.version, checkpoint_writer());
    return false;
  }
  if (args.scene.empty() && !args.overrides.empty()) {
    std::cerr << "slide: --resume " << args.resume.string() << ": --set needs the scene file too (slide run SCENE "
              << "--set ... --resume DIR), and they must be the checkpoint's: a resumed run continues its scene as it "
                 "was\n";
    return false;
  }
  if (args.scene.empty()) return true;
  const auto resolved = resolve_or_report(args);
  if (!resolved) return false;
  if (const std::string given = YAML::Dump(*resolved); given != h.resolved_scene) {
    std::cerr << fmt::format("slide: --resume {}: the checkpoint belongs to another scene than {} with these --set "
                             "(first difference: {}); resume without a scene to continue the checkpoint's own\n",
                             args.resume.string(), args.scene.string(), first_difference(given, h.resolved_scene));
    return false;
  }
  return true;
}

// A resumed run: the checkpoint's scene (or the one given, which must be the same), built without settling, then the
// checkpoint's state put back; or, from a checkpoint taken while settling, built to settle on from it. Refusals name
// why (exit 2). The checkpoint is read already (read_resumed_checkpoint).
template <int D>
std::optional<PreparedRun<D>> prepare_resumed_run(const RunArguments& args, Checkpoint checkpoint,
                                                  const cases::SameMachine& machine) {
  PreparedRun<D> run;
  run.out = args.resume;
  run.resumed_from = std::move(checkpoint);
  const CheckpointHeader& h = run.resumed_from->header;
  // Built in parts, the build is a collective: a refusal here is agreed first (a scene file one process cannot read).
  const bool refused = !resumes_as_given(args, h);
  if (built_in_parts(args, D) ? refused_anywhere(args, refused) : refused) return std::nullopt;
  std::optional<YAML::Node> resolved;
  try {
    resolved = cases::load_yaml_text(h.resolved_scene);
  } catch (const cases::YamlTextRefused& e) {
    std::cerr << "slide: --resume " << args.resume.string() << ": the checkpoint's scene is refused: " << e.what()
              << "\n";
    return std::nullopt;
  }
  RunArguments scene_args = args;  // the checkpoint's scene, its files beside it
  scene_args.scene = args.scene.empty() ? std::filesystem::path(h.scene_file) : args.scene;
  const auto start = h.settling ? cases::StartOfRun::left_to_caller : cases::StartOfRun::already_settled;
  if (built_in_parts(args, D)) {
    // Built in parts as a new run is, its copy too: restore_state then shares the checkpoint's particles.
    if (!build_copy_in_parts(scene_args, *resolved, machine, run)) return std::nullopt;
    run.scene = build_or_report<D>(scene_args, *resolved, start, {args.world, false, machine});
  } else {
    run.scene = build_or_report<D>(scene_args, *resolved, start, {nullptr, false, machine});
  }
  if (!run.scene) return std::nullopt;
  run.header = h;
  if (h.settling) run.settling_from = std::exchange(run.resumed_from, std::nullopt);
  run.header.settling = false;  // the run's own checkpoints, once it runs, are not the settling's (found in review)
  return run;
}

// checkpoint.bin of the running simulation's state at its time and step, with `after` after it (the outputs', the
// settling's); taken while settling or not. A collective on several processes (`world`): every process gives its own
// particles (tools/shared_checkpoint.hpp), and `after` is the first's (null on the others).
template <int D>
void write_state_checkpoint(const PreparedRun<D>& run, const Simulation<D>& sim, const StateWriter* after,
                            bool settling, const Communicator& world) {
  std::optional<CheckpointFile> file;
  StateWriter rest;
  if (after) {
    CheckpointHeader header = run.header;
    header.time = sim.time();
    header.step = sim.step_count();
    header.settling = settling;
    file.emplace(run.out, header);
    sim.save_state_after_particles(rest);
    rest.append(after->bytes().data(), after->bytes().size());
  }
  write_shared_checkpoint(world, sim, file ? &*file : nullptr, after ? &rest : nullptr);
}

// Writes checkpoint.bin at the scene's interval of simulated time (after the outputs have sampled the step), and on
// demand (an interrupted run). On several processes every process has one and writes together (write(); the first's
// outputs, null on the others); the first decides when (due), and its ObserverCopy has the others join.
template <int D>
class CheckpointObserver : public StepObserver<D> {
 public:
  CheckpointObserver(const PreparedRun<D>& run, RunOutputs<D>* outputs, const Simulation<D>& sim,
                     const Communicator& world)
      : run_(run), outputs_(outputs), sim_(sim), world_(world), interval_(run.scene->output.checkpoint_interval),
        next_(interval_ > 0 ? interval_ : std::numeric_limits<double>::infinity()) {}
  bool due(double t) const { return interval_ > 0.0 && t >= next_ - 1e-12 * std::max(1.0, next_); }
  void after_step(Simulation<D>& sim, double) override { write_if_due(sim.time()); }
  void write_if_due(double t) {
    if (!due(t)) return;
    next_ += interval_;
    if (t >= next_) next_ = t + interval_;
    write();
  }
  void write() {
    if (!outputs_) return write_state_checkpoint(run_, sim_, nullptr, false, world_);
    outputs_->flush();
    StateWriter after;
    outputs_->save_state(after);
    after.put(next_);
    write_state_checkpoint(run_, sim_, &after, false, world_);
  }
  void restore(StateReader& in) { in.get(next_); }

 private:
  const PreparedRun<D>& run_;
  RunOutputs<D>* outputs_;
  const Simulation<D>& sim_;
  const Communicator& world_;
  double interval_, next_;
};

// A run stopped by a signal while its water settled: a checkpoint of the simulation and the settling (from which
// --resume settles on, then runs; a collective on several processes), and run.json saying so (the first process).
// Returns the exit code, 128 + the signal.
template <int D>
int stop_while_settling(const PreparedRun<D>& run, const Simulation<D>& sim, const Settling<D>& settling,
                        const Communicator& world) {
  const bool first = world.rank() == 0;
  if (first) std::filesystem::create_directories(run.out);
  StateWriter after;
  settling.save_state(after);
  write_state_checkpoint(run, sim, first ? &after : nullptr, true, world);
  const int signal = interrupted;
  if (!first) return 128 + signal;
  const std::string msg = fmt::format(
      "interrupted by {} while the water settled, at {:.6g} of its {:.6g} s (step {}); checkpoint written: continue "
      "with slide run --resume {}",
      signal == SIGTERM ? "SIGTERM" : "SIGINT", sim.time(), settling.duration(), sim.step_count(), run.out.string());
  json j;
  j["program"] = "slide";
  j["version"] = SLIDE_VERSION;
  j["case"] = run.scene->name;
  j["scene_file"] = run.header.scene_file;
  j["overrides"] = run.header.overrides;
  j["status"] = "interrupted";
  j["message"] = msg;
  j["settling"] = {{"time", sim.time()}, {"duration", settling.duration()}, {"steps", sim.step_count()}};
  j["simulated_time"] = 0.0;
  j["steps"] = 0;
  write_file_atomically(run.out / "run.json", j.dump(2) + "\n");
  std::cerr << "\nslide: " << msg << "\n";
  return 128 + signal;
}

// The run's processes: mpirun's, or this one alone.
const Communicator& world_of(const RunArguments& args) {
  static const SerialCommunicator alone;
  return args.world ? *args.world : alone;
}

// A checkpoint's state refused while it was put back: exit 2. Every process refuses alike (each put back the whole
// state), or on several processes that each put back a part, one or more refused theirs and the others were told
// (StateRefusedElsewhere): the one that refused says why (refused_anywhere).
int refuse_resumed_state(const RunArguments& args, const std::filesystem::path& out, const std::runtime_error& e) {
  if (dynamic_cast<const StateRefusedElsewhere*>(&e))
    refused_elsewhere = true;
  else
    std::cerr << "slide: --resume " << out.string() << ": " << e.what() << "; nothing was run\n";
  refused_anywhere(args, true);
  return 2;
}

// A run on several processes, beside its running simulation: the first process's observers' copy
// (tools/observer_copy.hpp) and what brings it up to date. Absent on one process.
template <int D>
struct ProcessesOfRun {
  const Communicator* world;
  std::unique_ptr<cases::Scene<D>> copy;  // the first process's; null on the others
  std::optional<ObserverCopy<D>> observer;
  bool first() const { return world->rank() == 0; }
};

// Takes the scene onto the processes (each its share) before it settles: as built, or as its checkpoint left it. The
// first process builds its copy, its start (gates) left as the running scene's is: both are completed after settling
// (settle_before_the_run); what the copy holds comes from the running simulation. A scene that cannot run there was
// refused before (run_scene); what is refused here exits 2 too, nothing written.
template <int D>
std::optional<ProcessesOfRun<D>> distribute_run(const RunArguments& args, PreparedRun<D>& run, Simulation<D>& sim) {
  ProcessesOfRun<D> p{args.world.get(), std::move(run.observers_copy), std::nullopt};
  RunArguments scene_args = args;  // a resumed run's scene is the checkpoint's (its files beside it)
  if (scene_args.scene.empty()) scene_args.scene = run.header.scene_file;
  if (p.first() && !p.copy) {
    p.copy = build_or_report<D>(scene_args, cases::load_yaml_text(run.header.resolved_scene),
                                cases::StartOfRun::left_to_caller, {nullptr, true});
    if (p.copy) p.copy->simulation->drop_copy_particles();
  }
  if (refused_anywhere(args, p.first() && !p.copy)) return std::nullopt;
  try {
    sim.distribute(args.world);
  } catch (const std::invalid_argument& e) {
    std::cerr << "slide: invalid scene " << scene_args.scene.string() << ": " << e.what() << "; nothing was written\n";
    return std::nullopt;
  }
  return p;
}

// The settled start (method.initial_state: settled), run here rather than while the scene is built, so that a signal
// stops it as it stops the run: within a step, with a checkpoint (stop_while_settling). A run resumed from such a
// checkpoint settles on from it. Then the start is completed (the settled water checked at rest, the gates lifted).
// Several processes: the scene is shared among them (`processes`) before its first step, and settles shared; stopped,
// the first process's copy is brought up to date and writes the checkpoint.
// Returns an exit code where the run ends here (128 + signal; 2 where the water is refused), nothing where it goes on.
template <int D>
std::optional<int> settle_before_the_run(PreparedRun<D>& run, const RunArguments& args,
                                         std::optional<ProcessesOfRun<D>>& processes) {
  cases::Scene<D>& scene = *run.scene;
  Simulation<D>& sim = *scene.simulation;
  const auto share = [&] {
    if (args.world && args.world->size() > 1) processes = distribute_run<D>(args, run, sim);
    return !args.world || args.world->size() == 1 || processes.has_value();
  };
  std::optional<Relaxation> settled;
  const std::string refused = "slide: invalid scene " + (args.scene.empty() ? run.header.scene_file : args.scene.string()) +
                              ": method.initial_state: ";
  if (scene.pending_settling) {
    Settling<D> settling(sim, *scene.pending_settling);
    if (run.settling_from) {
      try {
        StateReader in(run.settling_from->state);
        sim.restore_state(in);
        settling.restore_state(in);
      } catch (const std::runtime_error& e) {
        return refuse_resumed_state(args, run.out, e);
      }
      std::vector<char>().swap(run.settling_from->state);  // put back (the header stays, for run.json)
    }
    if (!share()) return 2;
    InterruptWatch<D> interrupt(std::numeric_limits<double>::infinity(), args.world.get());
    ProgressLine<D> progress(Clock::now(), settling.duration(), sim, "settling: ");
    std::vector<StepObserver<D>*> observers{&interrupt};
    if (!args.quiet) observers.push_back(&progress);
    try {
      if (settling.advance(observers).outcome == AdvanceResult::Outcome::stopped)
        return stop_while_settling(run, sim, settling, world_of(args));
      settled = settling.finish();
    } catch (const std::runtime_error& e) {  // it went unstable, or its water left the domain or is not at rest
      std::cerr << (args.quiet ? "" : "\n") << refused << e.what() << "\n";
      return 2;
    }
    if (!args.quiet) std::cerr << "\r" << std::string(100, ' ') << "\r";
  } else if (!share()) {
    return 2;
  }
  try {
    cases::complete_start(scene, settled);
    // The copy's gates lifted (its settling is the running scene's, already judged: not judged again on the first
    // process alone, where a refusal would leave the others waiting).
    if (processes && processes->copy) cases::complete_start(*processes->copy, std::nullopt);
  } catch (const cases::SceneError& e) {
    std::cerr << "slide: invalid scene " << (args.scene.empty() ? run.header.scene_file : args.scene.string()) << ": "
              << e.what() << "\n";
    return 2;
  }
  return std::nullopt;
}

// run.json's partition: the rebalance factor, repartitions and final imbalance, each process's owned particles and
// what its exchanges took (seconds of the step loop refreshing ghosts, re-sorting across processes, reducing; bytes
// sent), each process's memory (estimated, its peak so far, its neighbour list's size, the particles it made while
// building, the particles it held, ghosts included, at the first build and the most at any), and the observers' copy's
// gathers and their seconds on the first process (costs: 11 per process, in order).
template <int D>
json partition_json(const Domain<D>& domain, double imbalance, const std::vector<std::int64_t>& owned,
                    const std::vector<double>& costs, const ObserverCopy<D>* copy) {
  json per = json::array(), memory = json::array();
  for (std::size_t r = 0; (r + 1) * 11 <= costs.size(); ++r) {
    const double* c = &costs[r * 11];
    per.push_back({{"halo_s", c[0]}, {"rebuild_s", c[1]}, {"reduction_s", c[2]}, {"bytes_sent", c[3]}});
    memory.push_back({{"memory_estimate_bytes", c[4]},
                      {"peak_resident_bytes", c[5]},
                      {"listed_neighbours", {{"at_first_build", c[6]}, {"most", c[7]}}},
                      {"particles_made_at_build", c[8]},
                      {"particles_held", {{"at_first_build", c[9]}, {"most", c[10]}}}});
  }
  return {{"rebalance_imbalance", domain.rebalance_imbalance()}, {"repartitions", domain.repartitions()},
          {"imbalance", imbalance}, {"owned_particles", owned}, {"communication", per}, {"memory", memory},
          {"observer_copy",
           {{"gathers", copy ? copy->gathers() : 0L},
            {"seconds", copy ? copy->seconds() : 0.0},
            {"particles", copy ? copy->held() : std::size_t{0}}}}};
}

// The run of a D-dimensional scene: its resolved scene (a new run) or its checkpoint (a resumed one).
template <int D>
int run_scene(const RunArguments& args, const std::optional<YAML::Node>& resolved, std::optional<Checkpoint> checkpoint,
              Clock::time_point setup_start, double resident_bytes_at_start) {
  // Which processes share this machine's memory (a collective: every process gets here).
  const cases::SameMachine machine =
      args.world && args.world->size() > 1 ? cases::same_machine(*args.world) : cases::SameMachine{{1}};
  std::optional<PreparedRun<D>> run =
      checkpoint ? prepare_resumed_run<D>(args, std::move(*checkpoint), machine)
                 : prepare_new_run<D>(args, resolved, machine);
  if (refused_anywhere(args, !run)) return 2;
  const bool several = args.world && args.world->size() > 1;
  if (several) {  // before it settles
    try {
      run->scene->simulation->check_processes(args.world->size());
    } catch (const std::invalid_argument& e) {
      std::cerr << "slide: invalid scene " << args.scene.string() << ": " << e.what() << "; nothing was run or written\n";
      return 2;
    }
  }
  // From here on SIGINT and SIGTERM stop the run where it is, settling or stepping: before the next step, with a
  // checkpoint (exit 128 + signal). While the scene is built they end the process at once, as by default: nothing
  // has been computed that a checkpoint would keep, and the build does not look at a flag (found in review: a build
  // that took minutes could not be stopped but by SIGKILL).
  interrupted = 0;
  using Handler = void (*)(int);
  const Handler previous_sigint = std::signal(SIGINT, on_stop_signal);
  const Handler previous_sigterm = std::signal(SIGTERM, on_stop_signal);
  const std::unique_ptr<cases::Scene<D>>& scene = run->scene;
  const std::filesystem::path& out = run->out;
  auto& sim = *scene->simulation;
  for (const auto& slide : scene->slides)  // what the user would not expect of a slide, said before it runs
    if (!slide.floats_warning.empty()) std::cerr << "slide: warning: " << slide.floats_warning << "\n";
  // A resumed run's state: whole on every process (before it is shared among them), or where the scene is built in
  // parts the particles of a part each; the outputs' and checkpoints' state after it in the same stream, read by the
  // process that writes them.
  std::optional<StateReader> resumed_state;
  if (run->resumed_from) {
    try {
      resumed_state.emplace(run->resumed_from->state);
      sim.restore_state(*resumed_state);
    } catch (const std::runtime_error& e) {
      return refuse_resumed_state(args, out, e);
    }
  }
  std::optional<ProcessesOfRun<D>> processes;
  if (const auto ended = settle_before_the_run(*run, args, processes)) return *ended;
  const bool writes = !processes || processes->first();  // this process writes the outputs
  // What the outputs and checkpoints read: the simulation, or on several processes the first's copy of it.
  const Simulation<D>& whole = processes && processes->copy ? *processes->copy->simulation : sim;
  std::optional<RunOutputs<D>> outputs;
  std::optional<CheckpointObserver<D>> checkpoints;
  std::string refusal;  // of the resumed outputs' state, on the process that writes them
  if (writes) {
    std::filesystem::create_directories(out);
    // A new run in a folder an earlier run used: that run's checkpoint is not this run's to resume.
    std::error_code no_checkpoint;
    if (!run->resumed_from) std::filesystem::remove(checkpoint_path(out), no_checkpoint);
    outputs.emplace(*scene, whole, out, run->resumed_from.has_value());
    if (resumed_state) {
      try {
        outputs->restore_state(*resumed_state);
      } catch (const std::runtime_error& e) {
        refusal = e.what();
      }
    }
  }
  // Every process writes the checkpoints together (their particles), the first with its outputs' state.
  checkpoints.emplace(*run, writes ? &*outputs : nullptr, sim, world_of(args));
  if (writes && resumed_state && refusal.empty()) {
    try {
      checkpoints->restore(*resumed_state);
    } catch (const std::runtime_error& e) {
      refusal = e.what();
    }
  }
  std::int64_t refused = refusal.empty() ? 0 : 1;
  if (processes) processes->world->max(&refused, 1);  // every process stops where the first does
  if (refused != 0) {
    if (!refusal.empty()) std::cerr << "slide: --resume " << out.string() << ": " << refusal << "; nothing was run\n";
    return 2;
  }
  // The checkpoint's state is put back: its bytes go (the header stays, for run.json).
  resumed_state.reset();
  if (run->resumed_from) std::vector<char>().swap(run->resumed_from->state);
  // Several processes: a snapshot of every process's own particles (or of their last good state), a collective; the
  // first's outputs call it where they write one, the others join it.
  const SnapshotFormat snapshot_format_of_scene = snapshot_format(*scene);
  const auto shared_snapshot = [&](const IdOrdered<D>& mine, double time, long step) {
    write_shared_snapshot(*processes->world, writes ? outputs->snapshot_writer() : nullptr, snapshot_format_of_scene,
                          mine, time, step);
  };
  const auto join_snapshot = [&](const Simulation<D>& s) { shared_snapshot(IdOrdered<D>(s.particles()), 0.0, 0); };
  if (processes) {
    std::vector<typename ObserverCopy<D>::Reader> readers;
    typename ObserverCopy<D>::Collective snapshots{nullptr, nullptr, join_snapshot};
    typename ObserverCopy<D>::Collective checkpoint_hooks{
        nullptr, nullptr, [&c = *checkpoints](const Simulation<D>&) { c.write(); }};
    if (writes) {
      readers = {{[&o = *outputs](double t) { return o.samples_due(t); }, &*outputs}};
      checkpoint_hooks.due = [&c = *checkpoints](double t) { return c.due(t); };
      checkpoint_hooks.write = [&c = *checkpoints](const Simulation<D>& s) { c.write_if_due(s.time()); };
      snapshots.due = [&o = *outputs](double t) { return o.snapshot_due(t); };
      snapshots.write = [&o = *outputs, &whole](const Simulation<D>& s) {
        o.write_snapshot_if_due(whole.particles(), s.time(), s.step_count());
      };
      outputs->write_snapshots_with(
          [&](double time, long step) { shared_snapshot(IdOrdered<D>(sim.particles()), time, step); });
    }
    const cases::ObservedParticles<D> observed(*scene, sim.domain().ghost_layout(), sim.re() + sim.options.dp);
    processes->observer.emplace(*processes->world, processes->copy ? processes->copy->simulation.get() : nullptr,
                                observed, std::move(readers), std::move(snapshots), std::move(checkpoint_hooks));
  }
  // Where the first process writes a snapshot outside the step loop, the others join it: `first_writes_one` is known
  // on every process.
  const auto others_join_snapshot = [&](bool first_writes_one) {
    if (processes && !writes && first_writes_one) join_snapshot(sim);
  };
  // The copy brought up to date (a collective on several processes: every one calls it at the same point).
  const auto gather = [&] {
    if (processes) processes->observer->gather(sim);
  };

  const auto loop_start = Clock::now();
  const double cpu_at_loop_start = process_cpu_seconds();
  const long steps_at_loop_start = sim.step_count();
  const double setup_seconds = std::chrono::duration<double>(loop_start - setup_start).count();
  auto loop_rate = [&](double wall) {
    return wall > 0 ? double(whole.particles_in_run()) * double(sim.step_count() - steps_at_loop_start) / wall
                    : 0.0;
  };
  auto write_run_json = [&](const std::string& status, const std::string& message, const json& extra) {
    // The imbalance is a reduction (every process), but not where one process failed alone.
    const bool collective = processes && status != "failed";
    const std::vector<std::int64_t> owned = collective ? sim.domain().owned_counts() : std::vector<std::int64_t>{};
    const double imbalance = collective ? sim.domain().imbalance() : 1.0;
    const CommunicationCost& cost = sim.domain().communication_cost();
    const std::vector<double> costs =
        collective ? gather_on_first(*processes->world,
                                     {cost.halo_seconds, cost.rebuild_seconds, cost.reduction_seconds, cost.bytes_sent,
                                      scene->memory_estimate_bytes, peak_resident_bytes(),
                                      double(sim.listed_at_first_build()), double(sim.most_listed()),
                                      double(scene->particles_made_here), double(sim.held_at_first_build()),
                                      double(sim.most_held())})
                   : std::vector<double>{};
    if (!writes) return;
    const double wall = std::chrono::duration<double>(Clock::now() - loop_start).count();
    json j;
    j["program"] = "slide";
    j["version"] = SLIDE_VERSION;
    j["case"] = scene->name;
    j["scene_file"] = run->header.scene_file;
    j["overrides"] = run->header.overrides;
    if (run->resumed_from)
      j["resumed_from"] = {{"time", run->resumed_from->header.time}, {"step", run->resumed_from->header.step}};
    if (run->settling_from)
      j["resumed_from"] = {{"settling_time", run->settling_from->header.time},
                           {"settling_step", run->settling_from->header.step}};
    j["status"] = status;
    j["message"] = message;
    j["threads"] = thread_count();
    j["processes"] = processes ? processes->world->size() : 1;
    if (processes) j["partition"] = partition_json(sim.domain(), imbalance, owned, costs,
                                                   processes->observer ? &*processes->observer : nullptr);
    j["particles"] = {{"total", whole.particles_in_run()}, {"fluid", scene->fluid_count},
                      {"wall", scene->wall_count},      {"dummy", scene->dummy_count}};
    j["derived"] = {{"n0", sim.lattice.n0},
                    {"lambda", sim.lattice.lambda},
                    {"sound_speed", sim.options.sound_speed},
                    {"sound_speed_source", scene->sound_speed_source},
                    {"deepest_water", scene->deepest_water},
                    {"domain_min", std::vector<double>(sim.options.domain_lo.begin(), sim.options.domain_lo.end())},
                    {"domain_max", std::vector<double>(sim.options.domain_hi.begin(), sim.options.domain_hi.end())}};
    json limits = json::object();
    for (std::size_t k = 0; k < sim.limit_counts().size(); ++k)
      limits[std::string(to_string(TimeStepLimit(k)))] = sim.limit_counts()[k];
    j["time_step_limits"] = limits;
    j["simulated_time"] = sim.time();
    j["steps"] = sim.step_count();
    j["neighbor_rebuilds"] = sim.neighbor_rebuilds();
    // This process's (on several, each one's is in partition.memory).
    j["listed_neighbours"] = {{"at_first_build", sim.listed_at_first_build()}, {"most", sim.most_listed()}};
    j["largest_number_density_ratio"] = {{"value", sim.largest_number_density_ratio()},
                                         {"time", sim.largest_number_density_ratio_time()}};
    const ViscousSolveStats& vs = sim.viscous_solves();
    j["viscous_scheme"] = to_string(sim.options.viscous_scheme);
    j["viscous_solves"] = {{"solves", vs.solves},
                           {"mean_iterations", vs.solves ? double(vs.iterations) / vs.solves : 0.0},
                           {"most_iterations", vs.most_iterations},
                           {"largest_residual", vs.largest_residual},
                           {"unconverged", vs.unconverged}};
    j["setup_seconds"] = setup_seconds;
    j["wall_seconds"] = wall;
    j["cpu_seconds"] = process_cpu_seconds();
    j["loop_cpu_seconds"] = process_cpu_seconds() - cpu_at_loop_start;
    j["particle_steps_per_second"] = loop_rate(wall);
    j["peak_resident_bytes"] = peak_resident_bytes();
    j["resident_bytes_at_start"] = resident_bytes_at_start;
    j["memory_estimate_bytes"] = scene->memory_estimate_bytes;
    j["memory_estimate_list_growth_bytes"] = scene->memory_list_growth_bytes;  // its allowance for the list's growth
    j["pair_lanes"] = pair_lanes;
    j["snapshots"] = outputs->snapshot_count();
    j["left_the_domain"] = left_the_domain_json(whole);
    j["scene"] = to_json(scene->resolved);
    for (auto it = extra.begin(); it != extra.end(); ++it) j[it.key()] = it.value();
    write_file_atomically(out / "run.json", j.dump(2) + "\n");
  };

  // A write past a file-size limit (ulimit -f) fails with EFBIG instead of killing the process, so that it is
  // reported like a full disk.
  std::signal(SIGXFSZ, SIG_IGN);
  LastGoodState<D> last_good(sim);
  try {
    gather();
    if (writes && !run->resumed_from) outputs->write_initial();
    others_join_snapshot(!run->resumed_from && scene->output.snapshots);
    write_run_json("running", "", json::object());

    InterruptWatch<D> interrupt(args.stop_at, args.world.get());
    ProgressLine<D> progress(loop_start, scene->end_time, sim);
    std::vector<StepObserver<D>*> observers{&interrupt, &last_good};
    if (processes) observers.push_back(&*processes->observer);
    else observers.insert(observers.end(), {&*outputs, &*checkpoints});
    if (!args.quiet) observers.push_back(&progress);
    const AdvanceResult result = advance<D>(sim, scene->end_time, observers);
    std::signal(SIGINT, previous_sigint);
    std::signal(SIGTERM, previous_sigterm);

    if (result.outcome == AdvanceResult::Outcome::stopped) {
      // The checkpoint first: it records the series as a straight run has it, without the final snapshot below.
      checkpoints->write();
      gather();
      if (writes) {
        outputs->write_snapshot(whole.particles(), sim.time(), sim.step_count());
        outputs->flush();
      }
      others_join_snapshot(scene->output.snapshots);
      const int signal = interrupted;
      const std::string why = signal == 0 ? "stopped as --stop-at asked" : signal == SIGTERM ? "interrupted by SIGTERM"
                                                                                            : "interrupted by SIGINT";
      const std::string msg =
          fmt::format("{} at t = {:.6g} s (step {}); final snapshot and checkpoint written: continue with slide run "
                      "--resume {} (on any number of processes)",
                      why, sim.time(), sim.step_count(), out.string());
      write_run_json(signal == 0 ? "stopped" : "interrupted", msg, json::object());
      if (signal != 0 || !args.quiet) std::cerr << "\nslide: " << msg << "\n";
      return signal == 0 ? 0 : 128 + signal;
    }
    if (const auto& bad = result.instability) {
      gather();  // run.json's counts of the failed state (every process found the same instability)
      // Several processes: each kept its own particles' last good state, and gives it to the snapshot.
      if (!processes) outputs->write_snapshot(last_good.snapshot, last_good.time, last_good.step);
      else if (scene->output.snapshots) shared_snapshot(last_good.snapshot, last_good.time, last_good.step);
      if (writes) outputs->flush();
      const std::string where = bad->position.size() >= 2 ? position_text(bad->position) : "";
      const std::string msg = fmt::format(
          "unstable at t = {:.6g} s (step {}): particle {} at {}: {}; last good snapshot: t = {:.6g} s (step {})",
          bad->time, bad->step, bad->particle, where, bad->reason, last_good.time, last_good.step);
      write_run_json("unstable", msg,
                     {{"instability",
                       {{"time", bad->time},
                        {"step", bad->step},
                        {"particle", bad->particle},
                        {"position", bad->position},
                        {"reason", bad->reason},
                        {"last_good_time", last_good.time},
                        {"last_good_step", last_good.step}}}});
      std::cerr << "\nslide: " << msg << "\n";
      return 3;
    }
    gather();
    std::int64_t final_snapshot = writes && outputs->final_snapshot_due() ? 1 : 0;  // (the first process knows)
    if (processes) processes->world->max(&final_snapshot, 1);
    if (writes) outputs->write_final();
    others_join_snapshot(final_snapshot != 0);
    const double wall = std::chrono::duration<double>(Clock::now() - loop_start).count();
    const std::string msg =
        fmt::format("completed t = {:.6g} s in {} steps, {:.3f} s wall, {:.4g} M particle-steps/s; time-step limits: {}",
                    sim.time(), sim.step_count(), wall, loop_rate(wall) / 1e6, limit_summary(sim.limit_counts())) +
        (processes ? fmt::format(" on {} processes", processes->world->size()) : std::string()) +
        left_the_domain_note(whole);
    write_run_json("completed", msg, json::object());
    if (!args.quiet) std::cerr << "\r" << std::string(100, ' ') << "\rslide: " << msg << "\n";
    return 0;
  } catch (const std::exception& e) {
    // A failed write (a full disk, a file-size limit) or anything unexpected. Every file written before is whole
    // (each is written under a temporary name and renamed); the last good state is written too where it still can be.
    // Several processes: this one alone failed, and the others may wait for it; it says why, writes what it can
    // without them, and its exit 1 stops them all (tools/slide_main.cpp).
    std::signal(SIGINT, previous_sigint);
    std::signal(SIGTERM, previous_sigterm);
    if (processes) speak_up();
    const std::string msg = fmt::format("stopped at t = {:.6g} s (step {}) by an error{}: {}; the files written before "
                                        "are intact",
                                        sim.time(), sim.step_count(),
                                        processes ? fmt::format(" on process {}", processes->world->rank()) : "",
                                        e.what());
    std::cerr << "\nslide: error: " << msg << "\n";
    try {
      // Only a state newer than the last snapshot: the series stays in time order.
      if (!processes && last_good.time > outputs->last_snapshot_time())
        outputs->write_snapshot(last_good.snapshot, last_good.time, last_good.step);
      if (outputs) outputs->flush();
    } catch (const std::exception&) {
    }
    try {
      write_run_json("failed", msg, json::object());
    } catch (const std::exception&) {
    }
    return 1;
  }
}

// A resumed run's checkpoint: whole on each process, or where it is built in parts a part of its particles each (the
// first checks the whole file's checksum; where it refuses, refused_anywhere stops the others with it).
Checkpoint read_resumed_checkpoint(const RunArguments& args, int dimension) {
  if (!built_in_parts(args, dimension)) return read_checkpoint(args.resume);
  const auto rank = static_cast<std::uint64_t>(args.world->rank());
  return read_checkpoint_part(args.resume, rank, static_cast<std::uint64_t>(args.world->size()), rank == 0);
}

}  // namespace

int run_command(const RunArguments& args) {
  const auto setup_start = Clock::now();
  // The program's own memory (code, libraries, runtime) before any scene: what the particles cost is the peak above it.
  const double resident_bytes_at_start = cases::program_resident_bytes();
  if (args.threads < 0) {
    std::cerr << "slide: --threads must be at least 1 (got " << args.threads << ")\n";
    return 2;
  }
  if (args.threads > 0) set_thread_count(args.threads);
  // The scene's dimension decides which simulation runs: from the scene file, or from the checkpoint's scene.
  std::optional<YAML::Node> resolved;
  std::optional<Checkpoint> checkpoint;
  int dimension = 2;
  bool refused = false;  // on several processes, every one reads the files (refused_anywhere)
  if (args.resume.empty()) {
    resolved = resolve_or_report(args);
    refused = !resolved;
    if (resolved) dimension = cases::scene_dimension(*resolved);
  } else {
    try {
      // The header says how the state is read (a damaged one is read whole, which checks the checksum first and names
      // the fault; a scene the checkpoint cannot give back too: prepare_resumed_run says why).
      try {
        dimension = cases::scene_dimension(cases::load_yaml_text(read_checkpoint_header(args.resume).resolved_scene));
      } catch (const std::exception&) {
        dimension = 2;
      }
      checkpoint = read_resumed_checkpoint(args, dimension);
    } catch (const CheckpointError& e) {
      std::cerr << "slide: --resume " << args.resume.string() << ": " << e.what() << "; nothing was run or written\n";
      refused = true;
    }
  }
  if (refused_anywhere(args, refused)) return 2;
  return dimension == 3 ? run_scene<3>(args, resolved, std::move(checkpoint), setup_start, resident_bytes_at_start)
                        : run_scene<2>(args, resolved, std::move(checkpoint), setup_start, resident_bytes_at_start);
}

}  // namespace slide::tools
