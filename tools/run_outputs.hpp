#pragma once
// What a run writes while it goes (DESIGN.md, "Command line and outputs"): snapshots, gauges, the surge front,
// profiles and bodies.csv, each at its scene-set interval. One observer of the step loop (coupling/advance.hpp).
#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include "cases/scene.hpp"
#include "coupling/advance.hpp"
#include "tools/atomic_file.hpp"
#include "tools/snapshot_writer.hpp"

namespace slide::tools {

// Particle data copied in id order, the order every snapshot uses: the real particles only (periodic ghosts,
// fluid/periodic.hpp, are left out), whose ids are below id_end(), with gaps where particles left the domain.
template <int D>
struct IdOrdered {
  std::vector<double> position, velocity, pressure, number_density, density;
  std::vector<std::uint8_t> phase, kind;
  std::vector<ParticleId> id;

  IdOrdered() = default;
  explicit IdOrdered(const Particles<D>& P) { assign(P); }
  // Refills from P, reusing the arrays' storage (the last good state takes one every few steps).
  void assign(const Particles<D>& P);
  SnapshotFields fields() const { return {D, position, velocity, pressure, number_density, density, phase, kind, id}; }
  // Several processes: each process's piece as bytes (its rows [begin, end), or all), and every process's pieces (one
  // after another) as one, by id.
  std::vector<unsigned char> bytes() const { return bytes(0, id.size()); }
  std::vector<unsigned char> bytes(std::size_t begin, std::size_t end) const;
  static IdOrdered merged(const std::vector<unsigned char>& pieces);
};

// The snapshots' format the scene's output keys ask for.
template <int D>
SnapshotFormat snapshot_format(const cases::Scene<D>& scene);

// Every CSV a scene asks for, in 2-D and 3-D (the 2-D diagnostics, surge front and velocity profile, are absent from
// 3-D scenes so far).
template <int D>
class RunOutputs : public StepObserver<D> {
 public:
  // resuming: the outputs continue those in `out` (restore_state), rather than starting afresh.
  RunOutputs(const cases::Scene<D>& scene, const std::filesystem::path& out, bool resuming = false)
      : RunOutputs(scene, *scene.simulation, out, resuming) {}
  // The outputs of a run on several processes: the scene's, read from the first process's whole copy of the run
  // (tools/observer_copy.hpp), which the copy's owner brings up to date after each step where samples_due() says so
  // (snapshots: write_snapshots_with).
  RunOutputs(const cases::Scene<D>& scene, const Simulation<D>& observed, const std::filesystem::path& out,
             bool resuming = false);
  // Whether after_step at time t samples anything (the CSVs), and whether it writes a snapshot; whether write_final
  // writes one.
  bool samples_due(double t) const;
  bool snapshot_due(double t) const { return snapshots_ && t >= next_snapshot_ - eps_; }
  bool final_snapshot_due() const;
  // after_step's snapshot alone: of P (or, where write_snapshots_with is set, of every process's own particles) at
  // time t and step, where one is due.
  void write_snapshot_if_due(const Particles<D>& P, double t, long step);
  // Several processes: the first's snapshots are every process's own particles, written by `shared(time, step)`, a
  // collective the others join where snapshot_due and final_snapshot_due say (tools/snapshot_rows.hpp), rather than the
  // observed copy's particles.
  void write_snapshots_with(std::function<void(double, long)> shared) { shared_snapshot_ = std::move(shared); }
  SnapshotWriter* snapshot_writer() { return snapshots_ ? &*snapshots_ : nullptr; }

  // Writes the initial state (snapshot and first samples) and flushes.
  void write_initial();
  void after_step(Simulation<D>& sim, double dt) override;
  // At the end of a completed run: the final snapshot and samples not yet taken.
  void write_final();

  void write_snapshot(const Particles<D>& P, double time, long step);
  void write_snapshot(const IdOrdered<D>& snapshot, double time, long step);
  void flush();
  std::size_t snapshot_count() const { return snapshots_ ? snapshots_->count() : 0; }
  // The time of the last snapshot written (-infinity before the first, or without snapshots).
  double last_snapshot_time() const {
    return snapshots_ && snapshots_->count() ? snapshots_->entries().back().time
                                             : -std::numeric_limits<double>::infinity();
  }

  // What the outputs have written so far and when they sample next (tools/checkpoint.hpp); flush() first, so that
  // the files on disk hold what the state says. Restoring takes the files back to that point.
  void save_state(StateWriter& out) const;
  void restore_state(StateReader& in);

 private:
  void sample();
  void sample_flume_diagnostics();
  void sample_bodies();
  void sample_profiles();
  void sample_slides();
  void sample_slide_outlines();
  void sample_slide_shapes();
  void write_gauge_records() const;
  struct ModelSurface {
    std::vector<Vec<D>> surface;  // column centres and tops, increasing x (then y)
    double front = 0.0;           // m, the largest x the material reaches
  };
  std::vector<std::pair<std::string, ModelSurface>> model_surfaces() const;
  template <class F>
  void for_each_csv(F&& f);

  const cases::Scene<D>& scene_;
  const Simulation<D>& sim_;
  std::optional<SnapshotWriter> snapshots_;
  std::function<void(double, long)> shared_snapshot_;
  std::optional<CsvWriter> gauges_, front_, velocity_profile_, bodies_, profiles_, slide_front_, slide_outline_,
      slide_shapes_;
  std::size_t next_profile_ = 0, next_outline_ = 0, next_shape_ = 0;
  double eps_ = 0.0;
  double next_snapshot_ = std::numeric_limits<double>::infinity();
  double next_sample_ = 0.0;
  double next_body_sample_ = 0.0;
  // When the last samples were taken: the end of a run adds its own only where the last step did not take them.
  double last_sample_time_ = -std::numeric_limits<double>::infinity();
  double last_body_sample_time_ = -std::numeric_limits<double>::infinity();
};

extern template struct IdOrdered<2>;
extern template struct IdOrdered<3>;
extern template SnapshotFormat snapshot_format(const cases::Scene<2>&);
extern template SnapshotFormat snapshot_format(const cases::Scene<3>&);
extern template class RunOutputs<2>;
extern template class RunOutputs<3>;

}  // namespace slide::tools
