#pragma once
// The processes of a run that share this machine's memory: those with this process's host name (gethostname). A
// machine-wide memory limit (cases/particle_budget.hpp: MemAvailable, a cgroup's, SLIDE_MACHINE_MEMORY) is theirs
// together, not each one's.
#include <vector>

#include "fluid/communicator.hpp"

namespace slide::cases {

struct SameMachine {
  std::vector<char> here;  // here[r]: process r runs on this machine (this process included)
  int count() const;
  // Collective: the sum, and the least, of `mine` over the processes on this machine (whole numbers).
  double sum_here(const Communicator& comm, double mine) const;
  double least_here(const Communicator& comm, double mine) const;
};

// Collective: which processes share this machine. One process alone: itself.
SameMachine same_machine(const Communicator& comm);

}  // namespace slide::cases
