#pragma once
// Runs a shipped scene in-process, calling back after every step, for validation tests that measure more than the
// output files hold.
#include <gtest/gtest.h>

#include <functional>

#include "cases/scene.hpp"
#include "coupling/advance.hpp"
#include "tests/cli_helpers.hpp"

namespace slide::testing {

inline constexpr double g = 9.81;  // m/s^2, the test scenes' gravity

// The scene of `yaml`, written to a fresh folder named `name`.
inline std::unique_ptr<cases::Scene<2>> build_scene_text(const std::string& name, const std::string& yaml) {
  const auto dir = fresh_directory(name);
  write_file(dir / "s.yaml", yaml);
  return cases::build_scene<2>(cases::load_scene(dir / "s.yaml", {}), name);
}

inline std::unique_ptr<cases::Scene<2>> load_shipped_scene(const std::string& name,
                                                        const std::vector<std::string>& overrides = {}) {
  return cases::build_scene<2>(cases::load_scene(source_dir() / "cases" / name, overrides), name, source_dir() / "cases");
}

// Steps to the scene's end time with the one step loop (coupling/advance.hpp); returns false (with a test failure)
// if the run goes unstable.
inline bool run_scene(cases::Scene<2>& scene, const std::function<void(const Simulation<2>&)>& after_step) {
  AfterEveryStep<2, std::function<void(const Simulation<2>&)>> observer(after_step);
  const AdvanceResult result = advance<2>(*scene.simulation, scene.end_time, {&observer});
  if (result.instability) {
    ADD_FAILURE() << "unstable at t = " << result.instability->time << ": " << result.instability->reason;
    return false;
  }
  return true;
}

}  // namespace slide::testing
