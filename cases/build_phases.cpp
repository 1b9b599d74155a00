// Step: the fluid phases (fluid.phases), by name and index, with each one's density and viscosity.
#include <fmt/format.h>

#include "cases/scene_build.hpp"

namespace slide::cases {

std::size_t ScenePhases::find(const std::string& name, const std::string& key) const {
  const std::string wanted = name.empty() ? phases.front().name : name;
  const auto it = index.find(wanted);
  if (it == index.end()) throw SceneError(key, "no phase named \"" + wanted + "\" in fluid.phases");
  return it->second;
}

ScenePhases read_phases(const YAML::Node& list) {
  ScenePhases out;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const auto ph = list[k];
    const std::string name = ph["name"].as<std::string>();
    if (out.index.count(name))
      throw SceneError(fmt::format("fluid.phases[{}].name", k), "duplicate phase name \"" + name + "\"");
    out.index[name] = k;
    out.phases.push_back({name, ph["density"].as<double>(), ph["viscosity"].as<double>()});
  }
  return out;
}

}  // namespace slide::cases
