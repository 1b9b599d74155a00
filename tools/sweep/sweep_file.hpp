#pragma once
// A sweep file (`slide sweep SWEEP.yaml`): one base scene, the keys to vary, and how each run is scored.
//
//   scene: ../dam_break_2d.yaml        # the base scene, relative to the sweep file
//   set: {end_time: 0.165}             # overrides every run gets (optional)
//   vary:                              # a full grid: every combination of these values, in this key order
//     particle_spacing: [0.0057150, 0.0028575]
//     method.gradient: [symmetric, variational]
//   combinations:                      # or (instead of vary) a list of runs, each a map of keys to values
//     - {particle_spacing: 0.0057150, method.gradient: symmetric}
//   error:                             # how a completed run is scored (optional; default: measure none)
//     measure: dam_break_front         # one of error_measure_names (tools/sweep/error_spec.hpp)
//     reference: ../reference/martin_moyce_1952_surge_front.csv   # relative to the sweep file
//     threshold: 0.10                  # a completed run whose error exceeds it is `inaccurate`
//     T_max: 3                         # dam_break_front: compared over 0 < T <= T_max (default 3)
//     from_time: 0.5                   # floating_draft: the draft's time mean starts here, s (default 0)
//   max_runs: 1000                     # a sweep of more runs is refused before any is checked (default 1000)
//   plots:                             # what tools/plot_sweep.py draws (optional)
//     resolution_key: particle_spacing # the chart's series are the other varied keys
//     map: {x: particle_spacing, y: method.gradient, panels: method.wall_pressure}   # default: the first three;
//                                      # panels: none draws one panel (a third key that follows the other two)
//
// Keys are scene key paths as `--set` takes them; values are YAML (a number, a name, a list). Every run's scene is
// checked against the schema before anything runs: a bad sweep file, key or value is a SceneError (exit 2) naming the
// key. So is a sweep of more than max_runs runs (checked from the lists' lengths first: a grid of 10^7 runs would
// spend hours being checked) and a combination given twice. A combination that passes the schema but that the scene builder refuses (the mirror wall model on the
// hexagonal lattice) runs, exits 2 by itself, and is `invalid` in the results.
#include <filesystem>
#include <string>
#include <vector>

#include "tools/sweep/error_spec.hpp"

namespace slide::tools {

struct SweepRun {
  std::string name;                    // run_001, ...: its folder under runs/
  std::vector<std::string> values;     // one per varied key, as YAML text
  std::vector<std::string> overrides;  // the sweep's fixed ones, then key=value for each varied key
};

// What tools/plot_sweep.py draws: the resolution key (the accuracy-cost chart's series are the other varied keys) and
// the stability map's axes and panels (empty: the first, second and third varied keys).
struct PlotSpec {
  std::string resolution_key = "particle_spacing";
  std::string map_x, map_y, map_panels;
};

struct Sweep {
  std::string name;                     // the sweep file's stem
  std::filesystem::path scene;          // the base scene, absolute
  std::vector<std::string> varied_keys;  // in the file's order
  std::vector<SweepRun> runs;
  ErrorSpec error;
  PlotSpec plots;
};

// Reads and checks a sweep file (every run's scene loads and passes the schema).
Sweep load_sweep(const std::filesystem::path& file);

}  // namespace slide::tools
