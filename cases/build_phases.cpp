// Step: the fluid phases (fluid.phases, and the deformable slides'), by name and index, with each one's density and
// rheology; the viscous scheme that follows from them.
#include <fmt/format.h>

#include "cases/scene_build.hpp"
#include "cases/viscous_scheme_choice.hpp"
#include "fluid/basal_friction.hpp"

namespace slide::cases {

std::size_t ScenePhases::find(const std::string& name, const std::string& key) const {
  const std::string wanted = name.empty() ? phases.front().name : name;
  const auto it = index.find(wanted);
  if (it == index.end()) throw SceneError(key, "no phase named \"" + wanted + "\" in fluid.phases");
  return it->second;
}

std::size_t ScenePhases::add(const std::string& name, double density, const Rheology& rheology, double basal_friction,
                             const std::string& key) {
  if (index.count(name)) throw SceneError(key, "duplicate phase name \"" + name + "\" (phases and deformable slides share names)");
  if (phases.size() >= 255) throw SceneError(key, "more than 255 phases");
  index[name] = phases.size();
  // A non-Newtonian phase's particles are made with its viscosity at rest; the rheology stage sets it from the first
  // step on (coupling/simulation.cpp).
  phases.push_back({name, density, effective_viscosity(rheology, 0.0, 0.0), rheology, basal_friction});
  return phases.size() - 1;
}

ScenePhases read_phases(const YAML::Node& list) {
  ScenePhases out;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const auto ph = list[k];
    out.add(ph["name"].as<std::string>(), ph["density"].as<double>(),
            read_rheology(ph["rheology"], fmt::format("fluid.phases[{}].rheology", k)),
            basal_friction_coefficient(ph["basal_friction_angle"].as<double>()), fmt::format("fluid.phases[{}].name", k));
  }
  return out;
}

// The phases as the simulation keeps them, and the viscous scheme (auto: implicit when some phase is non-Newtonian).
template <int D>
void set_phases(SceneBuild<D>& b) {
  const YAML::Node& r = b.r;  // (b is of a dependent type: r's .as<T>() needs no 'template')
  bool non_newtonian = false;
  for (const auto& p : b.phases.phases) {
    b.sim->phases.push_back(Phase{p.name, p.density, p.rheology, p.basal_friction});
    non_newtonian = non_newtonian || !std::holds_alternative<Newtonian>(p.rheology);
  }
  auto& o = b.options();
  switch (viscous_scheme_choice_names.parse(r["method"]["viscous_scheme"].as<std::string>())) {
    case ViscousSchemeChoice::automatic:
      o.viscous_scheme = non_newtonian ? ViscousScheme::implicit : ViscousScheme::explicit_;
      break;
    case ViscousSchemeChoice::explicit_: o.viscous_scheme = ViscousScheme::explicit_; break;
    case ViscousSchemeChoice::implicit: o.viscous_scheme = ViscousScheme::implicit; break;
  }
  o.implicit_tolerance = r["method"]["implicit_tolerance"].as<double>();
}

template void set_phases(SceneBuild<2>&);
template void set_phases(SceneBuild<3>&);

}  // namespace slide::cases
