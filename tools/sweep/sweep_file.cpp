#include "tools/sweep/sweep_file.hpp"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <map>
#include <sstream>

#include "cases/duplicate_keys.hpp"
#include "cases/scene.hpp"
#include "cases/schema.hpp"
#include "cases/yaml_text.hpp"

namespace slide::tools {
namespace {

using cases::SceneError;

// A value as the YAML text `--set` parses back (flow style for lists and maps).
std::string yaml_text(const YAML::Node& v) {
  if (v.IsScalar()) return v.Scalar();
  YAML::Emitter e;
  e << YAML::Flow << v;
  return e.c_str();
}

YAML::Node load_yaml(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!std::filesystem::is_regular_file(file) || !in)
    throw SceneError("<file>", "cannot read sweep file " + file.string());
  std::ostringstream text;
  text << in.rdbuf();
  YAML::Node root;
  try {
    root = cases::load_yaml_text(text.str());
  } catch (const cases::YamlTextRefused& e) {
    throw SceneError("<file>", e.what());
  }
  if (!root.IsMap()) throw SceneError("<root>", "a sweep file must be a YAML mapping");
  if (const auto d = cases::find_duplicate_key(root)) throw SceneError(d->path, cases::duplicate_key_message(*d));
  return root;
}

// A scalar's text, or a SceneError naming the key.
std::string text(const YAML::Node& n, const std::string& key) {
  if (!n || !n.IsScalar()) throw SceneError(key, "must be a single value (a name or a number)");
  return n.Scalar();
}

std::filesystem::path beside(const std::filesystem::path& sweep_file, const std::string& name) {
  const std::filesystem::path p(name);
  return std::filesystem::absolute(p.is_absolute() ? p : sweep_file.parent_path() / p).lexically_normal();
}

// key=value overrides from a map of scene keys (the sweep's `set`).
std::vector<std::string> assignments(const YAML::Node& map, const std::string& where) {
  if (!map) return {};
  if (!map.IsMap()) throw SceneError(where, "must be a map of scene keys to values");
  std::vector<std::string> out;
  for (const auto& kv : map) out.push_back(kv.first.as<std::string>() + "=" + yaml_text(kv.second));
  return out;
}

void refuse_too_many_runs(std::size_t runs, std::size_t max_runs, const std::string& key) {
  if (runs > max_runs)
    throw SceneError(key, fmt::format("stands for {}{} runs, more than max_runs ({}); raise max_runs if you mean it",
                                      runs == SIZE_MAX ? "over " : "", runs == SIZE_MAX ? SIZE_MAX : runs, max_runs));
}

// The full grid over `vary`, the first key varying slowest; its size is checked before it is built.
void expand_grid(const YAML::Node& vary, std::size_t max_runs, Sweep& s) {
  if (!vary.IsMap() || vary.size() == 0) throw SceneError("vary", "must be a non-empty map of scene keys to lists");
  std::size_t runs = 1;  // saturates at SIZE_MAX
  for (const auto& kv : vary) {
    const std::size_t n = kv.second.IsSequence() ? kv.second.size() : 1;
    runs = n != 0 && runs > SIZE_MAX / n ? SIZE_MAX : runs * n;
  }
  refuse_too_many_runs(runs, max_runs, "vary");
  std::vector<std::vector<std::string>> values;
  for (const auto& kv : vary) {
    const std::string key = kv.first.as<std::string>();
    if (!kv.second.IsSequence() || kv.second.size() == 0)
      throw SceneError("vary." + key, "must be a non-empty list of values");
    s.varied_keys.push_back(key);
    values.emplace_back();
    for (const auto& v : kv.second) {
      const std::string value = yaml_text(v);
      if (std::find(values.back().begin(), values.back().end(), value) != values.back().end())
        throw SceneError("vary." + key, fmt::format("value {} appears twice: its runs would run twice; keep one", value));
      values.back().push_back(value);
    }
  }
  std::vector<std::size_t> index(values.size(), 0);
  while (true) {
    SweepRun r;
    for (std::size_t k = 0; k < values.size(); ++k) r.values.push_back(values[k][index[k]]);
    s.runs.push_back(std::move(r));
    std::size_t k = values.size();
    while (k > 0 && ++index[k - 1] == values[k - 1].size()) index[--k] = 0;
    if (k == 0) break;
  }
}

// One run per entry of `combinations`; the varied keys are the union of their keys, in order of first appearance;
// a run that does not name a key keeps the base scene's value (an empty cell).
void expand_list(const YAML::Node& list, std::size_t max_runs, Sweep& s) {
  if (!list.IsSequence() || list.size() == 0)
    throw SceneError("combinations", "must be a non-empty list of maps of scene keys to values");
  refuse_too_many_runs(list.size(), max_runs, "combinations");
  for (std::size_t i = 0; i < list.size(); ++i) {
    if (!list[i].IsMap()) throw SceneError(fmt::format("combinations[{}]", i), "must be a map of scene keys to values");
    for (const auto& kv : list[i]) {
      const std::string key = kv.first.as<std::string>();
      if (std::find(s.varied_keys.begin(), s.varied_keys.end(), key) == s.varied_keys.end())
        s.varied_keys.push_back(key);
    }
  }
  std::map<std::vector<std::string>, std::size_t> seen;  // each combination's values -> its index
  for (std::size_t i = 0; i < list.size(); ++i) {
    SweepRun r;
    for (const auto& key : s.varied_keys) r.values.push_back(list[i][key] ? yaml_text(list[i][key]) : "");
    if (const auto [it, added] = seen.emplace(r.values, i); !added)
      throw SceneError(fmt::format("combinations[{}]", i),
                       fmt::format("is combinations[{}] again: it would run twice; keep one", it->second));
    s.runs.push_back(std::move(r));
  }
}

// `max_runs`: a whole number >= 1 (default 1000).
std::size_t read_max_runs(const YAML::Node& n) {
  if (!n) return 1000;
  const std::string value = text(n, "max_runs");
  std::size_t used = 0;
  unsigned long long runs = 0;
  try {
    runs = std::stoull(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != value.size() || value.empty() || value[0] == '-' || runs < 1)
    throw SceneError("max_runs", "must be a whole number of runs >= 1, not " + value);
  return static_cast<std::size_t>(runs);
}

ErrorSpec read_error(const YAML::Node& e, const std::filesystem::path& file) {
  ErrorSpec spec;
  if (!e) return spec;
  if (!e.IsMap()) throw SceneError("error", "must be a map (measure, reference, threshold)");
  for (const auto& kv : e) {
    const std::string k = kv.first.as<std::string>();
    if (k != "measure" && k != "reference" && k != "threshold" && k != "T_max" && k != "from_time")
      throw SceneError("error." + k, "unknown key (known: measure, reference, threshold, T_max, from_time)");
  }
  const std::string name = e["measure"] ? text(e["measure"], "error.measure") : "none";
  const auto measure = error_measure_names.find(name);
  if (!measure)
    throw SceneError("error.measure", fmt::format("unknown measure \"{}\" (one of: {})", name,
                                                  fmt::join(error_measure_names.names(), ", ")));
  spec.measure = *measure;
  try {
    if (e["threshold"]) spec.threshold = e["threshold"].as<double>();
    if (e["T_max"]) spec.T_max = e["T_max"].as<double>();
    if (e["from_time"]) spec.from_time = e["from_time"].as<double>();
  } catch (const YAML::Exception&) {
    throw SceneError("error", "threshold, T_max and from_time must be numbers");
  }
  if (!(spec.from_time >= 0.0) || !std::isfinite(spec.from_time))
    throw SceneError("error.from_time", "must be a finite time >= 0");
  if (!(spec.threshold > 0.0)) throw SceneError("error.threshold", "must be positive");
  if (!(spec.T_max > 0.0) || !std::isfinite(spec.T_max)) throw SceneError("error.T_max", "must be positive");
  if (spec.measure == ErrorMeasure::dam_break_front) {
    if (!e["reference"]) throw SceneError("error.reference", "dam_break_front needs the reference CSV file");
    spec.reference = beside(file, text(e["reference"], "error.reference"));
    if (!std::filesystem::is_regular_file(spec.reference))
      throw SceneError("error.reference", "no file " + spec.reference.string());
  }
  return spec;
}

PlotSpec read_plots(const YAML::Node& p, const std::vector<std::string>& varied) {
  PlotSpec spec;
  if (!p) return spec;
  if (!p.IsMap()) throw SceneError("plots", "must be a map (resolution_key, map)");
  auto varied_key = [&](const YAML::Node& n, const std::string& where) {
    const std::string k = text(n, where);
    if (std::find(varied.begin(), varied.end(), k) == varied.end())
      throw SceneError(where, "\"" + k + "\" is not a varied key");
    return k;
  };
  for (const auto& kv : p) {
    const std::string k = kv.first.as<std::string>();
    if (k == "resolution_key") {
      spec.resolution_key = text(kv.second, "plots.resolution_key");
    } else if (k == "map") {
      if (!kv.second.IsMap()) throw SceneError("plots.map", "must be a map (x, y, panels)");
      for (const auto& m : kv.second) {
        const std::string axis = m.first.as<std::string>();
        if (axis == "x") spec.map_x = varied_key(m.second, "plots.map.x");
        else if (axis == "y") spec.map_y = varied_key(m.second, "plots.map.y");
        else if (axis == "panels")
          spec.map_panels = text(m.second, "plots.map.panels") == "none" ? "none"
                                                                          : varied_key(m.second, "plots.map.panels");
        else throw SceneError("plots.map." + axis, "unknown key (known: x, y, panels)");
      }
    } else {
      throw SceneError("plots." + k, "unknown key (known: resolution_key, map)");
    }
  }
  return spec;
}

}  // namespace

// finest_run compares with the run of the smallest resolution-key value: the key must be varied, every value a number.
static void check_resolution_key(const Sweep& s) {
  if (s.error.measure != ErrorMeasure::finest_run) return;
  const auto key = std::find(s.varied_keys.begin(), s.varied_keys.end(), s.plots.resolution_key);
  if (key == s.varied_keys.end())
    throw SceneError("plots.resolution_key", "finest_run needs the resolution key (\"" + s.plots.resolution_key +
                                                 "\") among the varied keys");
  for (const auto& r : s.runs) {
    const std::string& v = r.values[key - s.varied_keys.begin()];
    char* end = nullptr;
    std::strtod(v.c_str(), &end);
    if (!v.empty() && (end == v.c_str() || *end != '\0'))
      throw SceneError(s.plots.resolution_key, "\"" + v + "\" is not a number (finest_run compares the smallest)");
  }
}

static Sweep read_sweep(const std::filesystem::path& file);

Sweep load_sweep(const std::filesystem::path& file) {
  try {
    return read_sweep(file);
  } catch (const YAML::Exception& e) {
    throw SceneError("<file>", std::string("cannot read the sweep file: ") + e.what());
  }
}

static Sweep read_sweep(const std::filesystem::path& file) {
  const YAML::Node root = load_yaml(file);
  for (const auto& kv : root) {
    const std::string k = kv.first.as<std::string>();
    if (k != "scene" && k != "set" && k != "vary" && k != "combinations" && k != "error" && k != "description" &&
        k != "plots" && k != "max_runs")
      throw SceneError(k, "unknown key (known: description, scene, set, vary, combinations, error, plots, max_runs)");
  }
  const std::size_t max_runs = read_max_runs(root["max_runs"]);
  Sweep s;
  s.name = file.stem().string();
  if (!root["scene"]) throw SceneError("scene", "required: the base scene file");
  s.scene = beside(file, text(root["scene"], "scene"));
  const std::vector<std::string> fixed = assignments(root["set"], "set");
  if (root["vary"].IsDefined() == root["combinations"].IsDefined())
    throw SceneError("vary", "give exactly one of vary (a full grid) and combinations (a list of runs)");
  if (root["vary"]) expand_grid(root["vary"], max_runs, s);
  else expand_list(root["combinations"], max_runs, s);
  s.error = read_error(root["error"], file);
  s.plots = read_plots(root["plots"], s.varied_keys);
  check_resolution_key(s);
  for (std::size_t i = 0; i < s.runs.size(); ++i) {
    SweepRun& r = s.runs[i];
    r.name = fmt::format("run_{:03d}", i + 1);
    r.overrides = fixed;
    for (std::size_t k = 0; k < s.varied_keys.size(); ++k)
      if (!r.values[k].empty()) r.overrides.push_back(s.varied_keys[k] + "=" + r.values[k]);
    try {
      cases::load_scene(s.scene, r.overrides);
    } catch (const SceneError& e) {
      throw SceneError(e.key_path, fmt::format("{} (in the sweep's {}: {})", e.message, r.name,
                                               fmt::join(r.overrides, " ")));
    }
  }
  return s;
}

}  // namespace slide::tools
