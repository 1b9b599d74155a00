// An exchange between processes whose bytes pass what one MPI call carries (2 GiB, MPI's int counts) goes in rounds
// (mpi/mpi_communicator.cpp): here with calls of a few bytes, every pair's bytes arrive whole and in order, whatever
// their sizes (none, fewer than a round's share, a share's multiple, several rounds, one pair needing more rounds than
// every other), and the same as one call carries them.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "mpi/mpi_communicator.hpp"
#include "tests/mpi/world.hpp"

namespace slide::testing {
namespace {

// The bytes process `from` sends process `to` in case `c`: their count, and byte k.
std::size_t count_of(int c, int from, int to) {
  switch (c) {
    case 0: return 0;
    case 1: return static_cast<std::size_t>(1 + from + 2 * to);
    case 2: return 12;                                                // a multiple of every round's share below
    case 3: return static_cast<std::size_t>(97 * (from + 1) + 13 * to);  // several rounds
    default: return from == 1 && to == 0 ? 1000 : static_cast<std::size_t>(to);  // one pair needs the most rounds
  }
}
unsigned char byte_of(int from, int to, std::size_t k) { return static_cast<unsigned char>(31 * from + 7 * to + k); }

TEST(ExchangeRounds, EveryPairsBytesArriveWholeAndInOrder) {
  const Communicator& whole = *world();
  const int p = whole.size(), me = whole.rank();
  for (const std::size_t call_bytes : {std::size_t{1}, std::size_t{5}, std::size_t{12}, std::size_t{64}}) {
    const auto rounds = mpi::world_with_calls_of(call_bytes);
    for (int c = 0; c < 5; ++c) {
      std::vector<unsigned char> send;
      std::vector<std::size_t> send_bytes, expected_bytes;
      for (int to = 0; to < p; ++to) {
        send_bytes.push_back(count_of(c, me, to));
        for (std::size_t k = 0; k < send_bytes.back(); ++k) send.push_back(byte_of(me, to, k));
      }
      std::vector<unsigned char> expected;
      for (int from = 0; from < p; ++from) {
        expected_bytes.push_back(count_of(c, from, me));
        for (std::size_t k = 0; k < expected_bytes.back(); ++k) expected.push_back(byte_of(from, me, k));
      }
      std::vector<std::size_t> received_bytes;
      EXPECT_EQ(rounds->exchange(send, send_bytes, received_bytes), expected)
          << call_bytes << " bytes a call, case " << c;
      EXPECT_EQ(received_bytes, expected_bytes);
      EXPECT_EQ(rounds->exchange_known(send, send_bytes, expected_bytes), expected);
      EXPECT_EQ(whole.exchange_known(send, send_bytes, expected_bytes), expected);
    }
  }
}

}  // namespace
}  // namespace slide::testing
