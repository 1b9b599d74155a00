#pragma once
// The dam break's error measure (issue 13; tests/test_dam_break.cpp and `slide sweep` both call it).
#include "cases/csv_table.hpp"

namespace slide::tools {

struct FrontError {
  double mean_relative = 0.0;  // mean of |Z_run - Z_ref| / Z_ref over the points compared
  int points = 0;              // reference points compared
};

// Surge front against Martin & Moyce (1952): over the reference points with 0 < T <= T_max (all transcriptions in
// the file), the mean of |Z_run(T) - Z_ref| / Z_ref, Z_run linearly interpolated in the run's surge_front.csv (columns
// T and Z) and the reference's columns T_dimless_t_sqrt_2g_over_a and Z_dimless_xfront_over_a.
// std::runtime_error when the run stops before T_max (its error over the span is not known) or has no rows.
FrontError dam_break_front_error(const CsvTable& surge_front, const CsvTable& reference, double T_max = 3.0);

}  // namespace slide::tools
