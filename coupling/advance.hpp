#pragma once
// The one loop that advances a simulation to a time: the run, the settled start, the equilibrium column and the
// tests all call it, and what each needs to do around the steps is an observer (outputs, progress, interrupts,
// settling's bookkeeping).
#include <initializer_list>
#include <optional>
#include <utility>
#include <vector>

#include "coupling/simulation.hpp"

namespace slide {

template <int D>
class StepObserver {
 public:
  virtual ~StepObserver() = default;
  // Before every step; returning false stops the loop there (an interrupt, a converged state).
  virtual bool before_step(const Simulation<D>&) { return true; }
  // After every step that passed the checks, with the step's dt.
  virtual void after_step(Simulation<D>&, double /*dt*/) {}
};

// An observer that calls f(sim) after every step (tests that measure as the run goes).
template <int D, class F>
class AfterEveryStep : public StepObserver<D> {
 public:
  explicit AfterEveryStep(F f) : f_(std::move(f)) {}
  void after_step(Simulation<D>& sim, double) override { f_(static_cast<const Simulation<D>&>(sim)); }

 private:
  F f_;
};

struct AdvanceResult {
  enum class Outcome { reached_end, stopped, unstable } outcome = Outcome::reached_end;
  std::optional<Instability> instability;  // when unstable: where, when and why
};

// Steps with the allowed time step until end_time (the last step shortened to land on it, and counted under the
// end_time limit), an observer stops it, or a step fails its checks.
template <int D>
AdvanceResult advance(Simulation<D>& sim, double end_time, const std::vector<StepObserver<D>*>& observers = {}) {
  const double eps = 1e-12 * std::max(1.0, std::abs(end_time));
  AdvanceResult result;
  while (sim.time() < end_time - eps) {
    for (auto* o : observers)
      if (!o->before_step(sim)) {
        result.outcome = AdvanceResult::Outcome::stopped;
        return result;
      }
    auto [dt, limit] = sim.allowed_time_step();
    if (sim.time() + dt >= end_time - eps) {
      dt = end_time - sim.time();
      limit = TimeStepLimit::end_time;
    }
    if (auto bad = sim.step(dt, limit)) {
      result.outcome = AdvanceResult::Outcome::unstable;
      result.instability = std::move(bad);
      return result;
    }
    for (auto* o : observers) o->after_step(sim, dt);
  }
  return result;
}

}  // namespace slide
