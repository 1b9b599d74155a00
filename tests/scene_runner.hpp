#pragma once
// Runs a shipped scene in-process, calling back after every step, for validation tests that measure more than the
// output files hold.
#include <gtest/gtest.h>

#include <functional>

#include "cases/scene.hpp"
#include "tests/cli_helpers.hpp"

namespace slide::testing {

inline std::unique_ptr<cases::Scene> load_shipped_scene(const std::string& name,
                                                        const std::vector<std::string>& overrides = {}) {
  return cases::build_scene(cases::load_scene(source_dir() / "cases" / name, overrides), name, source_dir() / "cases");
}

// Steps to the scene's end time; returns false (with a test failure) if the run goes unstable.
inline bool run_scene(cases::Scene& scene, const std::function<void(const Simulation<2>&)>& after_step) {
  auto& sim = *scene.simulation;
  while (sim.time < scene.end_time - 1e-12) {
    auto [dt, limit] = sim.allowed_time_step();
    if (sim.time + dt > scene.end_time) dt = scene.end_time - sim.time;
    if (auto bad = sim.step(dt, limit)) {
      ADD_FAILURE() << "unstable at t = " << bad->time << ": " << bad->reason;
      return false;
    }
    after_step(sim);
  }
  return true;
}

}  // namespace slide::testing
