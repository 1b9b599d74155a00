#include "cases/particle_budget.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "fluid/vec.hpp"

namespace slide::cases {

// The constants are measured (peak_resident_bytes less resident_bytes_at_start of short runs of every shipped case at
// its spacing and 1.5 times it, 2 threads, issue 30), around what the code allocates:
//  * per particle, 310 B + 12 B a listed neighbour: the particles' arrays (130 B: fluid/particles.hpp), the last good
//    state (62 B: tools/run_outputs.hpp IdOrdered), the step's working copies (56 B), the corrective matrices and
//    other per-particle fields (about 60 B), and the list: a 4 B index and an 8 B weight a neighbour
//    (fluid/neighbor_grid.hpp, fluid/pair_weights.hpp); the bench case (no snapshots) measured 524-543 B a particle
//    at 18 listed neighbours;
//  * with snapshots 100 B a particle more (the snapshot's gathered copy, its padded positions and connectivity) and
//    7 MB fixed (HDF5's library and caches), against 3.5 MB without (the runtime's thread pools and buffers);
//  * 1 MB more with bodies or slides; 80 B a particle more with a non-Newtonian phase (the semi-implicit viscosity's
//    solver vectors);
//  * Bullet's journal: up to 12 doubles a body a step (a force, the step, a damped velocity while settling), twice:
//    a checkpoint copies it (at an interval, or at SIGTERM, at any time), and before it the vector's doubling held
//    the old and the new: a floating block's peak grew 11 MB over its 2 s of settling and 2 s of run (70,000 steps).
//    Since its blocks go back to the system when freed (tools/large_blocks_to_system.hpp), a run that writes no
//    checkpoint peaks lower: the floating block as shipped at 41.2 MB against 48.3 MB estimated (stop 61).
// Everything above the program's own is taken 5 % larger: the measured peaks scatter by 3 % about the sum. And 1 MB
// more for the scatter of small runs, which 5 % of a few MB does not cover: the peak and the program's own at its start
// each move by 0.2 MB from run to run, so their difference by 0.4 MB. With 0.5 MB here, the dam break at end_time 0.02
// peaked 3 kB above its estimate in one of two runs at stop 42 (20.283 MB against 20.281 MB), and the subaerial
// Heinrich wedge at dp 0.03 (end_time 0.02, 2 threads) peaked 0.16 MB above it in one of three runs and 0.06 MB in a
// fourth, at stop 55 (the others 0.05-0.30 MB below).
// In 3-D (refitted at stop 52 to short runs of every shipped 3-D case at its spacing and a coarser one, as
// LongMemoryEstimate runs them, 2 threads: 3,768 to 322,252 particles, mirror images included, 29 to 47 listed
// neighbours a particle): 190 B a particle, 18 B a listed neighbour and 150 B more with snapshots, chosen on a grid of
// whole steps for a margin on both sides of the test's bound: every estimate 2.4 % (the Enet & Grilli rail case at dp
// 0.045) to 12.6 % (the bench case, no snapshots) above its peak. A fit, not a count: the split between a particle and
// its neighbours is not well told apart by these runs (their counts differ little), a term per fluid particle or for
// the semi-implicit viscosity's vectors (79 B a particle, measured on the Rzadkiewicz flume, implicit against
// explicit) came out 0, and the snapshot's 150 B is more than the 30-80 B a particle that turning snapshots off frees
// (it carries what the cases with snapshots hold beyond the bench case: mirror images are cheaper than particles, and
// the bench has the most of them). Stop 48's 350 B + 12 B a neighbour + 230 B with snapshots lay 28 % above the
// Rzadkiewicz flume's peak. Stop 61: with blocks of 128 kB or more given back when freed
// (tools/large_blocks_to_system.hpp) the peaks fell 2-6 %, and at 190 B the 3-D dam break at its spacing lay 15.3 %
// above its peak (the other 3-D runs 6.1-13.3 %): 170 B a particle since, the rest as fitted.
// Stop 58's snapshot writer (tools/snapshot_writer.cpp: the rows as the file stores them, the chunk shuffled with its
// padding and zlib's output, its own buffers rather than HDF5's) peaked 0.3 MB (none) and 0.3-0.6 MB (deflate) above
// stop 57's on the subaerial wedge at dp 0.03 (4,603 particles, 2 runs each, above each run's own start): the fixed
// part with snapshots, 7.0 MB before, is taken as 7.5 MB.
// Deflated snapshots (stop 48) hold a dataset's chunk (up to 32,768 rows) in HDF5's chunk cache, the filter's output
// and the values' copy at once: measured against `none` on the same short runs, +1.1 MB (9,552 particles, 2-D),
// +1.8 MB (12,800, 2-D), +3.5 MB (38,788, 3-D): taken as 0.5 MB + 120 B a particle up to 32,768.
double first_steps_memory_bytes(const RunMemoryInputs& in) {
  const bool three_d = in.dimension == 3;
  const double per_particle = three_d ? 170.0 + 18.0 * in.listed_per_particle + (in.snapshots ? 150.0 : 0.0)
                                      : 310.0 + 12.0 * in.listed_per_particle + (in.snapshots ? 100.0 : 0.0) +
                                            (in.non_newtonian ? 80.0 : 0.0);
  const double deflate = in.snapshots && in.snapshot_deflate ? 0.5e6 + 120.0 * std::min(in.particles, 32768.0) : 0.0;
  const double fixed = (in.snapshots ? 7.5e6 : 3.5e6) + deflate + (in.bodies_or_slides ? 1.0e6 : 0.0) + 1.0e6;
  const double journal = 2.0 * (three_d ? 20.0 : 12.0) * sizeof(double) * in.body_steps;
  return 1.05 * (fixed + in.particles * per_particle + journal);
}

// Stop 61: the neighbour list's storage keeps its largest size, and the list grows where the water comes to cover
// walls it did not touch at the start (a wall particle lists the water over it). Measured (run.json's
// listed_neighbours, the most at any build over the first; whole runs, 1 thread): the 3-D bench at dp 0.02 (water
// spreading over a floor four times the column's width) +9.2 %; the 3-D dam break (dp 0.005715) +0.6 %; the floating
// box at dp 0.02 +1.3 %; the Heinrich wedges and the Rzadkiewicz slide (2-D, dp 0.03 and 0.02) +0.3-0.5 %; the 2-D dam
// breaks none (the column's free surface grows faster than the wetted floor). Taken as 10 % of the list's bytes.
double list_growth_bytes(const RunMemoryInputs& in) {
  const double per_neighbour = in.dimension == 3 ? 18.0 : 12.0;
  return 1.05 * 0.10 * per_neighbour * in.listed_per_particle * in.particles;
}

double run_memory_bytes(const RunMemoryInputs& in) { return first_steps_memory_bytes(in) + list_growth_bytes(in); }

// Measured at stop 57 (the stage peaks, VmHWM, of 4 processes, oversubscribed, against one without mpirun): the 2-D
// bench case at dp 0.005 (86,018 particles) and the 3-D bench case (230,180; 322,252 with mirror images), 1 thread:
//  * Open MPI 4.1's own (its shared-memory transport): a one-process run under mpirun peaked 7.2 MB above the same
//    without it; taken as 8 MB;
//  * the build: when the scene was built and shared, each process had peaked 322 (2-D) and 347 (3-D) B a particle
//    made above the program's and MPI's own; taken as 350 B;
//  * the observers' copy and bringing it up to date (one process's particles at a time): the first process peaked
//    267 (2-D) and 332 (3-D) B a particle of the copy (mirror images included) above the others; taken as 280 and
//    350 B. (The copy writes no snapshot: every process gives its own particles to it, tools/snapshot_rows.hpp, whose
//    buffers the share's run counts.)
// Summed, not the largest of the three: the share's run is taken on top of the build's memory, which the allocator
// keeps, only partly reused. The sum lies above every measured peak: 4 processes of the 3-D bench, estimated
// 184 MB (the others) and 291 MB (the first) against peaks of 126-130 MB and 235-240 MB.
// The settled start (coupling/start_positions.hpp): each process keeps its own particles' ids and start positions
// (8 + 8 D bytes a particle of its share, ghosts included: an upper bound), and where particles move between processes
// a follow holds the starts that left it, twice (its list and the exchange's buffer), and those its id range was
// given, twice (the buffer and the list): at most the particles it made each, 4 (8 + 8 D) bytes a particle made (the
// asks and answers are fewer). Counted, not measured. (Until stop 63 every process gathered every particle's id and
// position and kept the positions by id; until stop 64 every process received every moved particle's id, 16 bytes a
// particle of the whole scene.)
// The copy's neighbour list: the share's run's 18 (3-D) and 12 (2-D) B a listed neighbour (run_memory_bytes). Its fixed parts, found missing at stop
// 58: the gated dam break (1,355 particles) peaked at 33.2 MB on the first of 4 processes against 32.1 MB estimated.
// The ghosts' exchange (stop 63): where its ghosts are made (fluid/process_halo.hpp make_ghosts), a process holds
// the entries it sends, per process and again in one buffer for the exchange, and those it receives: counted as
// three entries a ghost (it sends about as many as it receives). Found when the build was counted as the part a
// process makes (stop 62): a share's whole run, the 3-D bench at dp 0.02 on 4 processes (Mpi.WholeRunMemoryOnFour),
// peaked 4 MB above that estimate on the share whose held particles grew most (16,454 to 20,162, half of them
// ghosts of thin slabs), and the one-process constants above hold no ghosts' exchange.
double process_memory_bytes(const RunMemoryInputs& share, const ProcessMemoryInputs& p) {
  const bool three_d = share.dimension == 3;
  const double mpi = 8.0e6, build = 350.0 * p.made;
  const double ghosts_exchange = 1.05 * 3.0 * p.ghost_entry_bytes * p.ghosts;
  const double dimension = three_d ? 3.0 : 2.0;
  const double settling = p.settles ? (8.0 * dimension + 8.0) * (share.particles + 4.0 * p.made) : 0.0;
  const double copy_per_particle = (three_d ? 350.0 : 280.0) +
                                   (p.copy_lists_neighbours ? (three_d ? 18.0 : 12.0) * share.listed_per_particle : 0.0);
  // The copy is a second scene: its fixed parts as a run's (below), without the snapshots' (it writes none).
  const double copy_fixed = 3.5e6 + (share.bodies_or_slides ? 1.0e6 : 0.0) + 1.0e6;
  return mpi + build + run_memory_bytes(share) + ghosts_exchange + settling +
         (p.first ? copy_fixed + copy_per_particle * p.copy_particles : 0.0);
}

double particle_state_bytes(double n, int dimension) {
  // fluid/particles.hpp: four vectors, seven doubles, phase and kind, id and body frame (a body's own table aside)
  return n * (4 * double(dimension) * sizeof(double) + 7 * sizeof(double) + 2 + 2 * sizeof(std::uint32_t));
}

double program_resident_bytes() {
  static const double at_start = resident_bytes_now();
  return at_start;
}

double resident_bytes_now() {
  std::ifstream statm("/proc/self/statm");
  double total_pages = 0.0, resident_pages = 0.0;
  if (!(statm >> total_pages >> resident_pages)) return 0.0;
  return resident_pages * double(sysconf(_SC_PAGESIZE));
}

double listed_neighbours_estimate(double re_over_dp, double skin_over_dp) {
  const double radius = re_over_dp + skin_over_dp;
  return 1.25 * M_PI * radius * radius;
}

namespace {

std::optional<double> read_number_after(const char* file, const std::string& label) {
  std::ifstream in(file);
  std::string word;
  while (in >> word)
    if (word == label) {
      double v = 0.0;
      if (in >> v) return v;
    }
  return std::nullopt;
}

// "2G", "512M", "100000": bytes (`variable` names it in messages).
double parse_size(const std::string& text, const std::string& variable) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  double unit = 1.0;
  const std::string suffix(end);
  if (suffix == "k" || suffix == "K") unit = 1e3;
  else if (suffix == "M") unit = 1e6;
  else if (suffix == "G") unit = 1e9;
  else if (!suffix.empty()) throw std::invalid_argument(variable + "=" + text + ": expected bytes, or k, M or G");
  if (end == text.c_str() || !std::isfinite(v) || v <= 0)
    throw std::invalid_argument(variable + "=" + text + ": expected a positive size");
  return v * unit;
}

}  // namespace

std::optional<MemoryLimit> memory_limit() {
  if (const char* env = std::getenv("SLIDE_MEMORY_LIMIT"))
    return MemoryLimit{parse_size(env, "SLIDE_MEMORY_LIMIT"), "SLIDE_MEMORY_LIMIT", true, 0.0, false};
  if (const char* env = std::getenv("SLIDE_MACHINE_MEMORY"))
    return MemoryLimit{parse_size(env, "SLIDE_MACHINE_MEMORY"), "SLIDE_MACHINE_MEMORY", true, 0.0, true};
  std::optional<MemoryLimit> best;
  if (const auto kb = read_number_after("/proc/meminfo", "MemAvailable:"))
    best = MemoryLimit{*kb * 1024.0, "MemAvailable in /proc/meminfo", false, 0.0, true};
  std::ifstream max_file("/sys/fs/cgroup/memory.max");
  std::string max_text;
  if (max_file >> max_text && max_text != "max") {
    std::ifstream current_file("/sys/fs/cgroup/memory.current");
    double current = 0.0;
    current_file >> current;
    const double headroom = std::strtod(max_text.c_str(), nullptr) - current;
    if (headroom > 0 && (!best || headroom < best->bytes))
      best = MemoryLimit{headroom, "the cgroup's memory.max", false, 0.0, true};
  }
  if (best) best->resident_when_read = resident_bytes_now();
  return best;
}

}  // namespace slide::cases
