#include "tools/measures/floating_draft.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "tools/measures/series.hpp"

namespace slide::tools {
namespace {

// The first body's rows of bodies.csv: time and centre height.
void first_body(const CsvTable& bodies, std::vector<double>& t, std::vector<double>& y) {
  const auto times = bodies.numbers("time"), ys = bodies.numbers("y");
  const int body = bodies.find_column("body");
  for (std::size_t k = 0; k < times.size(); ++k)
    if (body < 0 || bodies.rows[k][body] == bodies.rows[0][body]) t.push_back(times[k]), y.push_back(ys[k]);
}

}  // namespace

FloatingDraft floating_draft(const CsvTable& gauges, const CsvTable& bodies, double height_m, double body_density,
                             double water_density, double from_time) {
  std::vector<double> body_t, body_y;
  first_body(bodies, body_t, body_y);
  if (body_t.empty()) throw std::runtime_error("bodies.csv has no rows");
  const auto times = gauges.numbers("time");
  std::vector<double> t, draft;
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (times[k] < from_time) continue;
    // The body's rows must cover the gauges' times: no reading beyond its ends.
    if (times[k] < body_t.front() || times[k] > body_t.back())
      throw std::runtime_error("gauges.csv has a row at t = " + std::to_string(times[k]) +
                               " s, outside the times of bodies.csv");
    double level = 0.0;
    int n = 0;
    for (std::size_t c = 0; c < gauges.header.size(); ++c)
      if (gauges.header[c] != "time") level += std::stod(gauges.rows[k].at(c)), ++n;
    if (n == 0 || !std::isfinite(level)) continue;  // a gauge without water there: the mean bridges the row
    t.push_back(times[k]);
    draft.push_back(level / n - (interpolate(body_t, body_y, times[k]) - 0.5 * height_m));
  }
  if (t.size() < 2) throw std::runtime_error("fewer than two gauge rows with a level at every gauge from t = " +
                                             std::to_string(from_time) + " s");
  double area = 0.0;
  for (std::size_t k = 1; k < t.size(); ++k) area += 0.5 * (draft[k] + draft[k - 1]) * (t[k] - t[k - 1]);
  FloatingDraft d;
  d.draft_m = area / (t.back() - t.front());
  d.exact_m = body_density / water_density * height_m;
  d.relative_error = std::abs(d.draft_m / d.exact_m - 1.0);
  return d;
}

FloatingDraft floating_draft(const std::filesystem::path& run_folder, double from_time) {
  std::ifstream in(run_folder / "run.json");
  const nlohmann::json run = nlohmann::json::parse(in);
  const auto& scene = run.at("scene");
  const auto& body = scene.at("bodies").at(0);
  const auto& shape = body.at("shape");
  if (shape.at("type") != "box" || shape.value("angle", 0.0) != 0.0)
    throw std::runtime_error("floating_draft needs bodies[0] to be an upright box (shape.type box, angle 0)");
  const double width = shape.at("size").at(0).get<double>(), height = shape.at("size").at(1).get<double>();
  const double density = body.value("density", 0.0) > 0.0 ? body.at("density").get<double>()
                                                            : body.at("mass").get<double>() / (width * height);
  const double water = scene.at("fluid").at("phases").at(0).at("density").get<double>();
  return floating_draft(read_csv(run_folder / "gauges.csv"), read_csv(run_folder / "bodies.csv"), height, density,
                        water, from_time);
}

}  // namespace slide::tools
