#pragma once
// The processes the MPI test program runs on (tests/mpi/main.cpp): every test runs on all of them.
#include <memory>

#include "fluid/communicator.hpp"

namespace slide::testing {
const std::shared_ptr<const Communicator>& world();
}  // namespace slide::testing
