// Reading a scene: the YAML text, duplicate keys refused, --set overrides applied, then checked and completed by the
// schema. Nothing here builds particles; the fuzz target (tests/fuzz/) drives exactly this.
#include <yaml-cpp/yaml.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "cases/duplicate_keys.hpp"
#include "cases/scene.hpp"
#include "cases/yaml_text.hpp"

namespace slide::cases {
namespace {

// The schema a scene is checked against follows its `dimension`: 3 for any text the schema reads as the integer 3
// ("3", "3.0", "+3", "03"), 2 otherwise; a value neither 2 nor 3 is left to the 2-D schema, which refuses it with its
// range.
int requested_dimension(const YAML::Node& raw) {
  const YAML::Node d = raw["dimension"];
  if (!d || !d.IsScalar()) return 2;
  const std::string& text = d.Scalar();
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size() && value == 3.0 ? 3 : 2;
}

// 2-D keys that 3-D scenes do not have yet: named as such rather than as unknown keys.
void refuse_keys_not_yet_in_3d(const YAML::Node& raw) {
  const auto refuse = [](const std::string& key) {
    throw SceneError(key, "3-D scenes (dimension: 3) have no " + key +
                              " yet: this key works in 2-D scenes only (cases/SCHEMA.md, 3-D scenes)");
  };
  const YAML::Node diagnostics = raw["diagnostics"];
  if (diagnostics && diagnostics.IsMap())
    for (const char* key : {"surge_front", "velocity_profile", "slide_shapes"})
      if (diagnostics[key]) refuse(std::string("diagnostics.") + key);
}

}  // namespace

YAML::Node load_scene_text(const std::string& text, const std::vector<std::string>& overrides) {
  YAML::Node raw;
  try {
    raw = load_yaml_text(text);
  } catch (const YamlTextRefused& e) {
    throw SceneError("<file>", e.what());
  }
  if (!raw.IsMap()) throw SceneError("<root>", "a scene file must be a YAML mapping");
  if (const auto d = find_duplicate_key(raw)) throw SceneError(d->path, duplicate_key_message(*d));
  std::set<std::string> overridden;  // a key set twice on the command line is as ambiguous as twice in the file
  for (const auto& o : overrides) {
    const std::string path = o.substr(0, o.find('='));
    if (!overridden.insert(path).second) throw SceneError("--set", "key " + path + " is set twice; keep one");
    apply_override(raw, o);
  }
  const int dimension = requested_dimension(raw);
  if (dimension == 3) refuse_keys_not_yet_in_3d(raw);
  return scene_schema(dimension).resolve(raw);
}

YAML::Node load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  std::ifstream in(file, std::ios::binary);
  if (!std::filesystem::is_regular_file(file) || !in)
    throw SceneError("<file>", "cannot read scene file " + file.string());
  std::ostringstream text;
  text << in.rdbuf();  // an empty file leaves text empty (and sets failbit on text, which is not an error here)
  return load_scene_text(text.str(), overrides);
}

}  // namespace slide::cases
