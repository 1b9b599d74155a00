#pragma once
// How far a run's wave gauges are from measured records (diagnostics.gauge_records, gauge_records.csv): the rms
// difference of the elevations over the time both cover, and the deepest trough and highest crest of each.
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "cases/csv_table.hpp"
#include "cases/gauge_records_spec.hpp"

namespace slide::tools {

struct GaugeExtreme {
  double time = std::numeric_limits<double>::quiet_NaN();       // s, on the model's clock
  double elevation = std::numeric_limits<double>::quiet_NaN();  // m
};

struct GaugeRecordComparison {
  std::string gauge;
  double from = 0.0, to = 0.0;  // s, model clock: the window both the run and the record cover
  std::size_t samples = 0;      // the run's samples in the window (wet ones)
  // m: rms over the run's samples of eta - eta_measured, the record read linearly between its samples
  double rms = std::numeric_limits<double>::quiet_NaN();
  double measured_height = 0.0;  // m, the record's largest minus its smallest elevation in the window
  GaugeExtreme trough, measured_trough, crest, measured_crest;
};

// Each measured gauge against the run's column of the same name in gauges.csv. The run's elevation is its gauge minus
// the gauge's first wet value (the settled still level), the record's as stored (from the still level); model time =
// measured time + spec.time_offset; the window ends at spec.until where that is set and earlier. std::invalid_argument
// naming the gauge when gauges.csv has no such column or the two share no time.
std::vector<GaugeRecordComparison> compare_gauge_records(const CsvTable& gauges, const cases::GaugeRecordsSpec& spec);

// One number for a run (a sweep's error): the largest rms over the gauges divided by the largest measured height.
double gauge_records_error(const std::vector<GaugeRecordComparison>& comparisons);
// The same from a run folder's gauge_records.csv (std::runtime_error when the run wrote none).
double gauge_records_error(const std::filesystem::path& run_folder);

}  // namespace slide::tools
