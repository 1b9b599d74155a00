#include "tools/sweep/recommendation.hpp"

#include <cmath>

namespace slide::tools {

std::optional<RunResult> cheapest_within(const std::vector<RunResult>& results, double max_error) {
  std::optional<RunResult> best;
  for (const auto& r : results) {
    if (r.outcome != RunOutcome::completed && r.outcome != RunOutcome::inaccurate) continue;
    if (!(r.error <= max_error) || !std::isfinite(time_to_answer(r))) continue;
    if (!best || time_to_answer(r) < time_to_answer(*best)) best = r;
  }
  return best;
}

}  // namespace slide::tools
