// Reading a scene file, and building a simulation from a resolved scene as a list of named steps (each in its own
// file under cases/, sharing a SceneBuild: cases/scene_build.hpp).
#include "cases/scene.hpp"

#include <set>
#include <stdexcept>

#include "cases/duplicate_keys.hpp"
#include "cases/scene_build.hpp"

namespace slide::cases {

SceneBuild::SceneBuild(const YAML::Node& resolved, const std::filesystem::path& dir) : r(resolved), scene_dir(dir) {}

YAML::Node load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  YAML::Node raw;
  try {
    raw = YAML::LoadFile(file.string());
  } catch (const YAML::BadFile&) {
    throw SceneError("<file>", "cannot read scene file " + file.string());
  } catch (const YAML::Exception& e) {
    throw SceneError("<file>", "not valid YAML: " + std::string(e.what()));
  }
  if (!raw.IsMap()) throw SceneError("<root>", "a scene file must be a YAML mapping");
  if (const auto d = find_duplicate_key(raw)) throw SceneError(d->path, duplicate_key_message(*d));
  std::set<std::string> overridden;  // a key set twice on the command line is as ambiguous as twice in the file
  for (const auto& o : overrides) {
    const std::string path = o.substr(0, o.find('='));
    if (!overridden.insert(path).second) throw SceneError("--set", "key " + path + " is set twice; keep one");
    apply_override(raw, o);
  }
  return scene_schema().resolve(raw);
}

std::unique_ptr<Scene> build_scene(const YAML::Node& r, const std::string& default_name,
                                   const std::filesystem::path& scene_dir, bool for_resume) {
  SceneBuild b(r, scene_dir);
  b.scene->resolved = r;
  b.scene->name = r["name"].as<std::string>().empty() ? default_name : r["name"].as<std::string>();
  b.scene->end_time = r["end_time"].as<double>();

  read_fluid_options(b);
  check_lattice_choices(b);
  check_period(b);
  check_particle_budget(b);  // before any particle is made
  b.phases = read_phases(r["fluid"]["phases"]);
  build_walls(b);  // first: below_level regions need the faces, bodies the lattice offset and faces
  build_slides_and_bodies(b);
  fill_fluid_regions(b);
  check_overlaps(b);
  check_fluid_contained(b);
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
  if (!for_resume) settle(b);
  lift_gates(b);

  b.scene->simulation = std::move(b.sim);
  return std::move(b.scene);
}

}  // namespace slide::cases
