#include "tools/report.hpp"

#include "tools/markup_escape.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

#include "cases/csv_table.hpp"
#include "tools/atomic_file.hpp"
#include "tools/base64.hpp"
#include "tools/plot_scripts.hpp"
#include "tools/sweep/recommendation.hpp"
#include "tools/sweep/sweep_plan.hpp"
#include "tools/sweep/sweep_results.hpp"

namespace slide::tools {
namespace {

using json = nlohmann::json;
namespace fs = std::filesystem;

std::string file_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// An embedded PNG with its caption; nothing if the file is not there.
std::string figure(const fs::path& png, const std::string& caption) {
  if (!fs::exists(png)) return "";
  return fmt::format("<figure><img src=\"data:image/png;base64,{}\" alt=\"{}\"><figcaption>{}</figcaption></figure>\n",
                     base64(file_bytes(png)), markup_escaped(caption), markup_escaped(caption));
}

std::string row(const std::vector<std::string>& cells, const char* tag = "td") {
  std::string out = "<tr>";
  for (const auto& c : cells) out += fmt::format("<{0}>{1}</{0}>", tag, markup_escaped(c));
  return out + "</tr>\n";
}

std::string number(double v) { return std::isfinite(v) ? fmt::format("{:.4g}", v) : ""; }

// gauge_records.csv as a table in mm and s (nothing without the file).
std::string gauge_records_table(const fs::path& file) {
  if (!fs::exists(file)) return "";
  const CsvTable t = read_csv(file);
  std::string out = "<h2>Wave gauges against the measured records (gauge_records.csv)</h2>\n<table>\n";
  out += row({"gauge", "compared, s", "rms, mm", "rms / measured height", "deepest trough: run, mm at s",
              "measured, mm at s", "highest crest: run, mm at s", "measured, mm at s"},
             "th");
  const auto mm = [](const std::string& v) { return number(1000.0 * std::stod(v)); };
  for (const auto& r : t.rows) {
    const auto at = [&](const char* name) { return r.at(t.column(name)); };
    const auto s = [&](const char* name) { return number(std::stod(at(name))); };
    out += row({at("gauge"), s("from") + " - " + s("to"), mm(at("rms")), s("rms_over_height"),
                mm(at("trough")) + " at " + s("trough_time"), mm(at("measured_trough")) + " at " + s("measured_trough_time"),
                mm(at("crest")) + " at " + s("crest_time"), mm(at("measured_crest")) + " at " + s("measured_crest_time")});
  }
  return out + "</table>\n";
}

std::string page(const std::string& title, const std::string& body) {
  return fmt::format(R"(<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>{0}</title>
<style>
body {{ font-family: sans-serif; max-width: 1200px; margin: 1em auto; padding: 0 1em; color: #222; }}
table {{ border-collapse: collapse; margin: 0.5em 0; font-size: 0.9em; }}
td, th {{ border: 1px solid #ccc; padding: 0.2em 0.5em; text-align: left; }}
figure {{ margin: 1em 0; }} img {{ max-width: 100%; }} figcaption {{ color: #555; font-size: 0.9em; }}
pre {{ background: #f6f6f6; padding: 0.5em; overflow-x: auto; font-size: 0.8em; }}
</style></head>
<body>
<h1>{0}</h1>
{1}<p style="color:#777">Written by slide {2} (slide report).</p>
</body></html>
)",
                     markup_escaped(title), body, SLIDE_VERSION);
}

json read_json(const fs::path& file) {
  std::ifstream in(file);
  return json::parse(in);
}

// "12800 particles: 11667 fluid, 465 wall, 668 dummy" from run.json's counts (a sentence, not a JSON object).
std::string particle_sentence(const json& run) {
  if (!run.contains("particles") || !run["particles"].is_object()) return "";
  const json& p = run["particles"];
  const auto count = [&](const char* key) { return p.contains(key) && p[key].is_number() ? p[key].dump() : "?"; };
  return fmt::format("{} particles: {} fluid, {} wall, {} dummy", count("total"), count("fluid"), count("wall"),
                     count("dummy"));
}

std::string run_body(const fs::path& dir) {
  const json run = read_json(dir / "run.json");
  std::string body = fmt::format("<p><b>{}</b>: {}</p>\n", markup_escaped(run.value("status", "?")),
                                 markup_escaped(run.value("message", "")));
  body += "<h2>Cost</h2>\n<table>\n";
  const auto value = [&](const char* key) { return run.contains(key) && run[key].is_number() ? run[key].get<double>() : NAN; };
  body += row({"particles", particle_sentence(run)});
  body += row({"steps", number(value("steps"))});
  body += row({"simulated time, s", number(value("simulated_time"))});
  body += row({"setup, s", number(value("setup_seconds"))});
  body += row({"loop wall time, s", number(value("wall_seconds"))});
  body += row({"CPU time, s", number(value("cpu_seconds"))});
  body += row({"particle-steps per second", number(value("particle_steps_per_second"))});
  body += row({"threads", number(value("threads"))});
  if (run.contains("largest_number_density_ratio"))
    body += row({"largest n/n0 (compression), at t, s",
                 number(run["largest_number_density_ratio"].value("value", NAN)) + " at " +
                     number(run["largest_number_density_ratio"].value("time", NAN))});
  body += "</table>\n<h2>Time-step limits (steps each limit ruled)</h2>\n<table>\n";
  if (run.contains("time_step_limits"))
    for (auto it = run["time_step_limits"].begin(); it != run["time_step_limits"].end(); ++it)
      body += row({it.key(), it.value().dump()});
  body += "</table>\n";
  body += gauge_records_table(dir / "gauge_records.csv");
  body += "<h2>Figures</h2>\n";
  run_plot_script("plot_run.py", dir);
  for (const auto& [png, caption] : std::vector<std::pair<const char*, const char*>>{
           {"particles.png", "the particles at four times, coloured by phase and by speed"},
           {"plan_view.png", "3-D: the free surface seen from above (the highest water particle in each square)"},
           {"gauges.png", "free-surface elevation at the wave gauges (against the measured records, where the scene "
                          "names them: diagnostics.gauge_records)"},
           {"surge_front.png", "dam-break surge front and water height at the wall against Martin & Moyce (1952)"},
           {"bodies.png", "bodies: position, velocity, fluid force and angle"},
           {"profiles.png", "free-surface profiles"},
           {"slide.png", "deformable slides: front, thickness and outline"},
           {"slide_shapes.png", "the slide's upper surface against the measured shapes"}})
    body += figure(dir / png, caption);
  body += "<h2>Method</h2>\n<table>\n";
  if (run.contains("scene")) {
    const json& scene = run["scene"];
    body += row({"particle spacing, m", scene.value("particle_spacing", json()).dump()});
    body += row({"lattice", scene.value("lattice", json()).dump()});
    if (scene.contains("method"))
      for (auto it = scene["method"].begin(); it != scene["method"].end(); ++it)
        body += row({"method." + it.key(), it.value().dump()});
  }
  if (run.contains("derived"))
    for (auto it = run["derived"].begin(); it != run["derived"].end(); ++it)
      body += row({"derived: " + it.key(), it.value().dump()});
  body += "</table>\n<h2>Scene (every key resolved)</h2>\n";
  body += "<pre>" + markup_escaped(run.contains("scene") ? run["scene"].dump(2) : "") + "</pre>\n";
  return body;
}

std::string sweep_body(const fs::path& dir) {
  const Sweep s = read_plan(dir);
  const std::vector<RunResult> results = collect_results(s, dir);
  write_results_csv(s, results, dir / "results.csv");
  run_plot_script("plot_sweep.py", dir);
  std::map<RunOutcome, int> count;
  for (const auto& r : results) ++count[r.outcome];
  std::string counts;
  for (const auto& [o, n] : count) counts += fmt::format("{}{} {}", counts.empty() ? "" : ", ", n, run_outcome_names.name(o));
  std::string body = fmt::format("<p>Base scene <code>{}</code>; varied: {}; {} runs ({}). Error measure: {}{}.</p>\n",
                                 markup_escaped(s.scene.string()), markup_escaped(fmt::format("{}", fmt::join(s.varied_keys, ", "))),
                                 results.size(), counts, markup_escaped(std::string(error_measure_names.name(s.error.measure))),
                                 std::isfinite(s.error.threshold) ? fmt::format(", threshold {:g}", s.error.threshold) : "");
  body += "<h2>Recommendation</h2>\n";
  if (s.error.measure == ErrorMeasure::none || !std::isfinite(s.error.threshold)) {
    body += "<p>The sweep sets no error measure and threshold, so it recommends nothing.</p>\n";
  } else if (const auto best = cheapest_within(results, s.error.threshold)) {
    std::string keys;
    for (std::size_t k = 0; k < s.varied_keys.size(); ++k)
      keys += fmt::format("{}{} = {}", keys.empty() ? "" : ", ", s.varied_keys[k], best->values[k]);
    body += fmt::format("<p>The cheapest run within the threshold: <b>{}</b> ({}), error {:.4g}, {:.4g} s to answer "
                        "({:.4g} particles, {:.3g} CPU seconds).</p>\n",
                        markup_escaped(best->name), markup_escaped(keys), best->error, time_to_answer(*best), best->particles,
                        best->cpu_seconds);
  } else {
    body += "<p>No run met the threshold.</p>\n";
  }
  body += figure(dir / "accuracy_cost.png", "error against time to answer; the Pareto front marked");
  body += figure(dir / "stability_map.png", "outcome of every run");
  body += "<h2>Runs</h2>\n<table>\n";
  std::vector<std::string> header{"run"};
  header.insert(header.end(), s.varied_keys.begin(), s.varied_keys.end());
  for (const char* c :
       {"outcome", "particles", "steps", "setup s", "loop s", "CPU s", "error", "largest n/n0", "failed at, s", "note"})
    header.emplace_back(c);
  body += row(header, "th");
  for (const auto& r : results) {
    std::vector<std::string> cells{r.name};
    cells.insert(cells.end(), r.values.begin(), r.values.end());
    for (const auto& c : {std::string(run_outcome_names.name(r.outcome)), number(r.particles), number(r.steps),
                          number(r.setup_seconds), number(r.wall_seconds), number(r.cpu_seconds), number(r.error),
                          number(r.largest_number_density_ratio), number(r.failure_time), r.failure_check.empty() ? r.note : r.failure_check})
      cells.push_back(c);
    body += row(cells);
  }
  body += "</table>\n";
  return body;
}

}  // namespace

int report_command(const fs::path& dir) {
  try {
    std::string html;
    if (fs::exists(dir / "plan.json")) {
      html = page("slide sweep report: " + read_plan(dir).name, sweep_body(dir));
    } else if (fs::exists(dir / "run.json")) {
      html = page("slide run report: " + read_json(dir / "run.json").value("case", dir.filename().string()),
                  run_body(dir));
    } else {
      std::cerr << "slide report: " << dir.string() << " is neither a run folder (run.json) nor a sweep folder "
                << "(plan.json)\n";
      return 2;
    }
    write_file_atomically(dir / "report.html", html);
    std::cerr << "slide report: " << (dir / "report.html").string() << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "slide report: error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace slide::tools
