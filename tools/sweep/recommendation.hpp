#pragma once
// Model no more than a scene needs (issue 13): the cheapest run of a finished sweep whose measured error is within a
// target, its cost per particle-step, and that cost scaled to another scene's size.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "tools/sweep/sweep_results.hpp"

namespace slide::tools {

// A run's time to answer: setup plus loop wall seconds.
inline double time_to_answer(const RunResult& r) { return r.setup_seconds + r.wall_seconds; }

// The run with the smallest time to answer among the completed or inaccurate runs whose error is at most
// `max_error` (ties: the first in the sweep's order); none if no run qualifies.
std::optional<RunResult> cheapest_within(const std::vector<RunResult>& results, double max_error);

// What `slide check --target-error E --with SWEEP_DIR` prints: the cheapest run of the sweep in SWEEP_DIR within E,
// its settings and cost, and that cost per particle-step (the loop's CPU seconds / (particles x steps)) applied to the checked
// scene (`fluid` and `boundary` particles, about `steps` steps, spacing `dp`) with the run's settings: where they
// change the spacing to dp', the fluid particles scale by (dp / dp')^D, the boundary ones (walls, bodies) by
// (dp / dp')^(D - 1), and the steps by dp / dp' (the acoustic time step is proportional to the spacing); D the
// scene's dimension. When no run is within
// E, the smallest error measured.
// std::runtime_error when SWEEP_DIR holds no sweep or the sweep measured no error.
std::string recommendation_report(const std::filesystem::path& sweep_dir, double target_error, double fluid,
                                  double boundary, double steps, double dp, int dimension = 2);

}  // namespace slide::tools
