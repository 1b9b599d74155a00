#pragma once
// Model no more than a scene needs (issue 13): the cheapest run of a finished sweep whose measured error is within a
// target, its cost per particle-step, and that cost scaled to another scene's size.
#include <optional>
#include <vector>

#include "tools/sweep/sweep_results.hpp"

namespace slide::tools {

// A run's time to answer: setup plus loop wall seconds.
inline double time_to_answer(const RunResult& r) { return r.setup_seconds + r.wall_seconds; }

// The run with the smallest time to answer among the completed or inaccurate runs whose error is at most
// `max_error` (ties: the first in the sweep's order); none if no run qualifies.
std::optional<RunResult> cheapest_within(const std::vector<RunResult>& results, double max_error);

}  // namespace slide::tools
