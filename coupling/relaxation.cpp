#include "coupling/relaxation.hpp"

#include <cmath>
#include <stdexcept>

#include "coupling/rigid_bodies.hpp"

namespace slide {

Relaxation relax_at_rest(Simulation<2>& sim, double duration, double damping_rate) {
  Relaxation out;
  out.duration = duration;
  out.damping_rate = damping_rate;
  auto& P = sim.particles;
  std::vector<Vec<2>> start(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) start[P.id[i]] = P.position[i];
  // Bodies that float with the water take part (coupling/rigid_bodies.hpp, set_settling); when none does, the
  // bodies are detached and their particles stand still as walls.
  const std::shared_ptr<RigidBodies> bodies = std::move(sim.bodies);
  bool floating = false;
  if (bodies)
    for (const auto& m : bodies->motion) floating = floating || (m.mode == BodyMotion::Mode::free && m.free_while_settling);
  if (floating) {
    bodies->set_settling(true);
    sim.bodies = bodies;
  }
  const double saved_rate = sim.options.velocity_damping_rate;
  sim.options.velocity_damping_rate = damping_rate;
  while (sim.time < duration - 1e-12) {
    auto [dt, limit] = sim.allowed_time_step();
    if (sim.time + dt > duration) dt = duration - sim.time;
    if (auto bad = sim.step(dt, limit))
      throw std::runtime_error("settling went unstable at t = " + std::to_string(bad->time) + " s: " + bad->reason);
    out.largest_speed = std::max(out.largest_speed, sim.max_fluid_speed());
    // The same damping as the fluid's (Simulation::step: u <- u exp(-rate dt)).
    if (floating) bodies->damp_floating(std::exp(-damping_rate * dt));
  }
  out.steps = sim.step_count;
  out.residual_speed = sim.max_fluid_speed();
  for (std::size_t i = 0; i < P.size(); ++i) {
    out.largest_shift = std::max(out.largest_shift, (P.position[i] - start[P.id[i]]).norm());
    if (P.kind[i] != Kind::fluid) continue;
    P.velocity[i] = Vec<2>::Zero();
    P.acceleration[i] = Vec<2>::Zero();
  }
  sim.options.velocity_damping_rate = saved_rate;
  if (floating) {
    bodies->set_settling(false);
    bodies->take_mean_forces();  // the settling's forces are not the run's
  }
  sim.bodies = bodies;
  sim.time = 0.0;
  sim.step_count = 0;
  sim.limit_counts = {};
  sim.initialise();
  return out;
}

}  // namespace slide
