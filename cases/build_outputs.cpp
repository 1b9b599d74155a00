// Step: what a run writes besides the particles' state: wave gauges, the dam-break surge front, the velocity
// profile, free-surface profiles, and the output intervals.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "cases/csv_table.hpp"
#include "cases/scene_build.hpp"

namespace slide::cases {
namespace {

std::vector<GaugeSpec> read_gauges(const YAML::Node& list) {
  std::vector<GaugeSpec> out;
  for (std::size_t k = 0; k < list.size(); ++k)
    out.push_back({list[k]["name"].as<std::string>(), list[k]["x"].as<double>(),
                   list[k]["y"] ? list[k]["y"].as<double>() : 0.0});
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

// profiles: times in increasing order, spacing 0 = dp; 2-D: x_max > x_min when there are times; 3-D: from and to
// distinct.
template <int D>
ProfileSpec read_profiles(const YAML::Node& pn, double dp) {
  ProfileSpec out;
  if (!pn) return out;
  for (const auto& t : pn["times"]) out.times.push_back(t.as<double>());
  if (!std::is_sorted(out.times.begin(), out.times.end()))
    throw SceneError("profiles.times", "must be in increasing order");
  if constexpr (D == 2) {
    out.from = {pn["x_min"].as<double>(), 0.0};
    out.to = {pn["x_max"].as<double>(), 0.0};
    if (!out.times.empty() && !(out.to[0] > out.from[0])) throw SceneError("profiles.x_max", "must exceed profiles.x_min");
  } else {
    out.from = {pn["from"][0].as<double>(), pn["from"][1].as<double>()};
    out.to = {pn["to"][0].as<double>(), pn["to"][1].as<double>()};
    if (!out.times.empty() && out.from == out.to) throw SceneError("profiles.to", "must differ from profiles.from");
  }
  out.spacing = pn["spacing"].as<double>() > 0 ? pn["spacing"].as<double>() : dp;
  return out;
}

// A CSV file a scene key names; SceneError naming the key when it cannot be read.
CsvTable read_scene_csv(const std::filesystem::path& path, const std::string& key) {
  try {
    return read_csv(path);
  } catch (const std::runtime_error&) {
    throw SceneError(key, "cannot read " + path.string());
  }
}

// diagnostics.slide_shapes: the measured surfaces grouped by their time (rows in any order), in increasing time.
std::optional<SlideShapesSpec> read_slide_shapes(const std::filesystem::path& scene_dir, const YAML::Node& sn) {
  const std::string file = sn["file"].as<std::string>();
  if (file.empty()) return std::nullopt;
  const std::string key = "diagnostics.slide_shapes.file";
  const std::filesystem::path path = scene_dir / file;
  const CsvTable t = read_scene_csv(path, key);
  const int ct = t.find_column("t_exp_s"), cx = t.find_column("x_m"), cy = t.find_column("y_m");
  if (ct < 0 || cx < 0 || cy < 0)
    throw SceneError(key, path.string() + ": the header must name the columns t_exp_s, x_m and y_m");
  std::map<double, std::vector<Vec<2>>> by_time;
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    try {
      const auto& f = t.rows[k];
      const double time = std::stod(f.at(ct)), x = std::stod(f.at(cx)), y = std::stod(f.at(cy));
      if (!std::isfinite(time) || !std::isfinite(x) || !std::isfinite(y)) throw std::invalid_argument("not finite");
      by_time[time].emplace_back(x, y);
    } catch (const std::exception&) {
      throw SceneError(key, fmt::format("{} line {}: t_exp_s, x_m and y_m must be finite numbers", path.string(),
                                        t.line_numbers[k]));
    }
  }
  if (by_time.size() < 2) throw SceneError(key, path.string() + ": needs the start and at least one later time");
  SlideShapesSpec spec{file, sn["time_offset"].as<double>(), {}};
  for (auto& [time, points] : by_time) spec.shapes.push_back({time, std::move(points)});
  if (spec.shapes.front().time_measured + spec.time_offset < 0.0)
    throw SceneError("diagnostics.slide_shapes.time_offset", "the first measured time falls before t = 0");
  return spec;
}

// A cell that is a number and nothing else (std::stod alone takes "1.5x" as 1.5); std::invalid_argument otherwise.
double whole_number(const std::string& cell) {
  std::size_t used = 0;
  const double v = std::stod(cell, &used);
  if (cell.find_first_not_of(" \t", used) != std::string::npos) throw std::invalid_argument("trailing text");
  return v;
}

// diagnostics.gauge_records: a time_s column, increasing, and one column per gauge of the scene, every cell finite.
std::optional<GaugeRecordsSpec> read_gauge_records(const std::filesystem::path& scene_dir, const YAML::Node& gn,
                                                   const std::vector<GaugeSpec>& gauges) {
  const std::string file = gn["file"].as<std::string>();
  if (file.empty()) return std::nullopt;
  const std::string key = "diagnostics.gauge_records.file";
  const std::filesystem::path path = scene_dir / file;
  const CsvTable t = read_scene_csv(path, key);
  const int ct = t.find_column("time_s");
  if (ct < 0 || t.header.size() < 2)
    throw SceneError(key, path.string() + ": the header must name a column time_s and at least one gauge");
  GaugeRecordsSpec spec{file, gn["time_offset"].as<double>(), gn["until"].as<double>(), {}, {}};
  std::vector<std::size_t> columns;
  for (std::size_t c = 0; c < t.header.size(); ++c) {
    if (static_cast<int>(c) == ct) continue;
    const std::string& name = t.header[c];
    if (std::none_of(gauges.begin(), gauges.end(), [&](const GaugeSpec& g) { return g.name == name; }))
      throw SceneError(key, path.string() + ": column '" + name + "' names no gauge of the scene (gauges[].name)");
    spec.gauges.push_back({name, {}});
    columns.push_back(c);
  }
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    try {
      const auto& f = t.rows[k];
      if (f.size() != t.header.size()) throw std::invalid_argument("short");
      const double time = whole_number(f.at(ct));
      if (!std::isfinite(time) || (!spec.time_measured.empty() && !(time > spec.time_measured.back())))
        throw std::invalid_argument("time");
      spec.time_measured.push_back(time);
      for (std::size_t g = 0; g < columns.size(); ++g) {
        const double e = whole_number(f.at(columns[g]));
        if (!std::isfinite(e)) throw std::invalid_argument("not finite");
        spec.gauges[g].elevation.push_back(e);
      }
    } catch (const std::exception&) {
      throw SceneError(key, fmt::format("{} line {}: needs {} finite numbers, time_s increasing", path.string(),
                                        t.line_numbers[k], t.header.size()));
    }
  }
  if (spec.time_measured.size() < 2) throw SceneError(key, path.string() + ": needs at least two rows");
  return spec;
}

OutputSpec read_output(const YAML::Node& on) {
  OutputSpec spec{on["snapshots"].as<bool>(), on["snapshot_interval"].as<double>(), on["gauge_interval"].as<double>(),
                  on["checkpoint_interval"].as<double>()};
  for (const auto& field : on["snapshot_fields"]) {
    const std::string name = field.as<std::string>();
    if (std::find(spec.snapshot_fields.begin(), spec.snapshot_fields.end(), name) != spec.snapshot_fields.end())
      throw SceneError("output.snapshot_fields", "'" + name + "' is listed twice");
    spec.snapshot_fields.push_back(name);
  }
  spec.snapshot_single_precision = on["snapshot_precision"].as<std::string>() == "single";
  spec.snapshot_deflate = on["snapshot_compression"].as<std::string>() == "deflate";
  return spec;
}

}  // namespace

// The keys a 3-D scene does not have (the diagnostics other than gauge_records: cases/load_scene.cpp) are
// absent from its resolved scene, and their specs stay off.
template <int D>
void read_outputs(SceneBuild<D>& b) {
  const YAML::Node& r = b.r;  // (b is of a dependent type: r's .as<T>() needs no 'template')
  Scene<D>& scene = *b.scene;
  const YAML::Node diagnostics = r["diagnostics"];
  scene.gauges = read_gauges(r["gauges"]);
  if (diagnostics && diagnostics["surge_front"]) {
    scene.surge_front = read_surge_front(diagnostics["surge_front"]);
    scene.velocity_profile = read_velocity_profile(diagnostics["velocity_profile"], b.options().lattice, b.dp);
  }
  scene.profiles = read_profiles<D>(r["profiles"], b.dp);
  scene.output = read_output(r["output"]);
  if (diagnostics && diagnostics["slide_shapes"])
    scene.slide_shapes = read_slide_shapes(b.scene_dir, diagnostics["slide_shapes"]);
  if (diagnostics) scene.gauge_records = read_gauge_records(b.scene_dir, diagnostics["gauge_records"], scene.gauges);
  if (scene.gauge_records) {
    const auto& g = *scene.gauge_records;
    const double first = g.time_measured.front() + g.time_offset, last = g.time_measured.back() + g.time_offset;
    if (first > scene.end_time || last < 0.0)
      throw SceneError("diagnostics.gauge_records.time_offset",
                       fmt::format("the records cover model times [{:.6g}, {:.6g}] s, outside the run's [0, {:.6g}] s",
                                   first, last, scene.end_time));
    if (g.until > 0.0 && g.until < std::max(first, 0.0))
      throw SceneError("diagnostics.gauge_records.until",
                       fmt::format("{:.6g} s ends the comparison before the records start (model time {:.6g} s)",
                                   g.until, std::max(first, 0.0)));
  }
  for (const auto& t : r["output"]["slide_outline_times"]) scene.slide_outline_times.push_back(t.as<double>());
  if (!std::is_sorted(scene.slide_outline_times.begin(), scene.slide_outline_times.end()))
    throw SceneError("output.slide_outline_times", "must be in increasing order");
}

template void read_outputs(SceneBuild<2>&);
template void read_outputs(SceneBuild<3>&);

}  // namespace slide::cases
