#include "mpi/mpi_communicator.hpp"

#include <mpi.h>

#include <algorithm>
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

// MPI's counts and offsets are int: what one call carries into or out of one process stays below 2 GiB.
int as_count(std::size_t bytes) { return static_cast<int>(bytes); }

class MpiCommunicator final : public Communicator {
 public:
  explicit MpiCommunicator(std::size_t call_bytes = std::size_t(INT_MAX)) : call_bytes_(call_bytes) {
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
  // An exchange goes in rounds, each carrying at most call_bytes_ / p bytes from each process to each, so that one
  // MPI call's counts and offsets fit in an int (an exchange of over 2 GiB into or out of one process: tens of
  // millions of particles on a process's edges, or a checkpoint's share). Every process takes part in as many rounds
  // as the largest pair needs, agreed by one reduction; nearly always one, sent straight from and into the buffers.
  std::vector<unsigned char> exchange_known(const std::vector<unsigned char>& send,
                                            const std::vector<std::size_t>& send_bytes,
                                            const std::vector<std::size_t>& in) const override {
    const std::size_t p = static_cast<std::size_t>(size_);
    const std::size_t per_pair = std::max<std::size_t>(1, call_bytes_ / p);
    std::int64_t rounds = 1;
    for (std::size_t r = 0; r < p; ++r)
      rounds = std::max<std::int64_t>(
          rounds, static_cast<std::int64_t>((std::max(send_bytes[r], in[r]) + per_pair - 1) / per_pair));
    max(&rounds, 1);
    std::vector<unsigned char> result(std::accumulate(in.begin(), in.end(), std::size_t{0}));
    if (rounds == 1) {
      alltoallv(send.data(), send_bytes, result.data(), in);
      return result;
    }
    std::vector<std::size_t> send_at(p, 0), receive_at(p, 0);  // each process's section in `send` and `result`
    for (std::size_t r = 1; r < p; ++r) {
      send_at[r] = send_at[r - 1] + send_bytes[r - 1];
      receive_at[r] = receive_at[r - 1] + in[r - 1];
    }
    std::vector<unsigned char> out_round, in_round;
    std::vector<std::size_t> out_counts(p), in_counts(p);
    for (std::int64_t k = 0; k < rounds; ++k) {
      const std::size_t from = static_cast<std::size_t>(k) * per_pair;  // within each pair's bytes
      const auto part = [&](std::size_t bytes) { return bytes > from ? std::min(per_pair, bytes - from) : 0; };
      out_round.clear();
      for (std::size_t r = 0; r < p; ++r) {
        out_counts[r] = part(send_bytes[r]);
        in_counts[r] = part(in[r]);
        const unsigned char* first = send.data() + send_at[r] + from;
        out_round.insert(out_round.end(), first, first + out_counts[r]);
      }
      in_round.resize(std::accumulate(in_counts.begin(), in_counts.end(), std::size_t{0}));
      alltoallv(out_round.data(), out_counts, in_round.data(), in_counts);
      std::size_t at = 0;
      for (std::size_t r = 0; r < p; ++r) {
        std::copy_n(in_round.data() + at, in_counts[r], result.data() + receive_at[r] + from);
        at += in_counts[r];
      }
    }
    return result;
  }

 private:
  // One MPI_Alltoallv of counts[r] bytes to and from each process r, each side's bytes in the order of r (their
  // totals below 2 GiB).
  void alltoallv(const unsigned char* send, const std::vector<std::size_t>& send_bytes, unsigned char* receive,
                 const std::vector<std::size_t>& receive_bytes) const {
    const std::size_t p = static_cast<std::size_t>(size_);
    std::vector<int> send_counts(p), send_offsets(p), receive_counts(p), receive_offsets(p);
    std::size_t sent = 0, received = 0;
    for (std::size_t r = 0; r < p; ++r) {
      send_counts[r] = as_count(send_bytes[r]);
      send_offsets[r] = as_count(sent);
      receive_counts[r] = as_count(receive_bytes[r]);
      receive_offsets[r] = as_count(received);
      sent += send_bytes[r];
      received += receive_bytes[r];
    }
    check(MPI_Alltoallv(send, send_counts.data(), send_offsets.data(), MPI_BYTE, receive, receive_counts.data(),
                        receive_offsets.data(), MPI_BYTE, MPI_COMM_WORLD),
          "MPI_Alltoallv");
  }

  std::size_t call_bytes_;  // the most one MPI call carries into or out of one process
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

std::shared_ptr<const Communicator> world_with_calls_of(std::size_t bytes) {
  return std::make_shared<MpiCommunicator>(std::min(bytes, std::size_t(INT_MAX)));
}

void abort_all(int code) {
  MPI_Abort(MPI_COMM_WORLD, code);
  std::_Exit(code);
}

}  // namespace slide::mpi
