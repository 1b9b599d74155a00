#pragma once
// A checkpoint on several processes (tools/checkpoint.hpp): the same bytes as one process's checkpoint of the same
// state (coupling/simulation.hpp, save_state), from every process's own particles. The particles go to the process of
// their id's range (one exchange of a share), then to the first process one range at a time, which writes them as
// they come: no process holds the whole scene. The rest of the state is the first process's.
#include "coupling/simulation.hpp"
#include "fluid/communicator.hpp"
#include "fluid/state_stream.hpp"
#include "tools/checkpoint.hpp"

namespace slide::tools {

// Collective. file and rest: on the first process, the checkpoint with its header written and the state after the
// particle section (Simulation::save_state_after_particles and what follows it); null on the others. Commits the file.
template <int D>
void write_shared_checkpoint(const Communicator& world, const Simulation<D>& sim, CheckpointFile* file,
                             const StateWriter* rest);

extern template void write_shared_checkpoint(const Communicator&, const Simulation<2>&, CheckpointFile*,
                                             const StateWriter*);
extern template void write_shared_checkpoint(const Communicator&, const Simulation<3>&, CheckpointFile*,
                                             const StateWriter*);

}  // namespace slide::tools
