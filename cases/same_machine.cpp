#include "cases/same_machine.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <string>

namespace slide::cases {

namespace {
constexpr std::size_t kNameBytes = 256;  // a host name fits (HOST_NAME_MAX is 64 on Linux)
}

int SameMachine::count() const { return static_cast<int>(std::count(here.begin(), here.end(), char(1))); }

namespace {
// Every process's figure on every process (whole numbers: exact integer sums).
std::vector<std::int64_t> everyones(const Communicator& comm, double mine) {
  std::vector<std::int64_t> all(static_cast<std::size_t>(comm.size()), 0);
  all[static_cast<std::size_t>(comm.rank())] = static_cast<std::int64_t>(mine);
  comm.sum(all.data(), all.size());
  return all;
}
}  // namespace

double SameMachine::sum_here(const Communicator& comm, double mine) const {
  const std::vector<std::int64_t> all = everyones(comm, mine);
  double sum = 0.0;
  for (std::size_t r = 0; r < all.size(); ++r)
    if (here[r]) sum += double(all[r]);
  return sum;
}

double SameMachine::least_here(const Communicator& comm, double mine) const {
  const std::vector<std::int64_t> all = everyones(comm, mine);
  double least = mine;
  for (std::size_t r = 0; r < all.size(); ++r)
    if (here[r]) least = std::min(least, double(all[r]));
  return least;
}

SameMachine same_machine(const Communicator& comm) {
  std::vector<unsigned char> name(kNameBytes, 0);
  if (gethostname(reinterpret_cast<char*>(name.data()), kNameBytes - 1) != 0) name.assign(kNameBytes, 0);
  const std::vector<unsigned char> names = gather_bytes_on_all(comm, name);
  SameMachine m;
  for (int r = 0; r < comm.size(); ++r)
    m.here.push_back(std::equal(name.begin(), name.end(), names.begin() + std::ptrdiff_t(r) * kNameBytes) ? 1 : 0);
  return m;
}

}  // namespace slide::cases
