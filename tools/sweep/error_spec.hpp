#pragma once
// How a sweep scores each run: the error measure, its reference and the threshold above which a completed run is
// `inaccurate`.
#include <filesystem>
#include <limits>
#include <string_view>

#include "fluid/name_table.hpp"

namespace slide::tools {

enum class ErrorMeasure {
  none,             // no error: outcomes are completed or unstable (stability maps)
  dam_break_front,  // surge front against Martin & Moyce (tools/measures/dam_break_front.hpp)
  finest_run,       // wave crests, troughs and slide travel against the sweep's finest completed run (the smallest
                    // value of the resolution key; tools/measures/wave_signature.hpp)
};

inline constexpr auto error_measure_names = make_name_table<ErrorMeasure>(
    std::pair{ErrorMeasure::none, "none"}, std::pair{ErrorMeasure::dam_break_front, "dam_break_front"},
    std::pair{ErrorMeasure::finest_run, "finest_run"});

struct ErrorSpec {
  ErrorMeasure measure = ErrorMeasure::none;
  std::filesystem::path reference;  // absolute; the measure's reference data
  double T_max = 3.0;               // dam_break_front: compared over 0 < T <= T_max
  double threshold = std::numeric_limits<double>::infinity();
};

}  // namespace slide::tools
