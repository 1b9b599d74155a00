// A snapshot on several processes (tools/snapshot_rows.hpp, tools/snapshot_writer.hpp): each process's particles, in
// no order and with gaps in their ids, become rows in id order with every chunk's rows on one process, and the file
// the processes write together is, byte for byte, the one a single process writes of them all.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "tests/mpi/world.hpp"
#include "tools/snapshot_rows.hpp"

namespace slide::testing {
namespace {

using tools::IdOrdered;

// Particle k of `count`: its id (gaps: every seventh id unused), its values, and the process that owns it (blocks of
// 5000 dealt round, shifted by k % 3: every process's ids are scattered).
constexpr std::uint64_t id_of(std::size_t k) { return k + k / 6; }
int owner_of(std::size_t k, int processes) { return static_cast<int>((k / 5000 + k % 3) % processes); }

void put(IdOrdered<3>& to, std::size_t k) {
  for (int d = 0; d < 3; ++d) {
    to.position.push_back(0.001 * double(k) + d);
    to.velocity.push_back(-0.5 * double(k) / (d + 1.0));
  }
  to.pressure.push_back(1000.0 + double(k % 977) / 3.0);
  to.number_density.push_back(6.0 + double(k % 13));
  to.density.push_back(1000.0 + double(k % 2) * 600.0);
  to.phase.push_back(static_cast<std::uint8_t>(k % 2));
  to.kind.push_back(static_cast<std::uint8_t>(k % 3));
  to.id.push_back(id_of(k));
}

IdOrdered<3> owned(std::size_t count, int rank, int processes) {
  IdOrdered<3> mine;
  for (std::size_t k = 0; k < count; ++k)
    if (owner_of(k, processes) == rank) put(mine, k);
  return mine;
}

IdOrdered<3> all_of(std::size_t count) {
  IdOrdered<3> all;
  for (std::size_t k = 0; k < count; ++k) put(all, k);
  return all;
}

std::string file_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// 100,000 rows: a chunk start on every process up to 4; 40,000: on 4 processes two of them hold none.
TEST(SnapshotRows, EachChunksRowsLieOnOneProcessInIdOrder) {
  const Communicator& comm = *world();
  for (const std::size_t count : {std::size_t(100000), std::size_t(40000)}) {
    const tools::SnapshotRows<3> rows = tools::snapshot_rows(owned(count, comm.rank(), comm.size()), comm);
    const std::size_t n = rows.rows.id.size(), chunk = tools::SnapshotWriter::chunk_rows(count);
    EXPECT_EQ(rows.total, count);
    if (n > 0) {
      EXPECT_EQ(rows.first_row % chunk, 0u) << "process " << comm.rank();
      EXPECT_TRUE(n % chunk == 0 || rows.first_row + n == count) << "process " << comm.rank();
    }
    const std::vector<unsigned char> gathered = gather_bytes_on_first(comm, rows.rows.bytes());
    if (comm.rank() != 0) continue;
    // Every process's rows one after another are all the particles in id order (merged sorts, so compare ids too).
    const IdOrdered<3> together = IdOrdered<3>::merged(gathered), expected = all_of(count);
    EXPECT_EQ(together.id, expected.id);
    EXPECT_EQ(together.position, expected.position);
    EXPECT_EQ(together.pressure, expected.pressure);
    EXPECT_EQ(together.kind, expected.kind);
  }
}

TEST(SnapshotRows, TheProcessesWriteTheFileOneProcessWrites) {
  const Communicator& comm = *world();
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("slide_mpi_snapshot_rows_" + std::to_string(comm.size()));
  for (const bool deflate : {true, false}) {
    tools::SnapshotFormat format;
    format.deflate = deflate;
    std::optional<tools::SnapshotWriter> together, alone;
    if (comm.rank() == 0) {
      std::filesystem::remove_all(dir);
      together.emplace(dir / "together", tools::SnapshotLegend{"0 fluid", "0 water", "test"}, true, format);
      alone.emplace(dir / "alone", tools::SnapshotLegend{"0 fluid", "0 water", "test"}, true, format);
    }
    const std::size_t count = 70000;
    tools::write_shared_snapshot(comm, together ? &*together : nullptr, format,
                                 owned(count, comm.rank(), comm.size()), 0.25, 7);
    if (comm.rank() != 0) continue;
    alone->write(0.25, 7, all_of(count).fields());
    const std::string file = tools::SnapshotWriter::snapshot_relative_path(0);
    const std::string a = file_bytes(dir / "alone" / file), b = file_bytes(dir / "together" / file);
    EXPECT_GT(a.size(), 1000u);
    EXPECT_TRUE(a == b) << "on " << comm.size() << " processes, deflate " << deflate;
    EXPECT_EQ(file_bytes(dir / "alone" / "particles.xdmf"), file_bytes(dir / "together" / "particles.xdmf"));
  }
  if (comm.rank() == 0) std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace slide::testing
