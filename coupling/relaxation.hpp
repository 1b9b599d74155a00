#pragma once
// Settling water at rest before a run: damped dynamics carry the hydrostatically compressed lattice to the nearest
// stable arrangement, then velocities are zeroed and the clock restarts.
//
// Why: under any (p_i + p_j) pressure gradient a compressed square lattice is not a stable equilibrium. Its
// particles can lower the scheme's energy by shearing towards a denser-looking arrangement (the number density of
// a sheared lattice is a few per cent below the square one's at the same particle density), and a still tank
// started from it stirs itself to speeds of tens of per cent of sqrt(g H) (issue 3's closing note). Settling with
// damping releases that energy before t = 0. The same is done in SPH practice ("settling runs"). On the hexagonal
// lattice (fluid/lattice.hpp), a stable packing, settling only compresses the water under its weight.
// Bodies are left out while settling: their boundary particles stay where they are, like walls.
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "coupling/advance.hpp"
#include "coupling/simulation.hpp"
#include "coupling/start_positions.hpp"
#include "fluid/state_stream.hpp"

namespace slide {

struct Relaxation {
  double duration = 0.0;        // s of damped settling
  double damping_rate = 0.0;    // 1/s
  long steps = 0;
  double largest_speed = 0.0;   // m/s, largest fluid speed reached while settling
  double residual_speed = 0.0;  // m/s, at the end, before the velocities were zeroed
  double largest_shift = 0.0;   // m, largest distance a fluid particle moved while settling
  std::vector<double> largest_shift_by_phase;  // m, the same for each phase (index: Particles::phase)
  // Which particle of each phase moved the most, from where to where (for the message that refuses flowing water).
  std::vector<std::string> largest_shift_where_by_phase;
};

// The error of a settling that went unstable: "settling went unstable at t = T s: REASON", T counted from the start
// of settling. The sweep's results read it back from a run's message (tools/sweep/sweep_results.cpp).
inline constexpr const char* settling_instability_prefix = "settling went unstable at t = ";
inline std::string settling_instability_message(double time, const std::string& reason) {
  return settling_instability_prefix + std::to_string(time) + " s: " + reason;
}
struct SettlingInstability {
  double time = 0.0;  // s from the start of settling
  std::string reason;
};
// The instability a message holds (anywhere in it, as a run's refusal quotes it), or none.
inline std::optional<SettlingInstability> parse_settling_instability(const std::string& message) {
  const std::string prefix = settling_instability_prefix;
  const auto at = message.find(prefix);
  if (at == std::string::npos) return std::nullopt;
  const std::string rest = message.substr(at + prefix.size());
  const auto reason = rest.find(" s: ");
  return SettlingInstability{std::strtod(rest.c_str(), nullptr),
                             reason == std::string::npos ? std::string() : rest.substr(reason + 4)};
}

// Settles for `duration` seconds with velocities damped as exp(-damping_rate t). Throws std::runtime_error if the
// settling goes unstable (its message: settling_instability_message above), or the water is found not at rest while
// it settles (SettlingPlan::refuse_if_not_at_rest, water that left the domain; relax_at_rest leaves the end's checks
// of the shifts to its caller). On return the simulation is at time 0 with every fluid velocity zero.
// held: fluid particles of these phases (deformable slides) are held while the water settles around them, as a
// rigid slide is held: put back after every step, but free along their phase's unit `free_direction` (the normal of
// the face the slide rests on, or g), so that they compress to their hydrostatic pressure (relaxation.cpp).
// Sediment that is not held settles as a fluid (Simulation::set_rheology_suspended): its rheology starts at t = 0.
template <int D>
struct HeldPhase {
  std::uint8_t phase = 0;
  Vec<D> free_direction = -Vec<D>::Unit(D - 1);  // down
};
// refuse_if_not_at_rest: called at the first step at or after each twentieth of the duration, unless water has left
// the domain by then, with what the settling found so far (the largest shifts) and the settling's time; it throws
// std::runtime_error where the water is not at rest. Two checks running that find it (water that left, or this
// callback's refusal) stop the settling there rather than at its end (an Enet & Grilli case at dp 0.03 moved 42 dp
// by its end, about 80 minutes on two threads, and 9.5 dp by 1 s of its 4 s). Not set: no check before the end.
template <int D>
struct SettlingPlan {
  double duration = 0.0;      // s
  double damping_rate = 0.0;  // 1/s
  std::vector<HeldPhase<D>> held;
  std::function<void(const Relaxation& so_far, double time_s)> refuse_if_not_at_rest;
};
template <int D>
Relaxation relax_at_rest(Simulation<D>& sim, const SettlingPlan<D>& plan);

// The same in stages, so that a run can stop while it settles (a signal) and a checkpoint continue it bit for bit:
// construct (the simulation as built: the lattice it starts from is what held slides return to), advance (it stops
// where an observer says so), save and restore between them, finish (the checks and the clock's restart).
template <int D>
class Settling {
 public:
  Settling(Simulation<D>& sim, SettlingPlan<D> plan);
  ~Settling();
  Settling(const Settling&) = delete;
  Settling& operator=(const Settling&) = delete;
  // Settles until its duration or until an observer stops it; a stop returns the outcome `stopped`. Throws
  // std::runtime_error (settling_instability_message) if it goes unstable, or the plan's refuse_if_not_at_rest's.
  AdvanceResult advance(const std::vector<StepObserver<D>*>& observers = {});
  // After the whole duration: refuses water that left the domain (std::runtime_error), zeroes the velocities and
  // restarts the clock at 0; the simulation is then as relax_at_rest leaves it.
  Relaxation finish();
  // What a checkpoint taken while settling holds beyond the simulation's own state: the settling's bookkeeping.
  void save_state(StateWriter& out) const;
  void restore_state(StateReader& in);
  double duration() const { return out_.duration; }

 private:
  class Observer;
  Simulation<D>& sim_;
  Relaxation out_;
  std::optional<StartPositions<D>> start_;  // real particles' positions as built
  std::shared_ptr<RigidBodies<D>> bodies_;
  bool floating_ = false;
  double saved_damping_rate_ = 0.0;
  std::unique_ptr<Observer> observer_;
};

extern template class Settling<2>;
extern template class Settling<3>;
}  // namespace slide
