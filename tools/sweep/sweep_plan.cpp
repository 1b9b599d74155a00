#include "tools/sweep/sweep_plan.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <stdexcept>

#include "tools/atomic_file.hpp"
#include "tools/shell_quote.hpp"

namespace slide::tools {

using json = nlohmann::json;

void write_plan(const Sweep& s, const std::filesystem::path& dir) {
  json j;
  j["sweep"] = s.name;
  j["scene"] = s.scene.string();
  j["varied_keys"] = s.varied_keys;
  j["runs"] = json::array();
  for (const auto& r : s.runs) j["runs"].push_back({{"name", r.name}, {"values", r.values}, {"overrides", r.overrides}});
  j["error"] = {{"measure", std::string(error_measure_names.name(s.error.measure))},
                {"reference", s.error.reference.string()},
                {"T_max", s.error.T_max},
                {"threshold", std::isfinite(s.error.threshold) ? json(s.error.threshold) : json(nullptr)}};
  j["plots"] = {{"resolution_key", s.plots.resolution_key},
                {"map_x", s.plots.map_x},
                {"map_y", s.plots.map_y},
                {"map_panels", s.plots.map_panels}};
  write_file_atomically(dir / "plan.json", j.dump(2) + "\n");
}

std::optional<std::string> sweep_folder_problem(const std::filesystem::path& dir) {
  std::error_code ec;
  if (!std::filesystem::exists(dir, ec)) return "does not exist";
  if (!std::filesystem::is_directory(dir, ec)) return "is not a folder";
  if (!std::filesystem::is_regular_file(dir / "plan.json", ec))
    return "is not a sweep folder: it has no plan.json (slide sweep SWEEP.yaml writes one)";
  return std::nullopt;
}

Sweep read_plan(const std::filesystem::path& dir) {
  std::ifstream in(dir / "plan.json");
  if (!in) throw std::runtime_error("no plan.json in " + dir.string() + " (made by slide sweep)");
  try {
    const json j = json::parse(in);
    Sweep s;
    s.name = j.at("sweep").get<std::string>();
    s.scene = j.at("scene").get<std::string>();
    s.varied_keys = j.at("varied_keys").get<std::vector<std::string>>();
    for (const auto& r : j.at("runs"))
      s.runs.push_back({r.at("name").get<std::string>(), r.at("values").get<std::vector<std::string>>(),
                        r.at("overrides").get<std::vector<std::string>>()});
    const json& e = j.at("error");
    const auto measure = error_measure_names.find(e.at("measure").get<std::string>());
    if (!measure) throw std::runtime_error("unknown error measure " + e.at("measure").get<std::string>());
    s.error.measure = *measure;
    s.error.reference = e.at("reference").get<std::string>();
    s.error.T_max = e.at("T_max").get<double>();
    if (!e.at("threshold").is_null()) s.error.threshold = e.at("threshold").get<double>();
    const json& p = j.at("plots");
    s.plots = {p.at("resolution_key").get<std::string>(), p.at("map_x").get<std::string>(),
               p.at("map_y").get<std::string>(), p.at("map_panels").get<std::string>()};
    return s;
  } catch (const json::exception& ex) {
    throw std::runtime_error((dir / "plan.json").string() + ": " + ex.what());
  }
}

std::string run_command_line(const std::filesystem::path& program, const Sweep& s, const SweepRun& r,
                             const std::filesystem::path& dir, int threads) {
  std::string line = shell_quoted(program.string()) + " run " + shell_quoted(s.scene.string()) + " --out " +
                     shell_quoted(std::filesystem::absolute(run_folder(dir, r)).string()) + " --quiet --threads " +
                     std::to_string(threads);
  for (const auto& o : r.overrides) line += " --set " + shell_quoted(o);
  return line;
}

void write_jobs(const std::filesystem::path& program, const Sweep& s, const std::filesystem::path& dir, int threads) {
  std::string text;
  for (const auto& r : s.runs) text += run_command_line(program, s, r, dir, threads) + "\n";
  write_file_atomically(dir / "jobs.txt", text);
}

}  // namespace slide::tools
