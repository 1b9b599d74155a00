#include "tools/sweep/recommendation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "tools/sweep/sweep_plan.hpp"

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

std::string recommendation_report(const std::filesystem::path& dir, double target, double fluid, double boundary,
                                  double steps, double dp, int dimension) {
  const Sweep s = read_plan(dir);
  if (s.error.measure == ErrorMeasure::none) throw std::runtime_error("the sweep measured no error");
  const std::vector<RunResult> results = collect_results(s, dir);
  const auto settings = [&](const RunResult& r) {
    std::string out;
    for (std::size_t k = 0; k < s.varied_keys.size(); ++k)
      if (!r.values[k].empty()) out += fmt::format("{}{}={}", out.empty() ? "" : " ", s.varied_keys[k], r.values[k]);
    return out;
  };
  std::string out = fmt::format("sweep {} ({}, measure {}), target error {:g}:\n", s.name, dir.string(),
                                error_measure_names.name(s.error.measure), target);
  const auto best = cheapest_within(results, target);
  if (!best) {
    const RunResult* smallest = nullptr;
    for (const auto& r : results)
      if (std::isfinite(r.error) && (!smallest || r.error < smallest->error)) smallest = &r;
    out += smallest ? fmt::format("  no run is within it; the smallest error measured is {:.4g} ({}: {})\n",
                                  smallest->error, smallest->name, settings(*smallest))
                    : "  no run has a measured error\n";
    return out;
  }
  // The loop's CPU time (setup, a settled start included, does not grow with the steps); the whole process's where a
  // run.json predates loop_cpu_seconds.
  const double loop_cpu = std::isfinite(best->loop_cpu_seconds) ? best->loop_cpu_seconds : best->cpu_seconds;
  const double per_particle_step = loop_cpu / (best->particles * best->steps);
  out += fmt::format("  cheapest within it: {} ({}), error {:.4g}, {:.4g} s to answer for {:.0f} particles and {:.0f} "
                     "steps ({:.3g} us of CPU per particle-step)\n",
                     best->name, settings(*best), best->error, time_to_answer(*best), best->particles, best->steps,
                     1e6 * per_particle_step);
  const auto spacing = std::find(s.varied_keys.begin(), s.varied_keys.end(), "particle_spacing");
  if (spacing != s.varied_keys.end() && !best->values[spacing - s.varied_keys.begin()].empty()) {
    const double ratio = dp / std::stod(best->values[spacing - s.varied_keys.begin()]);
    fluid *= std::pow(ratio, dimension);
    boundary *= std::pow(ratio, dimension - 1);
    steps *= ratio;
  }
  const double particles = fluid + boundary;
  out += fmt::format("  this scene with those settings (--set them, or put them in the scene): about {:.0f} particles x "
                     "{:.0f} steps, {:.3g} CPU seconds of stepping at that cost per particle-step (setup not included)\n",
                     particles, steps, per_particle_step * particles * steps);
  return out;
}

}  // namespace slide::tools
