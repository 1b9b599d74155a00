// The test program of runs on several processes: mpirun starts it on N processes (CMakeLists.txt, Mpi.OnProcesses*),
// every test runs on all of them, only the first prints, and the program fails if a test failed on any.
#include <gtest/gtest.h>

#include <cstdint>
#include <memory>

#include "mpi/mpi_communicator.hpp"
#include "tests/mpi/world.hpp"

namespace slide::testing {
namespace {
std::shared_ptr<const Communicator> the_world;
}
const std::shared_ptr<const Communicator>& world() { return the_world; }
}  // namespace slide::testing

int main(int argc, char** argv) {
  slide::mpi::MpiSession session(argc, argv);
  slide::testing::the_world = session.world();
  ::testing::InitGoogleTest(&argc, argv);
  if (session.world()->rank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  std::int64_t failed = RUN_ALL_TESTS() != 0 ? 1 : 0;
  session.world()->max(&failed, 1);
  slide::testing::the_world.reset();
  return failed != 0 ? 1 : 0;
}
