#include "tools/sweep/sweep_results.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>

#include "cases/csv_table.hpp"
#include "coupling/relaxation.hpp"
#include "tools/atomic_file.hpp"
#include "tools/measures/dam_break_front.hpp"
#include "tools/measures/floating_draft.hpp"
#include "tools/measures/poiseuille_profile.hpp"
#include "tools/measures/gauge_records.hpp"

namespace slide::tools {
namespace {

using json = nlohmann::json;

// A JSON file in the run's folder (run.json, refused.json), if there is one made with this run's overrides.
std::optional<json> read_run_record(const std::filesystem::path& file, const SweepRun& run) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  try {
    json j = json::parse(in);
    if (!j.contains("overrides") || j["overrides"] != json(run.overrides)) return std::nullopt;
    return j;
  } catch (const json::exception&) {
    return std::nullopt;  // a file being replaced, or damaged: treated as missing
  }
}

std::optional<json> read_run_json(const std::filesystem::path& run_folder, const SweepRun& run) {
  return read_run_record(run_folder / "run.json", run);
}

// A small file's text without its trailing newline; empty if it cannot be read.
std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text;
}

std::string last_line(const std::string& text) {
  const auto k = text.find_last_of('\n');
  return k == std::string::npos ? text : text.substr(k + 1);
}

// "slide: invalid scene FILE: KEY: what" -> "KEY: what"
std::string refusal_message(const Sweep& s, const std::string& log_text) {
  std::string line = last_line(log_text);
  const std::string prefix = "slide: invalid scene " + s.scene.string() + ": ";
  if (line.rfind(prefix, 0) == 0) line = line.substr(prefix.size());
  return line;
}

double number_or_nan(const json& j, const char* key) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>() : RunResult::nan;
}

// The sweep's error measure on a completed run; NaN and a note when it cannot be computed.
void measure_error(const Sweep& s, const std::filesystem::path& run_folder, const WaveSignature* finest,
                   RunResult& r) {
  try {
    switch (s.error.measure) {
      case ErrorMeasure::none: return;
      case ErrorMeasure::finest_run:
        if (!finest) throw std::runtime_error("no finest run completed");
        r.error = wave_signature_error(wave_signature(run_folder), *finest);
        return;
      case ErrorMeasure::floating_draft:
        r.error = floating_draft(run_folder, s.error.from_time).relative_error;
        return;
      case ErrorMeasure::poiseuille_profile:
        r.error = poiseuille_profile_error(run_folder).rms;
        return;
      case ErrorMeasure::gauge_records:
        r.error = gauge_records_error(run_folder);
        if (std::isnan(r.error)) r.note = "a gauge stayed dry over the compared time";
        return;
      case ErrorMeasure::dam_break_front:
        r.error = dam_break_front_error(read_csv(run_folder / "surge_front.csv"), read_csv(s.error.reference),
                                        s.error.T_max)
                      .mean_relative;
        return;
    }
  } catch (const std::exception& e) {
    r.note = e.what();
  }
}

std::string cell(std::string text) {
  std::replace(text.begin(), text.end(), ',', ';');
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

std::string number(double v) { return std::isnan(v) ? "" : fmt::format("{:.6g}", v); }

}  // namespace

void write_refusal(const Sweep& s, const SweepRun& run, const std::filesystem::path& run_folder,
                   const std::filesystem::path& log_file) {
  std::filesystem::create_directories(run_folder);
  const json j{{"overrides", run.overrides}, {"status", "refused"}, {"message", refusal_message(s, read_text(log_file))}};
  write_file_atomically(run_folder / "refused.json", j.dump(2) + "\n");
}

bool run_is_finished(const std::filesystem::path& run_folder, const SweepRun& run) {
  if (read_run_record(run_folder / "refused.json", run)) return true;
  const auto j = read_run_json(run_folder, run);
  if (!j || !j->contains("status")) return false;
  const std::string status = (*j)["status"].get<std::string>();
  return status == "completed" || status == "unstable";
}

namespace {

// A run refused because its still water went unstable while it settled is unstable (the method fails on this
// scene), not invalid: its failure time is the settling time it failed at, its check the reason, and its note says
// "while settling".
void classify_settling_instability(RunResult& r) {
  const auto instability = parse_settling_instability(r.note);
  if (!instability) return;
  r.outcome = RunOutcome::unstable;
  r.failure_time = instability->time;
  r.failure_check = instability->reason;
  r.note = "while settling (t counted from the start of settling)";
}

}  // namespace

RunResult collect_run(const Sweep& s, const SweepRun& run, const std::filesystem::path& dir,
                      const WaveSignature* finest) {
  RunResult r;
  r.name = run.name;
  r.values = run.values;
  const std::filesystem::path run_folder = dir / "runs" / run.name;
  const auto j = read_run_json(run_folder, run);
  const std::string exit_code = read_text(dir / "logs" / (run.name + ".exit"));
  if (!j) {
    const auto refusal = read_run_record(run_folder / "refused.json", run);
    if (refusal || exit_code == "2") {
      r.outcome = RunOutcome::invalid;
      r.note = refusal ? refusal->value("message", "")
                       : refusal_message(s, read_text(dir / "logs" / (run.name + ".log")));  // no refused.json: older
      classify_settling_instability(r);
    } else if (!exit_code.empty() && exit_code != "0" && exit_code != "3" && exit_code != "130") {
      r.outcome = RunOutcome::failed;
      r.note = "exit " + exit_code + ": " + last_line(read_text(dir / "logs" / (run.name + ".log")));
    }
    return r;
  }
  r.particles = j->contains("particles") ? number_or_nan((*j)["particles"], "total") : RunResult::nan;
  r.steps = number_or_nan(*j, "steps");
  r.setup_seconds = number_or_nan(*j, "setup_seconds");
  r.wall_seconds = number_or_nan(*j, "wall_seconds");
  r.cpu_seconds = number_or_nan(*j, "cpu_seconds");
  r.loop_cpu_seconds = number_or_nan(*j, "loop_cpu_seconds");
  r.particle_steps_per_second = number_or_nan(*j, "particle_steps_per_second");
  if (j->contains("largest_number_density_ratio"))
    r.largest_number_density_ratio = number_or_nan((*j)["largest_number_density_ratio"], "value");
  const std::string status = j->value("status", "");
  if (status == "unstable") {
    r.outcome = RunOutcome::unstable;
    if (j->contains("instability")) {
      r.failure_time = number_or_nan((*j)["instability"], "time");
      r.failure_check = (*j)["instability"].value("reason", "");
    }
  } else if (status == "completed") {
    measure_error(s, run_folder, finest, r);
    r.outcome = r.error > s.error.threshold ? RunOutcome::inaccurate : RunOutcome::completed;
  } else if (!exit_code.empty() && exit_code != "0" && exit_code != "3" && exit_code != "130") {
    r.outcome = RunOutcome::failed;  // it died while running: run.json still says so
    r.note = "exit " + exit_code;
  } else {
    r.outcome = RunOutcome::interrupted;
  }
  return r;
}

namespace {
// The completed run with the smallest value of the resolution key (the first such in the sweep's order), or null.
const SweepRun* finest_completed_run(const Sweep& s, const std::filesystem::path& dir) {
  const auto key = std::find(s.varied_keys.begin(), s.varied_keys.end(), s.plots.resolution_key);
  if (key == s.varied_keys.end()) return nullptr;
  const std::size_t k = key - s.varied_keys.begin();
  const SweepRun* finest = nullptr;
  double smallest = std::numeric_limits<double>::infinity();
  for (const auto& run : s.runs) {
    const auto j = read_run_json(dir / "runs" / run.name, run);
    if (!j || j->value("status", "") != "completed" || run.values[k].empty()) continue;
    const double v = std::strtod(run.values[k].c_str(), nullptr);  // checked numeric by load_sweep
    if (v < smallest) smallest = v, finest = &run;
  }
  return finest;
}
}  // namespace

std::vector<RunResult> collect_results(const Sweep& s, const std::filesystem::path& dir) {
  std::optional<WaveSignature> finest;
  const SweepRun* finest_run = nullptr;
  std::string why_none;
  if (s.error.measure == ErrorMeasure::finest_run) {
    finest_run = finest_completed_run(s, dir);
    try {
      if (finest_run) finest = wave_signature(dir / "runs" / finest_run->name);
    } catch (const std::exception& e) {
      why_none = e.what();
    }
  }
  std::vector<RunResult> out;
  for (const auto& run : s.runs) {
    out.push_back(collect_run(s, run, dir, finest ? &*finest : nullptr));
    if (&run == finest_run) out.back().note = "the reference (finest) run";
    if (!why_none.empty() && out.back().note.empty()) out.back().note = "finest run unreadable: " + why_none;
  }
  return out;
}

void write_results_csv(const Sweep& s, const std::vector<RunResult>& results, const std::filesystem::path& file) {
  std::vector<std::string> header{"run"};
  for (const auto& k : s.varied_keys) header.push_back(cell(k));
  for (const char* c : {"outcome", "particles", "steps", "setup_seconds", "wall_seconds", "cpu_seconds",
                        "loop_cpu_seconds", "particle_steps_per_second", "error", "largest_number_density_ratio",
                        "failure_time", "failure_check", "note"})
    header.emplace_back(c);
  std::string text = fmt::format("{}\n", fmt::join(header, ","));
  for (const auto& r : results) {
    std::vector<std::string> row{r.name};
    for (const auto& v : r.values) row.push_back(cell(v));
    row.emplace_back(run_outcome_names.name(r.outcome));
    for (const double v : {r.particles, r.steps, r.setup_seconds, r.wall_seconds, r.cpu_seconds, r.loop_cpu_seconds,
                           r.particle_steps_per_second, r.error, r.largest_number_density_ratio, r.failure_time})
      row.push_back(number(v));
    row.push_back(cell(r.failure_check));
    row.push_back(cell(r.note));
    text += fmt::format("{}\n", fmt::join(row, ","));
  }
  write_file_atomically(file, text);
}

}  // namespace slide::tools
