// Step: what a run writes besides the particles' state: wave gauges, the dam-break surge front, the velocity
// profile, free-surface profiles, and the output intervals.
#include <algorithm>

#include "cases/scene_build.hpp"

namespace slide::cases {
namespace {

std::vector<GaugeSpec> read_gauges(const YAML::Node& list) {
  std::vector<GaugeSpec> out;
  for (std::size_t k = 0; k < list.size(); ++k)
    out.push_back({list[k]["name"].as<std::string>(), list[k]["x"].as<double>()});
  return out;
}

SurgeFrontSpec read_surge_front(const YAML::Node& sf) {
  return {sf["enabled"].as<bool>(), sf["wall_face_x"].as<double>(), sf["floor_y"].as<double>(),
          sf["column_width"].as<double>()};
}

// diagnostics.velocity_profile: bin 0 = the lattice's row spacing (one row of particles a bin).
VelocityProfileSpec read_velocity_profile(const YAML::Node& vp, LatticeKind lattice, double dp) {
  const double bin = vp["bin"].as<double>();  // >= 0 by the schema
  return {vp["enabled"].as<bool>(), vp["y_origin"].as<double>(), bin > 0.0 ? bin : row_spacing(lattice, dp)};
}

// profiles: times in increasing order, x_max > x_min when there are times, spacing 0 = dp.
ProfileSpec read_profiles(const YAML::Node& pn, double dp) {
  ProfileSpec out;
  if (!pn) return out;
  for (const auto& t : pn["times"]) out.times.push_back(t.as<double>());
  if (!std::is_sorted(out.times.begin(), out.times.end()))
    throw SceneError("profiles.times", "must be in increasing order");
  out.x_min = pn["x_min"].as<double>();
  out.x_max = pn["x_max"].as<double>();
  if (!out.times.empty() && !(out.x_max > out.x_min)) throw SceneError("profiles.x_max", "must exceed profiles.x_min");
  out.spacing = pn["spacing"].as<double>() > 0 ? pn["spacing"].as<double>() : dp;
  return out;
}

OutputSpec read_output(const YAML::Node& on) {
  return {on["snapshots"].as<bool>(), on["snapshot_interval"].as<double>(), on["gauge_interval"].as<double>(),
          on["checkpoint_interval"].as<double>()};
}

}  // namespace

void read_outputs(SceneBuild& b) {
  Scene& scene = *b.scene;
  scene.gauges = read_gauges(b.r["gauges"]);
  scene.surge_front = read_surge_front(b.r["diagnostics"]["surge_front"]);
  scene.velocity_profile = read_velocity_profile(b.r["diagnostics"]["velocity_profile"], b.options().lattice, b.dp);
  scene.profiles = read_profiles(b.r["profiles"], b.dp);
  scene.output = read_output(b.r["output"]);
  for (const auto& t : b.r["output"]["slide_outline_times"]) scene.slide_outline_times.push_back(t.as<double>());
  if (!std::is_sorted(scene.slide_outline_times.begin(), scene.slide_outline_times.end()))
    throw SceneError("output.slide_outline_times", "must be in increasing order");
}

}  // namespace slide::cases
