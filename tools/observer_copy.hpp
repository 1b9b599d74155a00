#pragma once
// A run on several processes (mpirun) writes what one process's run writes, byte for byte. The first process keeps a
// second simulation of the scene that never steps, the observers' copy: whenever an output is due, every process sends
// it those of its owned particles that the outputs read (cases/observed_particles.hpp: near a gauge, of a slide, all
// the fluid for the 2-D flume's diagnostics), one process after another, and the copy takes them in as one process
// would hold them at that step (Simulation::adopt_whole_state); the outputs (tools/run_outputs.hpp) then read the copy
// as they read a one-process run, gauges and fronts alike. The copy lists no neighbours (Simulation::make_observers_copy) unless an
// output reads them. Snapshots and checkpoints are the exceptions: every process gives its own particles, and the
// processes holding a chunk's rows encode it (tools/snapshot_rows.hpp); a checkpoint's particles come to the first
// process one id range at a time (tools/shared_checkpoint.hpp).
//
// The copy's memory and the gathering's time on the first process grow with the particles the outputs read, not with
// the whole scene (run.json's partition.observer_copy gives the gathers, their seconds and the particles the copy held
// at the last; partition.memory every process's peak; docs/using.md the measured figures).
#include <chrono>
#include <cstdint>
#include <functional>
#include <vector>

#include "coupling/advance.hpp"
#include "fluid/communicator.hpp"
#include "tools/run_outputs.hpp"

namespace slide::tools {

template <int D>
class ObserverCopy : public StepObserver<D> {
 public:
  // What reads the copy after a step (the outputs, the checkpoints), and whether it will after the step at time t.
  struct Reader {
    std::function<bool(double)> due;
    StepObserver<D>* observer;
  };
  // copy and readers: the first process's; null and none on the others. Snapshots and checkpoints, which read the
  // running simulation rather than the copy (every process gives its own particles: tools/snapshot_rows.hpp,
  // tools/shared_checkpoint.hpp): on the first, whether one is due after the step at time t, and how it writes one
  // (a snapshot: where no reader reads the copy); on the others, how they join the collective that writes it.
  struct Collective {
    std::function<bool(double)> due;
    std::function<void(const Simulation<D>&)> write, join;
  };
  // Which of a process's owned particles the copy takes (every process's: cases/observed_particles.hpp).
  using Observed = std::function<bool(const Particles<D>&, std::size_t)>;
  ObserverCopy(const Communicator& world, Simulation<D>* copy, Observed observed, std::vector<Reader> readers,
               Collective snapshots = {}, Collective checkpoints = {})
      : world_(&world), copy_(copy), observed_(std::move(observed)), readers_(std::move(readers)),
        snapshots_(std::move(snapshots)), checkpoints_(std::move(checkpoints)) {}

  // Every process: whether any reader reads the copy after this step, and whether a snapshot or a checkpoint is due
  // (the first process knows); the copy is brought up to date only for the readers. The checkpoint comes last, as on
  // one process: it records the outputs as they are after the step.
  void after_step(Simulation<D>& sim, double dt) override {
    std::int64_t due[3] = {0, 0, 0};
    for (const Reader& r : readers_) due[0] = due[0] || r.due(sim.time()) ? 1 : 0;
    if (snapshots_.due) due[1] = snapshots_.due(sim.time()) ? 1 : 0;
    if (checkpoints_.due) due[2] = checkpoints_.due(sim.time()) ? 1 : 0;
    world_->max(due, 3);
    if (due[0] != 0) {
      gather(sim);
      for (const Reader& r : readers_) r.observer->after_step(*copy_, dt);  // the first's outputs write the snapshot
    } else if (due[1] != 0 && copy_) {
      snapshots_.write(sim);
    }
    if (due[1] != 0 && !copy_) snapshots_.join(sim);
    if (due[2] != 0) (copy_ ? checkpoints_.write : checkpoints_.join)(sim);
  }

  // Brings the copy to the running simulation's present state (every process calls it).
  void gather(const Simulation<D>& sim) {
    const auto start = std::chrono::steady_clock::now();
    // One process's particles at a time (a collective each, but the first's own), so that the first process holds
    // no buffer of the whole scene beside the copy.
    std::vector<unsigned char> mine =
        sim.owned_state_bytes([&](std::size_t i) { return observed_(sim.particles(), i); });
    const std::vector<unsigned char> none;
    const auto owned_by = [&](int r) -> std::vector<unsigned char> {
      if (r == 0) {
        if (!copy_) return {};
        return std::move(mine);
      }
      return gather_bytes_on_first(*world_, r == world_->rank() ? mine : none);
    };
    if (copy_) copy_->adopt_whole_state(world_->size(), owned_by, sim);
    else
      for (int r = 0; r < world_->size(); ++r) owned_by(r);
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ++gathers_;
  }
  // How often the copy was brought up to date, and the seconds it took on this process (sending, or on the first
  // receiving and taking the particles in): run.json's partition.observer_copy.
  long gathers() const { return gathers_; }
  double seconds() const { return seconds_; }
  // The particles the copy held after the last gather (real ones, without their images); 0 on the others.
  std::size_t held() const { return copy_ ? copy_->particles().real_count() : 0; }

 private:
  const Communicator* world_;
  Simulation<D>* copy_;
  Observed observed_;
  std::vector<Reader> readers_;
  Collective snapshots_, checkpoints_;
  long gathers_ = 0;
  double seconds_ = 0.0;
};

}  // namespace slide::tools
