#pragma once
// MPI's communicator behind slide's Communicator (fluid/communicator.hpp), and the life of MPI in one program: only
// this folder includes mpi.h.
//
// A program started by mpirun (or srun) finds its launcher's variables in the environment (launched_by_mpi) and
// starts MPI (MpiSession); a program started alone does not touch MPI and runs as today's single process. MPI is
// called only from the thread that started it, outside parallel regions (MPI_THREAD_FUNNELED).
#include <cstddef>
#include <memory>
#include <optional>
#include <string>

#include "fluid/communicator.hpp"

namespace slide::mpi {

// Whether a launcher (Open MPI's mpirun, PMIx, Slurm's srun with PMI) started this process.
bool launched_by_mpi();

// How many processes the launcher says it started together (Open MPI's OMPI_COMM_WORLD_SIZE, PMI's PMI_SIZE, a Slurm
// job step's SLURM_STEP_NUM_TASKS: the first present), and in which variable; none where it says one or none is set. Where MPI then joins
// fewer (a program whose MPI is not the launcher's, or srun without PMI support), every process would run the whole
// scene alone into the same folder: main refuses that (exit 2) before anything runs.
struct LauncherCount {
  std::string variable;
  long processes = 1;
};
std::optional<LauncherCount> launcher_process_count();

// MPI started on construction and finished on destruction (all processes together); world() is then every process
// of the run.
class MpiSession {
 public:
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  std::shared_ptr<const Communicator> world() const { return world_; }

 private:
  std::shared_ptr<const Communicator> world_;
};

// Every process of the run (as MpiSession::world(), MPI started), whose exchanges carry at most `bytes` into or out
// of one process in one MPI call (MpiSession's: 2 GiB - 1, what MPI's int counts allow), in rounds past it: the tests
// exchange in rounds of a few bytes.
std::shared_ptr<const Communicator> world_with_calls_of(std::size_t bytes);

// Stops every process of the run at once with `code` as the run's exit status (one process failed: the others may be
// waiting for it in a collective call and would wait for ever).
[[noreturn]] void abort_all(int code);

}  // namespace slide::mpi
