#pragma once
// diagnostics.gauge_records (gauge_records.csv, tools/measures/gauge_records.hpp): measured free-surface elevations at
// the scene's gauges, each compared with the model's over the time both cover.
#include <string>
#include <vector>

namespace slide::cases {

struct MeasuredGauge {
  std::string name;               // a gauge of the scene
  std::vector<double> elevation;  // m, from the still water level, at GaugeRecordsSpec::time_measured
};

struct GaugeRecordsSpec {
  std::string file;                   // as the scene names it
  double time_offset = 0.0;           // s, model time = measured time + time_offset
  double until = 0.0;                 // s, model time the comparison ends; 0: the run's end
  std::vector<double> time_measured;  // s, increasing
  std::vector<MeasuredGauge> gauges;  // in the file's column order
};

}  // namespace slide::cases
