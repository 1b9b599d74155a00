#include "mpi/mpi_communicator.hpp"

#include <mpi.h>

#include <climits>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <stdexcept>

namespace slide::mpi {

namespace {

void check(int rc, const char* what) {
  if (rc != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

// MPI's counts and offsets are int: one exchange of 2 GiB or more into or out of one process must be split (not yet
// needed: 2 GiB is over ten million particles on one process's edge). Found on one process only, inside a collective
// call where the others wait: every process is stopped, with the message.
int as_count(std::size_t bytes) {
  if (bytes > std::size_t(INT_MAX)) {
    std::fprintf(stderr, "slide: error: one exchange between processes of more than 2 GiB (not yet supported)\n");
    abort_all(1);
  }
  return static_cast<int>(bytes);
}

class MpiCommunicator final : public Communicator {
 public:
  MpiCommunicator() {
    check(MPI_Comm_rank(MPI_COMM_WORLD, &rank_), "MPI_Comm_rank");
    check(MPI_Comm_size(MPI_COMM_WORLD, &size_), "MPI_Comm_size");
  }
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  void max(double* v, std::size_t n) const override {
    check(MPI_Allreduce(MPI_IN_PLACE, v, static_cast<int>(n), MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
  }
  void max(std::int64_t* v, std::size_t n) const override {
    check(MPI_Allreduce(MPI_IN_PLACE, v, static_cast<int>(n), MPI_INT64_T, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
  }
  void sum(std::int64_t* v, std::size_t n) const override {
    check(MPI_Allreduce(MPI_IN_PLACE, v, static_cast<int>(n), MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD), "MPI_Allreduce");
  }
  std::vector<unsigned char> exchange(const std::vector<unsigned char>& send, const std::vector<std::size_t>& send_bytes,
                                      std::vector<std::size_t>& received_bytes) const override {
    const std::size_t p = static_cast<std::size_t>(size_);
    std::vector<std::uint64_t> out(send_bytes.begin(), send_bytes.end()), in(p);
    check(MPI_Alltoall(out.data(), 1, MPI_UINT64_T, in.data(), 1, MPI_UINT64_T, MPI_COMM_WORLD), "MPI_Alltoall");
    received_bytes.assign(in.begin(), in.end());
    return exchange_known(send, send_bytes, received_bytes);
  }
  std::vector<unsigned char> exchange_known(const std::vector<unsigned char>& send,
                                            const std::vector<std::size_t>& send_bytes,
                                            const std::vector<std::size_t>& in) const override {
    const std::size_t p = static_cast<std::size_t>(size_);
    std::vector<int> send_counts(p), send_offsets(p), receive_counts(p), receive_offsets(p);
    std::size_t sent = 0, received = 0;
    for (std::size_t r = 0; r < p; ++r) {
      send_counts[r] = as_count(send_bytes[r]);
      send_offsets[r] = as_count(sent);
      receive_counts[r] = as_count(in[r]);
      receive_offsets[r] = as_count(received);
      sent += send_bytes[r];
      received += in[r];
    }
    std::vector<unsigned char> result(received);
    check(MPI_Alltoallv(send.data(), send_counts.data(), send_offsets.data(), MPI_BYTE, result.data(),
                        receive_counts.data(), receive_offsets.data(), MPI_BYTE, MPI_COMM_WORLD),
          "MPI_Alltoallv");
    return result;
  }

 private:
  int rank_ = 0, size_ = 1;
};

}  // namespace

bool launched_by_mpi() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"})
    if (std::getenv(name) != nullptr) return true;
  return false;
}

// The first of the variables present decides: mpirun inside a Slurm job starts its daemons in a job step of its own
// (one task per node), whose SLURM_STEP_NUM_TASKS its processes inherit beside mpirun's OMPI_COMM_WORLD_SIZE.
std::optional<LauncherCount> launcher_process_count() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "SLURM_STEP_NUM_TASKS"}) {
    const char* value = std::getenv(name);
    if (value == nullptr) continue;
    char* end = nullptr;
    const long n = std::strtol(value, &end, 10);
    if (end == value || *end != '\0' || n <= 1) return std::nullopt;
    return LauncherCount{name, n};
  }
  return std::nullopt;
}

MpiSession::MpiSession(int& argc, char**& argv) {
  int provided = 0;
  check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  if (provided < MPI_THREAD_FUNNELED) {
    MPI_Finalize();
    throw std::runtime_error("MPI: the library does not allow threads beside it (MPI_THREAD_FUNNELED)");
  }
  world_ = std::make_shared<MpiCommunicator>();
}

MpiSession::~MpiSession() { MPI_Finalize(); }

void abort_all(int code) {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::_Exit(code);
}

}  // namespace slide::mpi
