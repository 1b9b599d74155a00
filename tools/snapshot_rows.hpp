#pragma once
// A snapshot on several processes (tools/snapshot_writer.hpp): the rows of every process's real particles in id
// order, each chunk's rows on one process, so that the process holding them encodes the chunk. Two exchanges of one
// share each: particles to the process of their id's range (rows then follow from the counts), then each process's
// first rows, up to its first chunk's start, back to the process holding that chunk's first row.
#include <cstddef>

#include "fluid/communicator.hpp"
#include "tools/run_outputs.hpp"

namespace slide::tools {

template <int D>
struct SnapshotRows {
  IdOrdered<D> rows;  // this process's rows, in id order
  std::size_t first_row = 0, total = 0;
  SnapshotSlab slab() const { return {rows.fields(), first_row, total}; }
};

// Collective: `mine`, a process's own particles in id order, as its rows of the snapshot of all of them.
template <int D>
SnapshotRows<D> snapshot_rows(const IdOrdered<D>& mine, const Communicator& world);

// Collective: the snapshot of every process's `mine`, written by the first process's writer (null on the others; the
// others need the scene's format to encode their chunks alike).
template <int D>
void write_shared_snapshot(const Communicator& world, SnapshotWriter* writer, const SnapshotFormat& format,
                           const IdOrdered<D>& mine, double time, long step);

extern template SnapshotRows<2> snapshot_rows(const IdOrdered<2>&, const Communicator&);
extern template SnapshotRows<3> snapshot_rows(const IdOrdered<3>&, const Communicator&);
extern template void write_shared_snapshot(const Communicator&, SnapshotWriter*, const SnapshotFormat&,
                                           const IdOrdered<2>&, double, long);
extern template void write_shared_snapshot(const Communicator&, SnapshotWriter*, const SnapshotFormat&,
                                           const IdOrdered<3>&, double, long);

}  // namespace slide::tools
