#pragma once
// The one step loop (DESIGN.md, "The step loop"): neighbours, explicit viscosity and gravity, number density and
// pressure at the predicted positions, pressure-gradient correction, collisions, rigid bodies (fluid force in,
// Bullet step, boundary particles placed from the new poses), stability checks.
//
// The particles live in the domain (fluid/domain.hpp): the real (owned) particles, then their ghost copies (today
// the periodic images in x, options.periodic_x). Every stage computes the real particles only and then refreshes the
// fields its neighbours read next; the checks, the time-step limits and the largest speed are the domain's
// reductions over real particles. Outputs must take the first particles().real_count() entries
// (tools/run_outputs.hpp, IdOrdered).
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "fluid/domain.hpp"
#include "fluid/equation_of_state.hpp"
#include "fluid/fluid_options.hpp"
#include "fluid/pore_pressure.hpp"
#include "fluid/water_surface.hpp"
#include "fluid/gradient.hpp"
#include "fluid/image_neighbours.hpp"
#include "fluid/implicit_viscosity.hpp"
#include "fluid/kernel.hpp"
#include "fluid/lattice.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/pair_weights.hpp"
#include "fluid/particles.hpp"
#include "fluid/phase.hpp"
#include "fluid/state_stream.hpp"
#include "fluid/viscosity.hpp"
#include "fluid/wall_crossing.hpp"

namespace slide {

template <int D>
class RigidBodies;  // coupling/rigid_bodies.hpp

// What the semi-implicit viscous stage has solved so far (run.json reports it).
struct ViscousSolveStats {
  long solves = 0;
  long iterations = 0;      // summed over solves
  int most_iterations = 0;  // in one solve
  double largest_residual = 0.0;
  long unconverged = 0;     // solves that stopped at the iteration cap
};

// A fluid particle taken out of the run: it left the domain's bounds through an open side (fluid/wall_crossing.hpp).
struct LeftParticle {
  ParticleId id = 0;
  double time = 0.0;                // s, the end of the step it left in
  std::vector<double> position;     // where it was then, m
};

struct Instability {
  std::string reason;     // what went wrong
  double time = 0.0;
  long step = 0;
  ParticleId particle = 0;
  std::vector<double> position;
};

// More processes than a scene's neighbour grid has cells (Simulation::check_processes).
struct TooManyProcesses : std::invalid_argument {
  using std::invalid_argument::invalid_argument;
};

// A checkpoint's state refused on another process (restore_state, several processes): that one says why.
struct StateRefusedElsewhere : std::runtime_error {
  using std::runtime_error::runtime_error;
};

template <int D>
class Simulation {
 public:
  Simulation() = default;
  Simulation(const Simulation&) = delete;
  Simulation& operator=(const Simulation&) = delete;

  // The real particles, then their ghosts (fluid/domain.hpp).
  Particles<D>& particles() { return domain_.particles; }
  const Particles<D>& particles() const { return domain_.particles; }
  const Domain<D>& domain() const { return domain_; }
  // The processes this run spans (fluid/communicator.hpp), before initialise(): every process has then built the scene
  // whole, or (`whole` false) a part of it, and the first rebuild gives each its share. Not called: one process.
  void set_communicator(std::shared_ptr<const Communicator> comm, bool whole = true) {
    domain_.set_communicator(std::move(comm), whole);
  }
  FluidOptions<D> options;
  // The phases particles refer to (Particles::phase). With any non-Newtonian phase, every fluid particle's viscosity
  // is set from its phase's rheology at the start of each step; empty: viscosities stay as the particles were made.
  // A phase with a finite basal_friction gets its particles' wall viscosity (Particles::wall_fraction) there too.
  std::vector<Phase> phases;

  // Derived at initialise(): lattice constants, equation of state, grid.
  LatticeConstants lattice;
  EquationOfState eos;

  double re() const { return options.re_over_dp * options.dp; }
  double time() const { return time_; }
  long step_count() const { return step_count_; }
  const std::array<long, time_step_limit_count>& limit_counts() const { return limit_counts_; }  // per limit that ruled
  // The largest n / n0 of any fluid particle after any step since t = 0, and when: the run's largest compression,
  // which the sound speed bounds (density changes of order (u / c0)^2). 1 before the first step.
  double largest_number_density_ratio() const { return largest_number_density_ratio_; }
  double largest_number_density_ratio_time() const { return largest_number_density_ratio_time_; }

  // The fixed walls' faces, for telling a particle that passed through a wall from one that left through an open side
  // (fluid/wall_crossing.hpp). Empty: no wall is checked, and every particle leaving the domain is removed.
  WallCrossing<D> wall_crossing;
  // The fluid particles taken out of the run because they left the domain, in the order they left (by id within a
  // step).
  const std::vector<LeftParticle>& left_the_domain() const { return left_the_domain_; }

  // Rigid bodies two-way coupled with the fluid; null when the scene has none.
  const std::shared_ptr<RigidBodies<D>>& bodies() const { return bodies_; }
  void attach_bodies(std::shared_ptr<RigidBodies<D>> bodies) { bodies_ = std::move(bodies); }
  std::shared_ptr<RigidBodies<D>> detach_bodies() { return std::move(bodies_); }

  // Fluid velocities decay as exp(-rate t) in every step (settling only; 0 = off).
  void set_velocity_damping(double rate_per_s) { options.velocity_damping_rate = rate_per_s; }

  // While settling (coupling/relaxation.hpp), non-Newtonian phases take settling_viscosity (fluid/rheology/rheology.hpp)
  // instead of their rheology, so that their pressure settles hydrostatic; the rheology acts again once it is off.
  void set_rheology_suspended(bool suspended) { rheology_suspended_ = suspended; }
  // After an observer moved particles between steps (their positions and velocities, as settling's held phases):
  // their ghosts (periodic and mirror images, other processes' copies) take the new values before the next step reads
  // them. Every process calls it (a collective on several).
  void refresh_moved_ghosts();

  // The first process's observers' copy of a run on several processes (tools/observer_copy.hpp), before initialise():
  // it never steps, so initialise() makes no neighbour list (a run's largest array) and computes nothing, and
  // adopt_whole_state lists the particles only where `list` asks (an output reads neighbours: the surge front).
  void make_observers_copy(bool list) {
    observers_copy_ = true;
    copy_lists_ = list;
  }
  // The copy, once built: its particles dropped and their memory given back until the first adopt_whole_state fills
  // it (the copy is built before the running scene, whole in 2-D, its part in 3-D; holding it beside the build doubled
  // the first process's peak). Their id range (the whole scene's) stays.
  void drop_copy_particles();
  // The real particles of the whole run: on one process its own; on an observers' copy, every process's owned
  // particles at the last adopt_whole_state, of which the copy holds those the outputs read.
  std::size_t particles_in_run() const { return observers_copy_ ? particles_in_run_ : domain_.particles.real_count(); }

  // Computes n0 and lambda from the lattice, builds the neighbour list, and evaluates number density and
  // pressure at the initial positions. With a communicator set (set_communicator), the first re-sort keeps this
  // process's share, so that no process lists the whole scene. Throws std::invalid_argument for a periodic domain
  // with rigid bodies, with a period shorter than twice re + skin, or with a boundary particle outside the period, and
  // TooManyProcesses.
  void initialise();

  // Makes the present positions the start of the run: time and step counts back to zero, fluid at rest, and
  // initialise() again (after a settled start).
  void restart_at_rest();
  // Removes the particles of these ids (sorted; a scene's gates) on whichever process holds them, and renumbers the
  // others' ids as Particles::remove_if does on one process: id minus the removed ids below it, so that ids stay
  // creation ranks (the ids were 0 .. n - 1 over all processes: nothing has left the run). initialise() follows.
  void remove_particles(const std::vector<ParticleId>& sorted_ids);

  // The time step the limits allow now, and which limit ruled.
  std::pair<double, TimeStepLimit> allowed_time_step() const;

  // Advances by dt: the stages below in order, then the checks. Returns the instability found after the step, if
  // any (the state is then the failed one).
  std::optional<Instability> step(double dt, TimeStepLimit limit);

  // Everything a step depends on beyond the scene (tools/checkpoint.hpp): the particles, time and counters, the
  // neighbour list's state (the positions it was built at, so that it is rebuilt at the same step), what was recorded
  // so far, and the bodies'. Restoring expects a simulation made from the same scene and initialised, on one process
  // or built in parts on several (each process then reads a part of the particle section, any part, and they share
  // the particles as a re-sort at the saved run's last positions would: a collective); afterwards the particles are
  // stored as the processes held them (one: as adopt_whole_state leaves them) and the next step is the one the saved
  // run would have taken, bit for bit.
  //
  // The state (written by tools/shared_checkpoint.hpp, on one process or several) is its particle section, then the
  // rest (save_state_after_particles). The particle section holds every
  // real particle in id order and those that left the domain by time, then id, whichever process held them, so that
  // a checkpoint does not say how many processes wrote it (tools/shared_checkpoint.hpp writes one from every
  // process's own particles):
  //   its head (fluid/particle_section_head.hpp), the records, u64 left, the left particles
  // A record: every per-particle array's value (fluid/process_halo.hpp), the position the neighbour list was built at,
  // and the corrected gradient's matrix of the last pressure stage where present (the semi-implicit predictor reads
  // it in the next step).
  // (Throws std::runtime_error where the state is not this scene's; on several processes, StateRefusedElsewhere on
  // those whose part was not refused where another's was.)
  void restore_state(StateReader& in);
  // This process's own particles' records in id order, and their ids: all, or those of [begin, end) of `order`
  // (owned_in_id_order: a part at a time).
  struct StateRecords {
    std::vector<unsigned char> bytes;
    std::vector<ParticleId> ids;
    std::size_t record_bytes = 0, id_offset = 0;  // a record's bytes, and where in it its id lies
    bool correction = false;
  };
  StateRecords state_records() const;
  std::vector<std::uint32_t> owned_in_id_order() const;
  StateRecords state_records(const std::vector<std::uint32_t>& order, std::size_t begin, std::size_t end) const;
  // The left particles' part of the section, sorted by time, then id.
  static void put_left_particles(StateWriter& out, std::vector<LeftParticle> left);
  void save_state_after_particles(StateWriter& out) const;

  // For tests of the order independence (fluid/domain.hpp): after every re-sort the owned particles are stored in an
  // order drawn at random from `seed`, as a process's share of them would be; every result must stay the same to the
  // bit.
  void shuffle_storage_after_sorting(std::uint64_t seed) { storage_shuffle_seed_ = seed; }

  // Checks the current state: non-finite values, number-density collapse, speed.
  std::optional<Instability> check() const;

  const NeighborList& neighbors() const { return list_; }
  const NeighborGrid<D>& grid() const { return grid_; }
  long neighbor_rebuilds() const { return rebuilds_; }
  // Neighbours listed (this process's) at the first build and the most at any build since: the list's storage keeps
  // its largest size, which the memory estimate, taken at the first build, does not know (run.json reports both).
  std::size_t listed_at_first_build() const { return listed_at_first_build_; }
  std::size_t most_listed() const { return most_listed_; }
  // The same of the particles held (owned and ghosts), which grow too on several processes as particles come into a
  // process's cells.
  std::size_t held_at_first_build() const { return held_at_first_build_; }
  std::size_t most_held() const { return most_held_; }
  const ViscousSolveStats& viscous_solves() const { return viscous_solves_; }
  const ViscousSolveReport& last_viscous_solve() const { return last_viscous_solve_; }
  double max_fluid_speed() const;

  // The pore water's pressure anywhere (fluid/pore_pressure.hpp), from the water's surface as of the start of the
  // latest step (or initialise()); zero everywhere where the scene has no pore water: no phase of a frictional
  // strength, method.pore_pressure none, the first phase not Newtonian (the water is the first phase), or no gravity.
  PorePressureField<D> pore_pressure_field() const;

  // Several processes (tools/run_driver.cpp): after the scene is built (or restored from a checkpoint) as on one
  // process, before it settles, the run goes on across the processes of `comm`: each keeps its share of the particles
  // (a re-sort at the positions of the last re-sort, which leaves a scene just built as it is: the same order, the
  // same neighbour list); a simulation shared since its build (set_communicator before initialise) stays as it is.
  // Throws std::invalid_argument for
  // what does not run on several processes yet (prepare_processes) and for more processes than the grid has cells.
  void distribute(std::shared_ptr<const Communicator> comm);
  // The refusals of distribute, for `processes`, before a run (its settling) starts.
  void check_processes(int processes) const;

  // The first process's copy of a run on several processes (tools/observer_copy.hpp). owned_state_bytes: this
  // process's owned particles for which read(i) holds (those the outputs read, cases/observed_particles.hpp; all
  // without read), every array with the position the neighbour list was built at, its count of owned particles, and
  // the particles it took out of the run. adopt_whole_state, on a simulation of the same scene on one process: every
  // process's owned_state_bytes (owned_by(r) gives process r's, for r from 0 to processes - 1, each called once, in
  // order), and the running simulation's time and counters; afterwards the particles are stored, given ghosts and a
  // neighbour list as one process would hold them at this step (by cell of the positions of the last re-sort, by id
  // within a cell), so that every output reads the same numbers in the same order as one process's run, the corrected
  // gradient's matrices of the last pressure stage included; the rigid bodies are the running simulation's own
  // (shared).
  std::vector<unsigned char> owned_state_bytes(const std::function<bool(std::size_t)>& read = {}) const;
  void adopt_whole_state(int processes, const std::function<std::vector<unsigned char>(int)>& owned_by,
                         const Simulation& running);

  // Fluid number density at an arbitrary point (fluid particles only), for free-surface detection by gauges.
  double fluid_number_density_at(const Vec<D>& point) const;

 private:
  // The stages of one step (DESIGN.md, "The step loop").
  void update_neighbors(bool force);
  void update_viscosity(double dt);
  void update_water_surface();
  void record(const ViscousSolveReport& r);
  void predict_with_viscosity_and_gravity(double dt);
  void compute_pressure();
  void update_gradient_correction();
  void correct_with_pressure_gradient(double dt);
  void collide(double dt);
  void move_bodies(double dt);
  void remove_particles_that_left();
  void shuffle_owned_particles();
  std::optional<std::uint64_t> storage_shuffle_seed_;

  double particle_volume() const { return std::pow(options.dp, D); }  // per unit width in 2-D
  double list_radius() const { return re() + options.skin_over_dp * options.dp; }
  void check_periodic_setup() const;
  void check_mirror_setup() const;
  void prepare_processes();
  // A record of the particle section (restore_state) for particle i, and one read back onto the end of the particles.
  void append_state_record(std::size_t i, bool correction, std::vector<unsigned char>& out) const;
  void read_state_record(const unsigned char*& in, bool correction);
  // After the real particles and their build positions (and gradient matrices) were read in any order: stores them
  // as one process holds them at this step (by cell of the positions of the last re-sort, by id within a cell; on
  // several processes, this one's cells' after share_restored_particles), with their ghosts, neighbour list (unless an
  // observers' copy needs none) and the ghosts' fields.
  void store_as_one_process(bool correction);
  void share_restored_particles(bool correction);
  // The particle section (restore_state) read back in id order, of a scene of `made` particles; returns whether it
  // holds gradient matrices.
  bool read_particle_section(StateReader& in, std::size_t made);
  void read_state_after_particles(StateReader& in);

  Domain<D> domain_;
  std::shared_ptr<RigidBodies<D>> bodies_;
  double time_ = 0.0;
  long step_count_ = 0;
  std::array<long, time_step_limit_count> limit_counts_{};
  double largest_number_density_ratio_ = 1.0, largest_number_density_ratio_time_ = 0.0;
  void record_largest_compression(double n_max);
  int problem_code(std::size_t i) const;
  Instability problem_report(int worst) const;
  int face_crossed(std::size_t i) const;
  std::optional<Instability> wall_crossing_report() const;
  bool outside_domain(std::size_t i) const;
  NeighborGrid<D> grid_;
  NeighborList list_;
  ImageNeighbours image_neighbours_;  // of the predicted positions: the mirror fill finds them, the wall pressure reads them
  PairWeights pair_weights_;  // of the predicted positions: compute_pressure takes them, the gradient reads them
  std::vector<Vec<D>> position_at_build_;
  std::vector<Vec<D>> position_at_step_start_;  // for face_crossed; filled only when there are wall faces
  std::vector<LeftParticle> left_the_domain_;
  std::vector<Vec<D>> scratch_;
  std::vector<Vec<D>> predictor_acceleration_;  // semi-implicit viscous stage: a - grad p / rho given to the solve
  std::vector<Vec<D>> start_velocity_;  // semi-implicit viscous stage: u at the start of the step
  long rebuilds_ = 0;
  std::size_t listed_at_first_build_ = 0, most_listed_ = 0, held_at_first_build_ = 0, most_held_ = 0;
  // P.gradient_correction holds the matrices of the last pressure stage for the particles in their present order
  // (the corrected gradient; a rebuild, which re-sorts, clears it; a checkpoint keeps both).
  bool correction_current_ = false;
  bool rheology_ = false;  // some phase is non-Newtonian
  bool rheology_suspended_ = false;
  bool basal_friction_ = false;  // some phase has a Coulomb basal friction (fluid/basal_friction.hpp)
  bool pore_water_ = false;  // the frictional strengths act on the effective stress (pore_pressure_field)
  WaterSurface<D> water_surface_;  // of the first phase (the water), when pore_water_
  ImplicitViscosity implicit_viscosity_;
  bool observers_copy_ = false, copy_lists_ = false;  // make_observers_copy
  std::size_t particles_in_run_ = 0;  // an observers' copy's: particles_in_run
  ViscousSolveStats viscous_solves_;
  ViscousSolveReport last_viscous_solve_;
};

extern template class Simulation<2>;
extern template class Simulation<3>;

}  // namespace slide
