// Building a simulation from a resolved scene (cases/load_scene.cpp reads one) as a list of named steps (each in its
// own file under cases/, sharing a SceneBuild: cases/scene_build.hpp).
#include "cases/scene.hpp"

#include <stdexcept>

#include "cases/scene_build.hpp"

namespace slide::cases {

template <int D>
std::unique_ptr<Scene<D>> build_scene(const YAML::Node& r, const std::string& default_name,
                                      const std::filesystem::path& scene_dir, StartOfRun start) {
  if (scene_dimension(r) != D)
    throw SceneError("dimension", "a " + std::to_string(scene_dimension(r)) + "-D scene given to the " +
                                      std::to_string(D) + "-D builder");
  SceneBuild<D> b(r, scene_dir);
  b.scene->resolved = r;
  b.scene->name = r["name"].as<std::string>().empty() ? default_name : r["name"].as<std::string>();
  b.scene->end_time = r["end_time"].as<double>();

  read_fluid_options(b);
  check_lattice_choices(b);
  check_period(b);
  check_particle_budget(b);  // before any particle is made
  b.phases = read_phases(r["fluid"]["phases"]);
  place_floating_bodies(b);  // before anything is laid around them
  build_walls(b);  // first: below_level regions need the faces, bodies the lattice offset and faces
  build_slides_and_bodies(b);
  fill_fluid_regions(b);
  check_overlaps(b);
  if constexpr (D == 2) check_fluid_contained(b);
  // The last to name particles by their keys: the names (a string a particle, 60 bytes a particle with the heap's)
  // are freed before the simulation's own arrays grow.
  std::vector<std::string>().swap(b.fluid_owner);  // (= {} would keep the storage)
  std::vector<std::string>().swap(b.boundary_owner);
  choose_sound_speed(b);
  start_hydrostatic(b);
  set_domain(b);
  count_particles(b);
  read_outputs(b);
  finish_bodies(b);
  set_phases(b);
  try {
    b.sim->initialise();
  } catch (const std::invalid_argument& e) {  // what the solver refuses: a periodic domain's set-up
    throw SceneError("domain.periodic_x", e.what());
  }
  check_run_memory(b);
  plan_settling(b);
  b.scene->simulation = std::move(b.sim);
  std::unique_ptr<Scene<D>> scene = std::move(b.scene);
  if (start == StartOfRun::settle_now) settle_now(*scene);
  else if (start == StartOfRun::already_settled) complete_start(*scene, std::nullopt);
  return scene;
}

template std::unique_ptr<Scene<2>> build_scene(const YAML::Node&, const std::string&, const std::filesystem::path&,
                                               StartOfRun);
template std::unique_ptr<Scene<3>> build_scene(const YAML::Node&, const std::string&, const std::filesystem::path&,
                                               StartOfRun);

}  // namespace slide::cases
