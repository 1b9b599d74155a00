#include "tools/snapshot_rows.hpp"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace slide::tools {

namespace {

// Rows [begin, end) of each piece to process r, as `exchange` takes them.
struct Outgoing {
  std::vector<unsigned char> bytes;
  std::vector<std::size_t> sizes;
};

template <int D>
void add_piece(Outgoing& out, const IdOrdered<D>& from, std::size_t begin, std::size_t end) {
  const std::vector<unsigned char> piece = from.bytes(begin, end);
  out.bytes.insert(out.bytes.end(), piece.begin(), piece.end());
  out.sizes.push_back(piece.size());
}

// Step 1: each particle to the process of its id's range, [id_end r / P, id_end (r + 1) / P).
template <int D>
IdOrdered<D> by_id_range(const IdOrdered<D>& mine, const Communicator& world) {
  const auto processes = static_cast<std::uint64_t>(world.size());
  std::int64_t id_end = mine.id.empty() ? 0 : static_cast<std::int64_t>(mine.id.back() + 1);
  world.max(&id_end, 1);
  Outgoing out;
  std::size_t begin = 0;
  for (std::uint64_t r = 0; r < processes; ++r) {
    const std::uint64_t bound = static_cast<std::uint64_t>(id_end) * (r + 1) / processes;
    const std::size_t end = std::lower_bound(mine.id.begin(), mine.id.end(), bound) - mine.id.begin();
    add_piece(out, mine, begin, end);
    begin = end;
  }
  std::vector<std::size_t> received;
  return IdOrdered<D>::merged(world.exchange(out.bytes, out.sizes, received));
}

}  // namespace

template <int D>
SnapshotRows<D> snapshot_rows(const IdOrdered<D>& mine, const Communicator& world) {
  const auto processes = static_cast<std::size_t>(world.size()), me = static_cast<std::size_t>(world.rank());
  IdOrdered<D> held = by_id_range(mine, world);
  std::vector<std::int64_t> counts(processes, 0);
  counts[me] = static_cast<std::int64_t>(held.id.size());
  world.sum(counts.data(), counts.size());
  std::vector<std::size_t> lo(processes + 1, 0);  // process r's rows: [lo[r], lo[r + 1])
  for (std::size_t r = 0; r < processes; ++r) lo[r + 1] = lo[r] + static_cast<std::size_t>(counts[r]);
  const std::size_t total = lo[processes], chunk = SnapshotWriter::chunk_rows(total);
  // Step 2: the rows before this process's first chunk start belong to the chunk the process before it began.
  const std::size_t first_start = (lo[me] + chunk - 1) / chunk * chunk;
  const std::size_t lead = std::min(first_start, lo[me + 1]) - lo[me];
  std::size_t owner = 0;  // the process holding row lo[me] - lo[me] % chunk
  while (owner + 1 < processes && lo[owner + 1] <= lo[me] - lo[me] % chunk) ++owner;
  Outgoing out;
  for (std::size_t r = 0; r < processes; ++r) add_piece(out, held, 0, r == owner && lead > 0 ? lead : 0);
  std::vector<std::size_t> received;
  std::vector<unsigned char> kept = held.bytes(lead, held.id.size());
  const std::vector<unsigned char> from_later = world.exchange(out.bytes, out.sizes, received);
  held = IdOrdered<D>();
  kept.insert(kept.end(), from_later.begin(), from_later.end());
  SnapshotRows<D> rows{IdOrdered<D>::merged(kept), 0, total};
  rows.first_row = rows.rows.id.empty() ? 0 : first_start;
  return rows;
}

template <int D>
void write_shared_snapshot(const Communicator& world, SnapshotWriter* writer, const SnapshotFormat& format,
                           const IdOrdered<D>& mine, double time, long step) {
  const SnapshotRows<D> rows = snapshot_rows(mine, world);
  if (writer) writer->write(time, step, rows.slab(), world);
  else SnapshotWriter::send(rows.slab(), format, world);
}

template SnapshotRows<2> snapshot_rows(const IdOrdered<2>&, const Communicator&);
template SnapshotRows<3> snapshot_rows(const IdOrdered<3>&, const Communicator&);
template void write_shared_snapshot(const Communicator&, SnapshotWriter*, const SnapshotFormat&, const IdOrdered<2>&,
                                    double, long);
template void write_shared_snapshot(const Communicator&, SnapshotWriter*, const SnapshotFormat&, const IdOrdered<3>&,
                                    double, long);

}  // namespace slide::tools
