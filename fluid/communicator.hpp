#pragma once
// The processes one run spans (DESIGN.md, "One domain seam"): which one this is, how many there are, and the few
// collective operations the domain needs: element-wise maxima and exact integer sums across processes, and one
// exchange of bytes between every pair of them. A single process (SerialCommunicator) is a run without MPI;
// mpi/mpi_communicator.hpp is MPI's. fluid/ sees only this interface, never mpi.h.
//
// Every call is collective: each process makes the same calls in the same order (the step loop's stages run on every
// process; a decision that depends on particles is reduced first, so that all processes take it alike).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace slide {

class Communicator {
 public:
  virtual ~Communicator() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  // v[k] becomes the largest v[k] over the processes (exact in any order).
  virtual void max(double* v, std::size_t n) const = 0;
  virtual void max(std::int64_t* v, std::size_t n) const = 0;
  // v[k] becomes the sum of v[k] over the processes (integers: exact in any order; the caller keeps them from
  // overflowing).
  virtual void sum(std::int64_t* v, std::size_t n) const = 0;
  // Every process sends send_bytes[r] bytes to process r, taken from `send` in the order of r; returns what it
  // received, process 0's bytes first, and sets received_bytes[r] to the count from r (itself included).
  virtual std::vector<unsigned char> exchange(const std::vector<unsigned char>& send,
                                              const std::vector<std::size_t>& send_bytes,
                                              std::vector<std::size_t>& received_bytes) const = 0;
  // The same where each process knows what it receives from each (received_bytes[r] from r): one collective call
  // fewer (a halo refresh, whose sizes the ghosts fix).
  virtual std::vector<unsigned char> exchange_known(const std::vector<unsigned char>& send,
                                                    const std::vector<std::size_t>& send_bytes,
                                                    const std::vector<std::size_t>& received_bytes) const = 0;
};

// One process: the reductions leave the values as they are, and the exchange hands a process its own bytes back.
class SerialCommunicator final : public Communicator {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  void max(double*, std::size_t) const override {}
  void max(std::int64_t*, std::size_t) const override {}
  void sum(std::int64_t*, std::size_t) const override {}
  std::vector<unsigned char> exchange(const std::vector<unsigned char>& send, const std::vector<std::size_t>& send_bytes,
                                      std::vector<std::size_t>& received_bytes) const override {
    received_bytes = send_bytes;
    return send;
  }
  std::vector<unsigned char> exchange_known(const std::vector<unsigned char>& send, const std::vector<std::size_t>&,
                                            const std::vector<std::size_t>&) const override {
    return send;
  }
};

// Every process's bytes, process 0's first, on every process.
inline std::vector<unsigned char> gather_bytes_on_all(const Communicator& comm, const std::vector<unsigned char>& mine) {
  const auto processes = static_cast<std::size_t>(comm.size());
  std::vector<unsigned char> send;
  send.reserve(mine.size() * processes);
  for (std::size_t r = 0; r < processes; ++r) send.insert(send.end(), mine.begin(), mine.end());
  std::vector<std::size_t> received;
  return comm.exchange(send, std::vector<std::size_t>(processes, mine.size()), received);
}

// Every process's bytes, process 0's first, on process 0 (empty elsewhere).
inline std::vector<unsigned char> gather_bytes_on_first(const Communicator& comm, const std::vector<unsigned char>& mine) {
  std::vector<std::size_t> send_bytes(static_cast<std::size_t>(comm.size()), 0), received;
  send_bytes[0] = mine.size();
  return comm.exchange(mine, send_bytes, received);
}

// Every process's numbers, process 0's first, on process 0 (empty elsewhere): small results for a report.
inline std::vector<double> gather_on_first(const Communicator& comm, const std::vector<double>& mine) {
  std::vector<unsigned char> bytes(mine.size() * sizeof(double));
  if (!bytes.empty()) std::memcpy(bytes.data(), mine.data(), bytes.size());
  const std::vector<unsigned char> in = gather_bytes_on_first(comm, bytes);
  std::vector<double> all(in.size() / sizeof(double));
  if (!in.empty()) std::memcpy(all.data(), in.data(), in.size());
  return all;
}

}  // namespace slide
