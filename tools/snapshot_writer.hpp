#pragma once
// Particle snapshots readable by ParaView (XDMF) and h5py, crash-safe, O(1) HDF5 data written per
// snapshot.
//
// Layout under out_dir:
//   snapshots/snapshot_000000.h5, snapshot_000001.h5, ...   one file per snapshot, each written
//       under a temporary name, closed, fsync()ed and renamed. Datasets (n particles):
//       /position, /velocity  float64 n x 3 (z = 0 in 2-D), /pressure, /number_density, /density
//       float64 n, /phase, /kind uint8 n, /id uint32 n, /connectivity uint32 n (0 .. n-1: the
//       Polyvertex cells, one per particle, that ParaView's Xdmf3 reader needs to show points);
//       root attributes time (float64), step (int64), dim (int32), code; each dataset has a string
//       attribute units (SI; "1" for a count or code), /phase and /kind one named codes
//       ("0 fluid, 1 wall, 2 dummy").
//   particles.h5    master file (re-created atomically after every snapshot): group /snapshots
//       with one external link per snapshot, named by the 6-digit index, pointing at
//       "snapshots/snapshot_XXXXXX.h5" object "/"; datasets /times (float64) and /steps (int64).
//       The link targets are relative paths, which HDF5 (1.10+) resolves relative to the folder
//       of particles.h5, so h5py.File('.../particles.h5')['snapshots/000003/pressure'] works from
//       any working directory.
//   particles.xdmf  XDMF 3 temporal collection of Polyvertex grids (re-created atomically),
//       referencing the snapshot files by relative path: open it in ParaView (either Xdmf reader).
//       Units and codes appear there too, as <Information> elements.
//
// Deflated datasets are stored in chunks of whole rows (chunk_rows), each encoded by the process that holds its rows
// (tools/snapshot_chunk.hpp) and written as it is by the first process, in the same order whatever the number of
// processes: the file's bytes do not depend on it. Undeflated ones are contiguous, each process's rows written in turn. (HDF5's own parallel writes, libhdf5-openmpi's collective writes
// of each process's slab, left bytes that depend on the process count where the data are deflated: 1,650 of a 100,000
// value dataset's 24,707 bytes differed between 1 and 4 processes, with HDF5 1.10.8; uncompressed, they were the same
// for any count but not the serial library's.)
//
// Constructing a SnapshotWriter starts a new series: snapshot files left in out_dir/snapshots by
// a previous run (snapshot_*.h5 and stale temporaries) are removed.

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "fluid/communicator.hpp"

namespace slide::tools {

struct SnapshotFields {  // one snapshot; n particles (n = pressure.size())
  int dim = 3;           // 2 or 3
  std::span<const double> position, velocity;  // n*dim each, particle-major (x0 y0 [z0] x1 ...)
  std::span<const double> pressure, number_density, density;  // n each
  std::span<const uint8_t> phase, kind;  // n each; kind: 0 fluid, 1 wall, 2 dummy, 3 body
  std::span<const uint64_t> id;          // n; particle id (stable across snapshots)
};

// What the codes in /kind and /phase stand for, and who wrote the files, stored with every snapshot.
struct SnapshotLegend {
  std::string kind_codes;   // e.g. "0 fluid, 1 wall, 2 dummy"
  std::string phase_codes;  // e.g. "0 water, 1 sediment"
  std::string code;         // the program and its version, e.g. "slide 0.14"
};

// What a snapshot holds and how it is stored (the scene's output.snapshot_* keys). Position, kind and id are always
// written (with the XDMF's connectivity); `fields` are the others, by name. Deflate (with HDF5's byte shuffle, level 1,
// in chunks) is lossless: a snapshot of the Enet & Grilli case (96 k particles) went from 82 to 37 B a particle.
struct SnapshotFormat {
  static const std::vector<std::string>& field_names();  // velocity, pressure, number_density, density, phase
  std::vector<std::string> fields = field_names();
  bool single_precision = false;  // positions, velocities and the scalars as 32-bit floats
  bool deflate = true;
  bool holds(std::string_view field) const;
};

// One process's rows of a snapshot of `total` rows: rows [first_row, first_row + n) of the id order, n =
// fields.pressure.size(); on several processes each chunk's rows on one of them (tools/snapshot_rows.hpp).
struct SnapshotSlab {
  SnapshotFields fields;
  std::size_t first_row = 0;
  std::size_t total = 0;
};

class SnapshotWriter {
 public:
  // A dataset's rows a chunk: 32768, or all of them where fewer.
  static std::size_t chunk_rows(std::size_t total);

  // Creates out_dir and out_dir/snapshots if needed, and starts a new series (below). Throws std::invalid_argument on
  // a field name that is not one of SnapshotFormat::field_names().
  explicit SnapshotWriter(std::filesystem::path out_dir, SnapshotLegend legend = {}, bool new_series = true,
                          SnapshotFormat format = {});

  // One snapshot of the series: when, which step, how many particles.
  struct Entry {
    double time;
    long step;
    size_t n;
  };
  const std::vector<Entry>& entries() const { return entries_; }
  // Continues a series written before (a resumed run; construct with new_series = false): its first entries.size()
  // snapshot files, which must exist, are kept, later ones are removed, and the master and XDMF files are re-created.
  void continue_series(std::vector<Entry> entries);

  // Appends one snapshot: writes its file, then re-creates particles.h5 and particles.xdmf.
  // Throws std::invalid_argument on inconsistent span sizes or dim, std::runtime_error (naming
  // the file) on I/O or HDF5 errors; on error the previously written series stays intact.
  void write(double time, long step, const SnapshotFields& f);
  // The same on several processes, a collective: this (the first) process writes every process's slab, each of the
  // others calls send() with its own.
  void write(double time, long step, const SnapshotSlab& mine, const Communicator& world);
  static void send(const SnapshotSlab& mine, const SnapshotFormat& format, const Communicator& world);

  size_t count() const { return entries_.size(); }

  const std::filesystem::path& out_dir() const { return out_dir_; }
  std::filesystem::path master_path() const { return out_dir_ / "particles.h5"; }
  std::filesystem::path xdmf_path() const { return out_dir_ / "particles.xdmf"; }
  // "snapshots/snapshot_XXXXXX.h5" (relative to out_dir).
  static std::string snapshot_relative_path(size_t index);
  // "XXXXXX": the link name in /snapshots of particles.h5.
  static std::string snapshot_name(size_t index);

 private:
  void write_snapshot_file(const std::filesystem::path& final_path, double time, long step, const SnapshotSlab& mine,
                           const Communicator& world) const;
  void write_master() const;
  void remove_snapshot_files_from(size_t first) const;
  void write_xdmf() const;

  std::filesystem::path out_dir_;
  SnapshotLegend legend_;
  SnapshotFormat format_;
  std::vector<Entry> entries_;
};

}  // namespace slide::tools
