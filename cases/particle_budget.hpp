#pragma once
// How many particles this machine's memory holds, and the run's memory per particle: what `slide check` reports and
// what a scene is refused against before any particle is made (cases/build_particle_budget.cpp).
#include <cstddef>
#include <optional>
#include <string>

namespace slide::cases {

// Bytes a run holds for n particles with `neighbours` listed neighbours each on average: the particles' arrays, the
// last good state a failed run writes (what a snapshot holds), the step's working copies (positions at the list's
// build and at the step's start, one vector scratch, the grid's two indices), the list and its pair weights.
double run_memory_bytes(double n, double neighbours);

// Listed neighbours a particle has on average, estimated before any particle is made: the 2-D lattice points within
// the list's radius (re + skin), a quarter more for compression.
double listed_neighbours_estimate(double re_over_dp, double skin_over_dp);

struct MemoryLimit {
  double bytes = 0.0;
  std::string source;  // where the figure comes from, for messages
};

// The memory a run may use: the environment's SLIDE_MEMORY_LIMIT (bytes, or with a k/M/G suffix: a cluster job's
// share) if set, else the smaller of MemAvailable in /proc/meminfo and a cgroup v2 limit's headroom. Nothing where
// none of these can be read. Throws std::invalid_argument for a SLIDE_MEMORY_LIMIT that is not a positive size.
std::optional<MemoryLimit> memory_limit();

}  // namespace slide::cases
