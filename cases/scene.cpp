// Building a simulation from a resolved scene (cases/load_scene.cpp reads one) as a list of named steps (each in its
// own file under cases/, sharing a SceneBuild: cases/scene_build.hpp).
#include "cases/scene.hpp"

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>

#include "cases/scene_build.hpp"

namespace slide::cases {

namespace {

// The options, and every particle as placed on the lattice (its part, in a scene built in parts).
template <int D>
void lay_particles(SceneBuild<D>& b) {
  const YAML::Node& r = b.r;
  read_fluid_options(b);
  check_lattice_choices(b);
  check_period(b);
  check_particle_budget(b);  // before any particle is made
  b.phases = read_phases(r["fluid"]["phases"]);
  place_floating_bodies(b);  // before anything is laid around them
  build_walls(b);  // first: below_level regions need the faces, bodies the lattice offset and faces
  build_slides_and_bodies(b);
  fill_fluid_regions(b);
}

// A 3-D scene on several processes is built in parts (cases/build_share.hpp): a counting pass over every lattice
// point, in a build of its own that makes no particle, chooses each process's part.
template <int D>
void share_the_build(SceneBuild<D>& b) {
  if constexpr (D == 3) {
    if (!b.processes) return;
    auto count = std::make_unique<BuildCount>();
    SceneBuild<3> counting(b.r, b.scene_dir);
    counting.counting = count.get();
    counting.machine = b.machine;
    lay_particles(counting);
    const double re_over_dp = counting.sim->options.re_over_dp;
    b.share.emplace(*count, counting.dp, static_cast<long>(std::ceil(re_over_dp)) + 2, b.processes->size(),
                    b.processes->rank());
    b.counted = std::move(count);
  }
}

// A scene built in parts: steps that may refuse one process's part alone (its memory, an overlap in it) are agreed
// before the next step that reduces across the processes, so that every process stops there together.
template <int D, class Steps>
void agreed(SceneBuild<D>& b, Steps&& steps) {
  if (!b.processes) return steps();
  std::optional<SceneError> refused;
  try {
    steps();
  } catch (const SceneError& e) {
    refused = e;
  }
  std::int64_t anywhere = refused ? 1 : 0;
  b.processes->max(&anywhere, 1);
  if (refused) throw *refused;
  if (anywhere != 0) throw RefusedOnAnotherProcess("processes", "another process refused the scene");
}

// Everything before the neighbour list: the options, the particles and their starting state, the outputs' keys.
template <int D>
void make_particles(SceneBuild<D>& b) {
  agreed(b, [&] {
    share_the_build(b);
    lay_particles(b);
    check_overlaps(b);
    if constexpr (D == 2) check_fluid_contained(b);
  });
  // The last to name particles by their keys: the names (a string a particle, 60 bytes a particle with the heap's)
  // are freed before the simulation's own arrays grow.
  std::vector<std::string>().swap(b.fluid_owner);  // (= {} would keep the storage)
  std::vector<std::string>().swap(b.boundary_owner);
  choose_sound_speed(b);
  start_hydrostatic(b);
  b.scene->particles_made_here = b.particles().size();
  keep_own_columns(b);  // the last step that reads across columns is done
  agreed(b, [&] { set_domain(b); });
  count_particles(b);
  read_outputs(b);
  finish_bodies(b);
  set_phases(b);
}

}  // namespace

template <int D>
std::unique_ptr<Scene<D>> build_scene(const YAML::Node& r, const std::string& default_name,
                                      const std::filesystem::path& scene_dir, StartOfRun start,
                                      const ForProcesses& for_processes) {
  if (scene_dimension(r) != D)
    throw SceneError("dimension", "a " + std::to_string(scene_dimension(r)) + "-D scene given to the " +
                                      std::to_string(D) + "-D builder");
  SceneBuild<D> b(r, scene_dir);
  const std::shared_ptr<const Communicator>& share = for_processes.share;
  const bool shared = share && share->size() > 1;
  // Several processes build a 3-D scene in parts (cases/build_share.hpp), a 2-D one whole each.
  if (shared && D == 3) b.processes = share.get();
  b.scene->resolved = r;
  b.scene->name = r["name"].as<std::string>().empty() ? default_name : r["name"].as<std::string>();
  b.scene->end_time = r["end_time"].as<double>();
  // Several processes make the particles each (the same, or their parts), then initialise() shares them, a
  // collective: a refusal before it on one process alone (a file it cannot read, its memory, an overlap in its part)
  // is agreed first, and the others stop with it.
  std::optional<SceneError> refused;
  bool refused_elsewhere = false;  // (a part's refusal, agreed within make_particles: the refusing process says why)
  b.machine = for_processes.machine;
  try {
    make_particles(b);
  } catch (const RefusedOnAnotherProcess&) {
    if (!shared) throw;
    refused_elsewhere = true;
  } catch (const SceneError& e) {
    if (!shared) throw;
    refused = e;
  }
  if (shared) {
    std::int64_t anywhere = refused ? 1 : 0;
    share->max(&anywhere, 1);
    if (refused) throw *refused;
    if (anywhere != 0 || refused_elsewhere)
      throw RefusedOnAnotherProcess("processes", "another process refused the scene");
    // (The observers' copy, built in parts like the run, stays one process's: its particles come from the run.)
    if (!for_processes.observers_copy) b.sim->set_communicator(share, !b.share);
  }
  if (for_processes.observers_copy) {
    b.sim->make_observers_copy(b.scene->surge_front.enabled);
    // Built in parts, the copy holds its part: its id range is still the whole scene's (drop_copy_particles).
    if (b.share) b.particles().removed_count = static_cast<std::size_t>(b.made) - b.particles().real_count();
  }
  try {
    b.sim->initialise();
  } catch (const TooManyProcesses& e) {
    throw SceneError("processes", e.what());
  } catch (const std::invalid_argument& e) {  // what the solver refuses: a periodic domain's set-up
    throw SceneError("domain.periodic_x", e.what());
  }
  if (!for_processes.observers_copy) check_run_memory(b);  // (the copy's memory is counted in the running scene's)
  plan_settling(b);
  b.scene->simulation = std::move(b.sim);
  std::unique_ptr<Scene<D>> scene = std::move(b.scene);
  if (start == StartOfRun::settle_now) settle_now(*scene);
  else if (start == StartOfRun::already_settled) complete_start(*scene, std::nullopt);
  return scene;
}

template std::unique_ptr<Scene<2>> build_scene(const YAML::Node&, const std::string&, const std::filesystem::path&,
                                               StartOfRun, const ForProcesses&);
template std::unique_ptr<Scene<3>> build_scene(const YAML::Node&, const std::string&, const std::filesystem::path&,
                                               StartOfRun, const ForProcesses&);

}  // namespace slide::cases
