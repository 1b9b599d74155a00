#pragma once
// How many particles this machine's memory holds, and the run's memory per particle: what `slide check` reports and
// what a scene is refused against before any particle is made (cases/build_particle_budget.cpp).
#include <cstddef>
#include <optional>
#include <string>

namespace slide::cases {

// What a run's peak memory depends on, known once its particles are made (cases/build_particle_budget.cpp).
struct RunMemoryInputs {
  double particles = 0.0;            // all, periodic ghosts included
  double listed_per_particle = 0.0;  // neighbour-list entries a particle, as built
  bool snapshots = true;             // output.snapshots: HDF5 and the snapshot's buffers
  bool snapshot_deflate = false;     // output.snapshot_compression: deflate (its chunk buffers)
  bool bodies_or_slides = false;     // rigid bodies (Bullet) or deformable slides
  bool non_newtonian = false;        // a phase with a rheology: the semi-implicit viscosity's vectors
  double body_steps = 0.0;           // rigid bodies x the steps of the settling and the run (Bullet's journal)
  int dimension = 2;                 // 3: the 3-D constants (particle_budget.cpp)
};

// The run's peak resident memory above the program's own (program_resident_bytes), bytes: fixed parts, per-particle
// arrays, the neighbour list, and Bullet's journal, which grows by every step (coupling/rigid_bodies.hpp: a
// checkpoint replays it). Measured against peak_resident_bytes on every shipped case (tests/test_memory_estimate.cpp).
double run_memory_bytes(const RunMemoryInputs& in);
// Its two parts: the peak of the run's first steps, and what the neighbour list may grow by over the run (as water
// covers walls it did not touch at the start), an allowance measured on whole runs (particle_budget.cpp).
double first_steps_memory_bytes(const RunMemoryInputs& in);
double list_growth_bytes(const RunMemoryInputs& in);

// What one process of a run on several holds beside its share's run.
struct ProcessMemoryInputs {
  double made = 0.0;            // the particles this process made (a 2-D scene's all, its part of a 3-D scene)
  double copy_particles = 0.0;  // the observers' copy's: the particles the outputs read, with their images
  bool first = false;           // the first process: it holds the copy
  bool copy_lists_neighbours = false;  // the copy lists its neighbours (the surge front reads them)
  bool settles = false;         // a settled start: its start positions (coupling/start_positions.hpp)
  double ghosts = 0.0;          // the share's ghosts (other processes' particles and images) at its largest
  double ghost_entry_bytes = 0.0;  // a ghost's entry as make_ghosts sends it (fluid/process_halo.hpp)
};

// One process of a run on several (cases::ForProcesses), above the program's own, bytes: an upper bound, the sum of
// Open MPI's own, the build, its share's run (run_memory_bytes of `share`: its owned particles and ghosts, their
// list), the ghosts' exchange, the settled start's positions, and on the first process the observers' copy (with its
// list where it keeps one). The constants: particle_budget.cpp.
double process_memory_bytes(const RunMemoryInputs& share, const ProcessMemoryInputs& process);

// Bytes of the particles' own arrays (fluid/particles.hpp) for n particles: what any run of them holds at least. The
// guard before any particle is made refuses a scene whose particles alone would not fit.
double particle_state_bytes(double n, int dimension = 2);

// Listed neighbours a particle has on average, estimated before any particle is made: the 2-D lattice points within
// the list's radius (re + skin), a quarter more for compression.
double listed_neighbours_estimate(double re_over_dp, double skin_over_dp);

// The program's own resident memory (code, libraries, runtime) before any scene: taken at the first call, which
// slide's main makes first thing. 0 where /proc/self/statm cannot be read.
double program_resident_bytes();
// The resident size now, bytes (Linux: /proc/self/statm's second field, in pages); 0 where it cannot be read.
double resident_bytes_now();

struct MemoryLimit {
  double bytes = 0.0;
  std::string source;  // where the figure comes from, for messages
  // SLIDE_MEMORY_LIMIT and SLIDE_MACHINE_MEMORY are whole allocations (a job's); MemAvailable and a cgroup's headroom are
  // what is free beyond what the process held when they were read (resident_when_read).
  bool whole_process = false;
  double resident_when_read = 0.0;
  // The machine's, shared by every process of the run on it (all but SLIDE_MEMORY_LIMIT, which is one process's).
  bool per_machine = false;
  // The limit as a total for this process, to hold a whole-run estimate against (found in review: comparing the
  // estimate with the headroom read after the particles were made counted them twice).
  double total_bytes() const { return whole_process ? bytes : bytes + resident_when_read; }
  // This process's even part where `processes_here` processes of the run share the machine.
  double even_share_bytes(int processes_here) const {
    return (per_machine ? bytes / processes_here : bytes) + (whole_process ? 0.0 : resident_when_read);
  }
};

// The memory a run may use: the environment's SLIDE_MEMORY_LIMIT (bytes, or with a k/M/G suffix: one process's share
// of a cluster job) if set, else SLIDE_MACHINE_MEMORY (the same: what the processes of the run on one machine may use
// together, as Slurm's --mem gives a job's memory a node), else the smaller of MemAvailable in /proc/meminfo and a
// cgroup v2 limit's headroom. Nothing where none of these can be read. Throws std::invalid_argument for a size that is
// not a positive size.
std::optional<MemoryLimit> memory_limit();

}  // namespace slide::cases
