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
  floating_draft,   // an upright box's draft against Archimedes, time mean from from_time on
                    // (tools/measures/floating_draft.hpp)
  poiseuille_profile,  // a channel's last velocity profile against plane Poiseuille flow's closed form
                       // (tools/measures/poiseuille_profile.hpp; the scene needs diagnostics.velocity_profile)
  gauge_records,  // the wave gauges against measured records: the largest rms over the largest measured height
                  // (gauge_records.csv, tools/measures/gauge_records.hpp; the scene needs diagnostics.gauge_records)
};

inline constexpr auto error_measure_names = make_name_table<ErrorMeasure>(
    std::pair{ErrorMeasure::none, "none"}, std::pair{ErrorMeasure::dam_break_front, "dam_break_front"},
    std::pair{ErrorMeasure::finest_run, "finest_run"}, std::pair{ErrorMeasure::floating_draft, "floating_draft"},
    std::pair{ErrorMeasure::poiseuille_profile, "poiseuille_profile"},
    std::pair{ErrorMeasure::gauge_records, "gauge_records"});

struct ErrorSpec {
  ErrorMeasure measure = ErrorMeasure::none;
  std::filesystem::path reference;  // absolute; the measure's reference data
  double T_max = 3.0;               // dam_break_front: compared over 0 < T <= T_max
  double from_time = 0.0;           // s, floating_draft: the time mean starts here
  double threshold = std::numeric_limits<double>::infinity();
};

}  // namespace slide::tools
