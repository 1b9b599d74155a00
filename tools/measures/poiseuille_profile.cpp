#include "tools/measures/poiseuille_profile.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>

namespace slide::tools {

PoiseuilleProfileError poiseuille_profile_error(const CsvTable& profile, const HbPoiseuille& exact, double centre) {
  const auto time = profile.numbers("time"), y = profile.numbers("y"), u = profile.numbers("u"),
             count = profile.numbers("particles");
  if (time.empty()) throw std::runtime_error("velocity_profile.csv has no rows");
  PoiseuilleProfileError e;
  e.time = time.back();
  const double u_max = exact.max_velocity();
  double sum2 = 0.0, nearest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < time.size(); ++k) {
    if (time[k] != e.time) continue;  // every row of one sample carries the same time text
    const double d = (u[k] - exact.velocity(y[k] - centre)) / u_max;
    sum2 += count[k] * d * d;
    e.particles += std::lround(count[k]);
    nearest = std::min(nearest, std::abs(y[k] - centre));
  }
  e.rms = std::sqrt(sum2 / std::max(1L, e.particles));
  // The centreline: the rows nearest the centre (two, either side, where the rows straddle it), by particles.
  double centre_sum = 0.0, centre_count = 0.0;
  for (std::size_t k = 0; k < time.size(); ++k)
    if (time[k] == e.time && std::abs(y[k] - centre) <= nearest + 1e-9 * exact.half_width)
      centre_sum += count[k] * u[k], centre_count += count[k];
  e.centreline = (centre_sum / centre_count - u_max) / u_max;
  return e;
}

namespace {

// The closed form of the scene's channel, and its centre.
HbPoiseuille closed_form(const nlohmann::json& scene, double& centre) {
  const auto& phase = scene.at("fluid").at("phases").at(0);
  const auto& rheology = phase.at("rheology");
  const std::string model = rheology.at("model");
  double K = 0.0, n = 1.0, tau0 = 0.0;
  if (model == "newtonian") {
    K = rheology.at("viscosity").get<double>();
  } else if (model == "herschel_bulkley") {
    K = rheology.at("consistency").get<double>();
    n = rheology.at("flow_index").get<double>();
    tau0 = rheology.at("yield_stress").get<double>();
  } else {
    throw std::runtime_error("poiseuille_profile needs fluid.phases[0] newtonian or herschel_bulkley, not " + model);
  }
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  for (const auto& wall : scene.at("walls"))
    for (const auto& p : wall.at("points")) {
      lowest = std::min(lowest, p.at(1).get<double>());
      highest = std::max(highest, p.at(1).get<double>());
    }
  if (!(highest > lowest)) throw std::runtime_error("poiseuille_profile needs walls at two heights");
  centre = 0.5 * (lowest + highest);
  const HbPoiseuille exact{K, n, tau0, phase.at("density").get<double>() * scene.at("gravity").at(0).get<double>(),
                           0.5 * (highest - lowest)};
  if (!(exact.body_force * exact.half_width > tau0))
    throw std::runtime_error("poiseuille_profile: the body force does not exceed the yield stress (G H <= tau0)");
  return exact;
}

}  // namespace

PoiseuilleProfileError poiseuille_profile_error(const std::filesystem::path& run_folder) {
  std::ifstream in(run_folder / "run.json");
  const nlohmann::json run = nlohmann::json::parse(in);
  double centre = 0.0;
  const HbPoiseuille exact = closed_form(run.at("scene"), centre);
  return poiseuille_profile_error(read_csv(run_folder / "velocity_profile.csv"), exact, centre);
}

}  // namespace slide::tools
