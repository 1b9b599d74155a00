#include "coupling/relaxation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "coupling/advance.hpp"
#include "coupling/position_text.hpp"
#include "coupling/rigid_bodies.hpp"
#include "fluid/process_halo.hpp"

namespace slide {

namespace {

// Settling's bookkeeping after each step: the largest fluid speed, and the same damping for floating bodies as the
// fluid gets (Simulation::correct_with_pressure_gradient: u <- u exp(-rate dt)).
// Held phases' particles go back to where they started (by id) after every step, except along their phase's free
// direction: the normal of the face the slide rests on (g for a slide on no face). Why not held entirely: a slide
// held so kept the uncompressed lattice's number density, so it started at t = 0 with no pressure at all (measured on
// the Grilli slide: p = 0 to 300 Pa inside it against the 1.2-1.9 kPa of its weight and the water above), collapsed as
// a liquid until its weight had compressed it, and under water its effective stress began far below the pore
// pressure. Free along the face's normal, it compresses under its weight and the water's, as the water does, by
// about g H / c0^2 of its height (sub-millimetre), and starts at rest at its hydrostatic pressure. Why not free along
// g: on a slope of angle beta the face then carries the whole weight along g, a normal force 1 / cos(beta) of the
// weight where the weight's normal part is cos(beta) of it, so the slide started pressed on the face with
// 1 / cos^2(beta) its weight's normal stress (a block on a 45 degree face: 2400 Pa at its base against 1241 Pa), and
// its basal friction held it with that much more at first.
}  // namespace

namespace {

// Several processes (fluid/domain.hpp) settle the scene shared among them: what the checks and finish() report is the
// whole scene's, the same as on one process. comm: the simulation's (null on one process).

// The refusal of water that left the domain while settling: how many left, and the first (by time, then id).
template <int D>
std::string left_while_settling(const Simulation<D>& sim, std::int64_t count, const Communicator* comm) {
  std::vector<double> mine;  // time, id, position
  if (const auto& left = sim.left_the_domain(); !left.empty()) {
    const auto& l = *std::min_element(left.begin(), left.end(), [](const LeftParticle& a, const LeftParticle& b) {
      return a.time < b.time || (a.time == b.time && a.id < b.id);
    });
    mine = {l.time, double(l.id)};
    for (int k = 0; k < D; ++k) mine.push_back(l.position[k]);
  }
  const std::vector<double> all = comm ? gather_on_first(*comm, mine) : mine;
  constexpr std::size_t row = D + 2;
  std::size_t first = 0;
  for (std::size_t r = row; r + row <= all.size(); r += row)
    if (all[r] < all[first] || (all[r] == all[first] && all[r + 1] < all[first + 1])) first = r;
  Vec<D> x = Vec<D>::Zero();
  for (int k = 0; k < D && first + row <= all.size(); ++k) x[k] = all[first + 2 + k];
  return fmt::format("{} fluid particle{} left the domain while the water settled (the first, {}, at t = {:.6g} s at "
                     "{}): it is not at rest; hold it with a wall, or start it without settling (initial_state: "
                     "lattice)",
                     count, count == 1 ? "" : "s", all.empty() ? ParticleId(0) : ParticleId(all[first + 1]),
                     all.empty() ? 0.0 : all[first], position_text(x));
}

// Water at rest stays in the domain: what left it while settling flowed off an open edge. The refusal's message, or
// none (a collective on several processes).
template <int D>
std::optional<std::string> water_that_left(const Simulation<D>& sim, const Communicator* comm) {
  std::int64_t left = static_cast<std::int64_t>(sim.left_the_domain().size());
  if (comm) comm->sum(&left, 1);
  if (left == 0) return std::nullopt;
  return left_while_settling(sim, left, comm);
}

// How far each particle moved while settling: the largest of all, and each phase's fluid particle that moved the
// most, from where to where (among equal distances the lowest id, whatever the particles' order). Periodic in x: to
// the nearest image (a particle wrapped across the period's ends has not moved a period).
template <int D>
void find_largest_shifts(const Simulation<D>& sim, const StartPositions<D>& start, const Communicator* comm,
                         Relaxation& out) {
  const auto& P = sim.particles();
  constexpr std::size_t row = 2 + 2 * D;  // shift, id, from, to
  std::vector<double> mine;
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    Vec<D> shift = P.position[i] - start.of(P.id[i]);
    if (const auto& period = sim.options.periodic_x) shift[0] -= period->length() * std::round(shift[0] / period->length());
    out.largest_shift = std::max(out.largest_shift, shift.norm());
    if (P.kind[i] != Kind::fluid) continue;
    if (mine.size() < (P.phase[i] + 1u) * row) mine.resize((P.phase[i] + 1u) * row, 0.0);
    double* m = &mine[P.phase[i] * row];
    if (shift.norm() > m[0] || (shift.norm() == m[0] && shift.norm() > 0.0 && double(P.id[i]) < m[1])) {
      m[0] = shift.norm();
      m[1] = double(P.id[i]);
      for (int k = 0; k < D; ++k) m[2 + k] = P.position[i][k] - shift[k], m[2 + D + k] = P.position[i][k];
    }
  }
  std::int64_t phases = static_cast<std::int64_t>(mine.size() / row);
  if (comm) {
    comm->max(&out.largest_shift, 1);
    comm->max(&phases, 1);
  }
  mine.resize(static_cast<std::size_t>(phases) * row, 0.0);
  std::vector<double> shifts(static_cast<std::size_t>(phases));
  for (std::size_t ph = 0; ph < shifts.size(); ++ph) shifts[ph] = mine[ph * row];
  if (comm) comm->max(shifts.data(), shifts.size());  // every process decides the same (refuse_flowing_water)
  out.largest_shift_by_phase = shifts;
  out.largest_shift_where_by_phase.assign(shifts.size(), "");
  const std::vector<double> all = comm ? gather_on_first(*comm, mine) : mine;  // the first process's words
  for (std::size_t ph = 0; ph < shifts.size(); ++ph) {
    const double* best = nullptr;
    for (std::size_t r = ph * row; r + row <= all.size(); r += shifts.size() * row)
      if (all[r] > 0.0 && (!best || all[r] > best[0] || (all[r] == best[0] && all[r + 1] < best[1]))) best = &all[r];
    if (!best) continue;
    Vec<D> from, to;
    for (int k = 0; k < D; ++k) from[k] = best[2 + k], to[k] = best[2 + D + k];
    out.largest_shift_where_by_phase[ph] =
        fmt::format("particle {} from {} to {}", ParticleId(best[1]), position_text(from), position_text(to));
  }
}

}  // namespace

template <int D>
class Settling<D>::Observer : public StepObserver<D> {
 public:
  Observer(Relaxation& out, RigidBodies<D>* floating, StartPositions<D>& start, const SettlingPlan<D>& plan)
      : out_(out), floating_(floating), held_(256, false), free_(256, Vec<D>::Zero()), start_(start),
        refuse_if_not_at_rest_(plan.refuse_if_not_at_rest), check_interval_(plan.duration / 20) {
    for (const auto& h : plan.held) held_[h.phase] = true, free_[h.phase] = h.free_direction;
    holds_ = !plan.held.empty();  // the same on every process: the scene's plan
  }
  // The next check of the water at rest is at the first twentieth of the duration after `time` (a run resumed while
  // settling checks at the same steps as the straight run).
  void begin_at(double time) { checks_passed_ = checks_passed_by(time); }
  // Whether the last check found the water not at rest (a checkpoint keeps it: a resumed run refuses where the
  // straight run would).
  bool found_not_at_rest() const { return found_not_at_rest_; }
  void set_found_not_at_rest(bool found) { found_not_at_rest_ = found; }
  void after_step(Simulation<D>& sim, double dt) override {
    auto& P = sim.particles();
    // Particles change process only where the particles are re-sorted (the same steps on every process).
    if (holds_ && sim.neighbor_rebuilds() != rebuilds_followed_) {
      start_.follow(P, sim.domain().distributed() ? sim.domain().communicator() : nullptr);
      rebuilds_followed_ = sim.neighbor_rebuilds();
    }
    for (std::size_t i = 0; i < P.real_count(); ++i)
      if (P.kind[i] == Kind::fluid && held_[P.phase[i]]) {
        const Vec<D>& x0 = start_.of(P.id[i]);
        const Vec<D>& free = free_[P.phase[i]];
        P.position[i] = x0 + (P.position[i] - x0).dot(free) * free;
        P.velocity[i] = P.velocity[i].dot(free) * free;
      }
    // The next step reads the held particles' ghosts before it refreshes them (found in review: on several processes a
    // neighbour's copy kept the values from before the hold; periodic and mirror images did on one).
    if (holds_) sim.refresh_moved_ghosts();
    out_.largest_speed = std::max(out_.largest_speed, sim.max_fluid_speed());
    if (floating_) floating_->damp_floating(std::exp(-out_.damping_rate * dt));
    if (refuse_if_not_at_rest_ && check_time(checks_passed_ + 1) <= sim.time()) check_at_rest(sim);
  }

 private:
  Relaxation& out_;
  RigidBodies<D>* floating_;
  std::vector<bool> held_;
  bool holds_ = false;
  std::vector<Vec<D>> free_;   // by phase: the held phase's free direction (unit)
  StartPositions<D>& start_;  // Settling's
  long rebuilds_followed_ = -1;
  std::function<void(const Relaxation&, double)> refuse_if_not_at_rest_;
  double check_interval_ = 0.0;  // s
  long checks_passed_ = 0;        // the checks whose times lie at or before the clock's

  // Check k is due at k times the interval: one product, the same in a straight and a resumed run.
  double check_time(long k) const { return static_cast<double>(k) * check_interval_; }
  long checks_passed_by(double time) const {
    long k = static_cast<long>(std::floor(time / check_interval_));
    while (k > 0 && check_time(k) > time) --k;
    while (check_time(k + 1) <= time) ++k;
    return k;
  }
  bool found_not_at_rest_ = false;  // at the last check

  // The water that left the domain so far, then the shifts so far (a collective on several processes, at the same
  // step on every one: their clocks agree). Refused where the water was found not at rest at two checks running: an
  // unstable method moves the water before it blows up, and the interval's wait lets the instability, where there is
  // one, be named as such (a sweep's stability map tells the two apart: the difference gradient behind the gated dam
  // break's gate moved the water past its bound at 0.15 s and collapsed at 0.165 s).
  void check_at_rest(Simulation<D>& sim) {
    checks_passed_ = checks_passed_by(sim.time());
    const Communicator* comm = sim.domain().distributed() ? sim.domain().communicator() : nullptr;
    std::optional<std::string> why = water_that_left(sim, comm);
    if (!why) {
      start_.follow(sim.particles(), comm);
      Relaxation so_far = out_;
      find_largest_shifts(sim, start_, comm, so_far);
      try {
        refuse_if_not_at_rest_(so_far, sim.time());
      } catch (const std::runtime_error& e) {
        why = e.what();
      }
    }
    if (why && found_not_at_rest_) throw std::runtime_error(*why);
    found_not_at_rest_ = why.has_value();
  }
};



template <int D>
Settling<D>::Settling(Simulation<D>& sim, SettlingPlan<D> plan) : sim_(sim) {
  out_.duration = plan.duration;
  out_.damping_rate = plan.damping_rate;
  start_.emplace(sim.particles());  // real particles (periodic ghosts come and go)
  // Bodies that float with the water take part (coupling/rigid_bodies.hpp, set_settling); when none does, the
  // bodies are detached and their particles stand still as walls.
  bodies_ = sim.detach_bodies();
  if (bodies_)
    for (const auto& m : bodies_->motion)
      floating_ = floating_ || (m.mode == BodyMotion::Mode::free && m.free_while_settling);
  if (floating_) {
    bodies_->set_settling(true);
    sim.attach_bodies(bodies_);
  }
  saved_damping_rate_ = sim.options.velocity_damping_rate;
  sim.set_velocity_damping(plan.damping_rate);
  sim.set_rheology_suspended(true);  // sediment settles as a fluid (Simulation::set_rheology_suspended)
  observer_ = std::make_unique<Observer>(out_, floating_ ? bodies_.get() : nullptr, *start_, plan);
}

template <int D>
Settling<D>::~Settling() = default;

template <int D>
AdvanceResult Settling<D>::advance(const std::vector<StepObserver<D>*>& observers) {
  std::vector<StepObserver<D>*> all = observers;
  all.push_back(observer_.get());
  observer_->begin_at(sim_.time());
  const AdvanceResult result = slide::advance<D>(sim_, out_.duration, all);
  if (result.instability)
    throw std::runtime_error(settling_instability_message(result.instability->time, result.instability->reason));
  return result;
}

template <int D>
void Settling<D>::save_state(StateWriter& out) const {
  out.put(out_.largest_speed);
  out.put<std::uint8_t>(observer_->found_not_at_rest() ? 1 : 0);
}

template <int D>
void Settling<D>::restore_state(StateReader& in) {
  in.get(out_.largest_speed);
  observer_->set_found_not_at_rest(in.get<std::uint8_t>() != 0);
}

template <int D>
Relaxation Settling<D>::finish() {
  auto& sim = sim_;
  const Communicator* comm = sim.domain().distributed() ? sim.domain().communicator() : nullptr;
  if (const auto why = water_that_left(sim, comm)) throw std::runtime_error(*why);
  Relaxation out = out_;
  out.steps = sim.step_count();
  out.residual_speed = sim.max_fluid_speed();
  start_->follow(sim.particles(), comm);
  find_largest_shifts(sim, *start_, comm, out);
  sim.set_velocity_damping(saved_damping_rate_);
  sim.set_rheology_suspended(false);
  if (floating_) {
    bodies_->set_settling(false);
    bodies_->take_mean_forces();  // the settling's forces are not the run's
  }
  sim.attach_bodies(bodies_);
  sim.restart_at_rest();
  return out;
}

template <int D>
Relaxation relax_at_rest(Simulation<D>& sim, const SettlingPlan<D>& plan) {
  Settling<D> settling(sim, plan);
  settling.advance();
  return settling.finish();
}

template class Settling<2>;
template class Settling<3>;
template Relaxation relax_at_rest(Simulation<2>&, const SettlingPlan<2>&);
template Relaxation relax_at_rest(Simulation<3>&, const SettlingPlan<3>&);

}  // namespace slide
