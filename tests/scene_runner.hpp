#pragma once
// Runs a shipped scene in-process, calling back after every step, for validation tests that measure more than the
// output files hold.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <type_traits>

#include "cases/scene.hpp"
#include "coupling/advance.hpp"
#include "tests/cli_helpers.hpp"

namespace slide::testing {

inline constexpr double g = 9.81;  // m/s^2, the test scenes' gravity

// The scene of `yaml`, written to a fresh folder named `name`.
template <int D = 2>
std::unique_ptr<cases::Scene<D>> build_scene_text(const std::string& name, const std::string& yaml,
                                                  const std::vector<std::string>& overrides = {}) {
  const auto dir = fresh_directory(name);
  write_file(dir / "s.yaml", yaml);
  return cases::build_scene<D>(cases::load_scene(dir / "s.yaml", overrides), name);
}

template <int D = 2>
std::unique_ptr<cases::Scene<D>> load_shipped_scene(const std::string& name, const std::vector<std::string>& overrides = {}) {
  return cases::build_scene<D>(cases::load_scene(source_dir() / "cases" / name, overrides), name, source_dir() / "cases");
}

// Steps to the scene's end time (or end_time) with the one step loop (coupling/advance.hpp); returns false (with a test failure)
// if the run goes unstable.
template <int D>
bool run_scene(cases::Scene<D>& scene, const std::type_identity_t<std::function<void(const Simulation<D>&)>>& after_step,
               double end_time = std::numeric_limits<double>::quiet_NaN()) {
  AfterEveryStep<D, std::function<void(const Simulation<D>&)>> observer(after_step);
  const double end = std::isnan(end_time) ? scene.end_time : end_time;
  const AdvanceResult result = advance<D>(*scene.simulation, end, {&observer});
  if (result.instability) {
    ADD_FAILURE() << "unstable at t = " << result.instability->time << ": " << result.instability->reason;
    return false;
  }
  return true;
}

}  // namespace slide::testing
