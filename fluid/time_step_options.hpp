#pragma once
// The adaptive time step's settings (scene keys `time_step.*`) and the limits that can set it:
//   dt = min(cfl dp / (c0 + |u|max), viscous_number dp^2 / nu_max, force_number sqrt(dp / |a|max), dt_max).
#include "fluid/name_table.hpp"

namespace slide {

struct TimeStepOptions {
  double cfl = 0.2;
  double viscous_number = 0.1;
  double force_number = 0.25;
  double dt_max = 1e-3;
};

enum class TimeStepLimit { cfl = 0, viscous = 1, force = 2, dt_max = 3, end_time = 4 };
inline constexpr int time_step_limit_count = 5;

inline constexpr auto time_step_limit_names = make_name_table<TimeStepLimit>(
    std::pair{TimeStepLimit::cfl, "cfl"}, std::pair{TimeStepLimit::viscous, "viscous"},
    std::pair{TimeStepLimit::force, "force"}, std::pair{TimeStepLimit::dt_max, "dt_max"},
    std::pair{TimeStepLimit::end_time, "end_time"});

inline std::string_view to_string(TimeStepLimit l) { return time_step_limit_names.name(l); }

}  // namespace slide
