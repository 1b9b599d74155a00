#pragma once
// What a landslide run is judged by where no measurement exists (issue 13: against a sweep's finest run): the crest
// and trough at each wave gauge and how far the slide travelled.
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "cases/csv_table.hpp"

namespace slide::tools {

struct WaveSignature {
  std::vector<std::string> gauges;
  std::vector<double> crest, trough;  // m: max and min over the run of eta(t) - eta(0) at each gauge
  double slide_travel = std::numeric_limits<double>::quiet_NaN();  // m; NaN: the run has no slide or body
};

// From a run's gauges.csv and, for the slide, slide_front.csv (a deformable slide: the change of front_along of the
// first slide named) or else bodies.csv (a body: the distance between the first body's first and last centre).
// Gauges whose first value is NaN (dry at the start) count from their first wet value.
WaveSignature wave_signature(const CsvTable& gauges, const CsvTable* slide_front, const CsvTable* bodies);
// The same, reading the files of a run folder (the slide's file where there is one).
WaveSignature wave_signature(const std::filesystem::path& run_folder);

// Error of a run against a reference run (the sweep's finest), relative to the reference's largest wave height H* =
// max over gauges of (crest* - trough*):
//   e = max( max_g |crest_g - crest*_g| / H*, max_g |trough_g - trough*_g| / H*, |travel - travel*| / travel* ),
// the last term only where both have a slide. std::invalid_argument when the gauges differ or H* is 0.
double wave_signature_error(const WaveSignature& run, const WaveSignature& reference);

}  // namespace slide::tools
