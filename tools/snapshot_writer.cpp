#include "tools/snapshot_writer.hpp"

#include <hdf5.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <exception>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cases/snapshot_field_names.hpp"
#include "fluid/parallel.hpp"
#include "tools/atomic_file.hpp"
#include "tools/markup_escape.hpp"
#include "tools/snapshot_chunk.hpp"

namespace slide::tools {

namespace {

// Owns one HDF5 identifier and closes it with the matching H5?close on scope exit.
class H5Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  H5Handle() = default;
  H5Handle(hid_t id, Closer closer) : id_(id), closer_(closer) {}
  H5Handle(const H5Handle&) = delete;
  H5Handle& operator=(const H5Handle&) = delete;
  H5Handle(H5Handle&& o) noexcept : id_(std::exchange(o.id_, H5I_INVALID_HID)), closer_(o.closer_) {}
  ~H5Handle() {
    if (id_ >= 0) closer_(id_);
  }
  hid_t get() const { return id_; }
  // Closes now; returns the HDF5 status (negative on failure).
  herr_t close() {
    herr_t rc = 0;
    if (id_ >= 0) rc = closer_(std::exchange(id_, H5I_INVALID_HID));
    return rc;
  }

 private:
  hid_t id_ = H5I_INVALID_HID;
  Closer closer_ = nullptr;
};

// HDF5's error stack, walked: every entry as a line for the log, and the system's own error message where an entry
// carries one (the sec2 driver writes "errno = 28, error message = 'No space left on device'" into its description).
struct Hdf5Stack {
  std::string lines;
  std::string cause;
};

herr_t add_stack_entry(unsigned n, const H5E_error2_t* e, void* data) {
  auto& stack = *static_cast<Hdf5Stack*>(data);
  const std::string desc = e->desc ? e->desc : "";
  stack.lines += fmt::format("  #{:03d}: {} line {} in {}(): {}\n", n, e->file_name ? e->file_name : "?", e->line,
                             e->func_name ? e->func_name : "?", desc);
  const std::string marker = "error message = '";
  if (const auto at = desc.find(marker); stack.cause.empty() && at != std::string::npos) {
    const auto start = at + marker.size();
    stack.cause = desc.substr(start, desc.find('\'', start) - start);
  }
  return 0;
}

// The run's folder for a file written in it or in its snapshots/ folder.
std::filesystem::path run_folder_of(const std::filesystem::path& file) {
  const std::filesystem::path dir = file.parent_path();
  return dir.filename() == "snapshots" ? dir.parent_path() : dir;
}

// One line for the terminal: what failed, on which file, and the system's cause where HDF5 reports one. HDF5's own
// stack (a dozen entries for one failed write) goes to hdf5_errors.log in the run's folder, where it still can.
[[noreturn]] void fail(const std::filesystem::path& file, std::string_view what) {
  Hdf5Stack stack;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, add_stack_entry, &stack);
  H5Eclear2(H5E_DEFAULT);
  std::string log_note;
  if (!stack.lines.empty()) {
    const std::filesystem::path log = run_folder_of(file) / "hdf5_errors.log";
    std::ofstream out(log, std::ios::app);
    out << "HDF5 error writing '" << file.string() << "': " << what << "\n" << stack.lines;
    out.flush();
    log_note = fmt::format(" (HDF5's diagnostics: {})", log.string());
    if (!out) {  // the same full disk: no empty log left behind
      std::error_code ec;
      if (std::filesystem::file_size(log, ec) == 0 && !ec) std::filesystem::remove(log, ec);
      log_note = " (HDF5's diagnostics could not be logged)";
    }
  }
  throw std::runtime_error(fmt::format("HDF5 error writing '{}': {}{}{}", file.string(), what,
                                       stack.cause.empty() ? "" : ": " + stack.cause, log_note));
}

H5Handle check(hid_t id, H5Handle::Closer closer, const std::filesystem::path& file,
               std::string_view what) {
  if (id < 0) fail(file, what);
  return H5Handle(id, closer);
}

void check(herr_t rc, const std::filesystem::path& file, std::string_view what) {
  if (rc < 0) fail(file, what);
}

// Once per process, before any other HDF5 call where it can be: no automatic printing of HDF5's error stack (fail()
// reports it), and no library shutdown at exit: HDF5 1.10.8 crashes there (H5F__close_cb, a segfault after the
// run had reported its error) on a file whose close failed, as on a full disk. The run closes its files itself.
void prepare_hdf5() {
  static const bool prepared = [] {
    H5dont_atexit();
    H5open();
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    return true;
  }();
  (void)prepared;
}

// Removes a temporary file unless dismissed (used when a write throws midway).
struct TempGuard {
  std::filesystem::path path;
  bool active = true;
  ~TempGuard() {
    if (active) {
      std::error_code ec;
      std::filesystem::remove(path, ec);
    }
  }
};

// Object creation properties without modification times, so that the same data gives byte-identical files
// (results must be reproducible bit for bit, across runs and thread counts).
H5Handle untimed_properties(hid_t property_class, const std::filesystem::path& path) {
  H5Handle plist = check(H5Pcreate(property_class), H5Pclose, path, "cannot create property list");
  check(H5Pset_obj_track_times(plist.get(), false), path, "cannot disable object times");
  return plist;
}

H5Handle create_file(const std::filesystem::path& path) {
  H5Handle fcpl = untimed_properties(H5P_FILE_CREATE, path);
  return check(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.get(), H5P_DEFAULT), H5Fclose, path,
               "cannot create file");
}

// Rows of a dataset's chunk: 32768 rows of a vector are 786 kB in double precision, under HDF5's default chunk cache of
// 1 MB, and a reader of a few particles inflates no more than that. Deflated: HDF5's byte shuffle and deflate at
// level 1 (the fastest: measured on a 96 k particle snapshot, 0.07 s for 82 -> 37 B a particle).
constexpr size_t kChunkRows = 32768;

// Writes a contiguous dataset `name` of `rows` values (the master file's times and steps).
void write_dataset(hid_t file, const std::filesystem::path& path, const char* name, hid_t file_type, hid_t mem_type,
                   const void* data, size_t rows) {
  const hsize_t dims[1] = {static_cast<hsize_t>(rows)};
  H5Handle space = check(H5Screate_simple(1, dims, nullptr), H5Sclose, path,
                         fmt::format("cannot create dataspace for /{}", name));
  H5Handle dcpl = untimed_properties(H5P_DATASET_CREATE, path);
  H5Handle ds = check(H5Dcreate2(file, name, file_type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT), H5Dclose,
                      path, fmt::format("cannot create dataset /{}", name));
  if (rows > 0) {
    check(H5Dwrite(ds.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), path,
          fmt::format("cannot write dataset /{}", name));
  }
  check(ds.close(), path, fmt::format("cannot close dataset /{}", name));
}

void write_scalar_attribute(hid_t obj, const std::filesystem::path& path, const char* name,
                            hid_t file_type, hid_t mem_type, const void* value) {
  H5Handle space = check(H5Screate(H5S_SCALAR), H5Sclose, path, "cannot create dataspace");
  H5Handle attr = check(H5Acreate2(obj, name, file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT),
                        H5Aclose, path, fmt::format("cannot create attribute {}", name));
  check(H5Awrite(attr.get(), mem_type, value), path,
        fmt::format("cannot write attribute {}", name));
  check(attr.close(), path, fmt::format("cannot close attribute {}", name));
}

// A fixed-length, null-terminated ASCII string attribute (h5py reads it as bytes, ParaView and h5dump as text).
void write_string_attribute(hid_t obj, const std::filesystem::path& path, const char* name, const std::string& value) {
  H5Handle type = check(H5Tcopy(H5T_C_S1), H5Tclose, path, "cannot copy string type");
  check(H5Tset_size(type.get(), std::max<size_t>(1, value.size() + 1)), path, "cannot size string type");
  check(H5Tset_strpad(type.get(), H5T_STR_NULLTERM), path, "cannot pad string type");
  H5Handle space = check(H5Screate(H5S_SCALAR), H5Sclose, path, "cannot create dataspace");
  H5Handle attr = check(H5Acreate2(obj, name, type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose, path,
                        fmt::format("cannot create attribute {}", name));
  check(H5Awrite(attr.get(), type.get(), value.c_str()), path, fmt::format("cannot write attribute {}", name));
  check(attr.close(), path, fmt::format("cannot close attribute {}", name));
}

void write_dataset_attribute(hid_t file, const std::filesystem::path& path, const char* dataset, const char* name,
                             const std::string& value) {
  H5Handle ds = check(H5Dopen2(file, dataset, H5P_DEFAULT), H5Dclose, path, fmt::format("cannot open /{}", dataset));
  write_string_attribute(ds.get(), path, name, value);
}

void check_size(std::string_view name, size_t got, size_t expected) {
  if (got != expected) {
    throw std::invalid_argument(fmt::format(
        "SnapshotFields::{} has {} values, expected {}", name, got, expected));
  }
}

std::string fmt_double(double v) { return fmt::format("{:.17g}", v); }

// Each dataset of a snapshot after /position, as the XDMF names it: its attribute type, number type and unit.
struct FieldSpec {
  const char* name;
  const char* xdmf_type;  // Vector or Scalar
  const char* number_type;
  int precision;
  const char* units;
};
constexpr FieldSpec kPositionSpec{"position", "Vector", "Float", 8, "m"};
constexpr FieldSpec kFieldSpecs[] = {
    {"velocity", "Vector", "Float", 8, "m/s"},    {"pressure", "Scalar", "Float", 8, "Pa"},
    {"number_density", "Scalar", "Float", 8, "1"},  // the MPS sum of kernel weights (seed paper, eq. 2)
    {"density", "Scalar", "Float", 8, "kg/m^3"},  {"phase", "Scalar", "UChar", 1, "1"},
    {"kind", "Scalar", "UChar", 1, "1"},          {"id", "Scalar", "UInt", 4, "1"},
};

// How a snapshot dataset's values are stored (little-endian, as this machine holds them).
enum class Stored { f64, f32, u8, u32, u64 };
static_assert(std::endian::native == std::endian::little, "snapshot chunks are written as this machine holds them");

size_t stored_bytes(Stored t) {
  switch (t) {
    case Stored::f64: case Stored::u64: return 8;
    case Stored::f32: case Stored::u32: return 4;
    case Stored::u8: return 1;
  }
  return 0;
}

hid_t file_type(Stored t) {
  switch (t) {
    case Stored::f64: return H5T_IEEE_F64LE;
    case Stored::f32: return H5T_IEEE_F32LE;
    case Stored::u8: return H5T_STD_U8LE;
    case Stored::u32: return H5T_STD_U32LE;
    case Stored::u64: return H5T_STD_U64LE;
  }
  return H5I_INVALID_HID;
}

// A dataset of a snapshot: its name, how its values are stored, its columns (0: one value a row), and its rows as the
// file stores them: fill(begin, count, out) writes a slab's rows [begin, begin + count) to out.
struct SnapshotDataset {
  const char* name;
  Stored stored;
  size_t cols;
  std::function<void(size_t, size_t, unsigned char*)> fill;
  size_t row_bytes() const { return stored_bytes(stored) * std::max<size_t>(cols, 1); }
};

// A slab's datasets, in the file's order: position, the format's fields, kind, id, and the connectivity (the rows'
// numbers, 0 .. total - 1: the Polyvertex cells ParaView's Xdmf3 reader needs to show points). Reals in the format's
// precision; a vector padded to three components (XDMF's XYZ).
std::vector<SnapshotDataset> snapshot_datasets(const SnapshotSlab& slab, const SnapshotFormat& format) {
  const SnapshotFields& f = slab.fields;
  const size_t d = static_cast<size_t>(f.dim);
  const Stored real = format.single_precision ? Stored::f32 : Stored::f64;
  const auto reals = [real, d](std::span<const double> src, size_t cols) {
    return [src, cols, real, d](size_t begin, size_t count, unsigned char* out) {
      const size_t width = cols == 0 ? 1 : cols, given = cols == 0 ? 1 : d;
      for (size_t i = begin; i < begin + count; ++i)
        for (size_t k = 0; k < width; ++k) {
          const double v = k < given ? src[i * given + k] : 0.0;
          if (real == Stored::f64) {
            std::memcpy(out, &v, 8);
            out += 8;
          } else {
            const float narrow = static_cast<float>(v);
            std::memcpy(out, &narrow, 4);
            out += 4;
          }
        }
    };
  };
  const auto copied = [](const auto* src, size_t bytes) {
    return [src, bytes](size_t begin, size_t count, unsigned char* out) {
      std::memcpy(out, reinterpret_cast<const unsigned char*>(src) + begin * bytes, count * bytes);
    };
  };
  std::vector<SnapshotDataset> sets{{"position", real, 3, reals(f.position, 3)}};
  if (format.holds("velocity")) sets.push_back({"velocity", real, 3, reals(f.velocity, 3)});
  for (const auto& [name, values] : {std::pair{"pressure", f.pressure}, std::pair{"number_density", f.number_density},
                                     std::pair{"density", f.density}})
    if (format.holds(name)) sets.push_back({name, real, 0, reals(values, 0)});
  if (format.holds("phase")) sets.push_back({"phase", Stored::u8, 0, copied(f.phase.data(), 1)});
  sets.push_back({"kind", Stored::u8, 0, copied(f.kind.data(), 1)});
  sets.push_back({"id", Stored::u64, 0, copied(f.id.data(), 8)});
  const size_t first_row = slab.first_row;
  sets.push_back({"connectivity", Stored::u32, 0, [first_row](size_t begin, size_t count, unsigned char* out) {
                    for (size_t i = begin; i < begin + count; ++i, out += 4) {
                      const auto row = static_cast<uint32_t>(first_row + i);
                      std::memcpy(out, &row, 4);
                    }
                  }});
  return sets;
}

// A slab's rows as the datasets need them: sizes that agree, and each chunk's rows within it.
void check_slab(const SnapshotSlab& slab) {
  const SnapshotFields& f = slab.fields;
  if (f.dim != 2 && f.dim != 3) {
    throw std::invalid_argument(fmt::format("SnapshotFields::dim must be 2 or 3, got {}", f.dim));
  }
  const size_t n = f.pressure.size();
  const size_t d = static_cast<size_t>(f.dim);
  check_size("position", f.position.size(), n * d);
  check_size("velocity", f.velocity.size(), n * d);
  check_size("number_density", f.number_density.size(), n);
  check_size("density", f.density.size(), n);
  check_size("phase", f.phase.size(), n);
  check_size("kind", f.kind.size(), n);
  check_size("id", f.id.size(), n);
  const size_t chunk = SnapshotWriter::chunk_rows(slab.total);
  if (n > 0 && (slab.first_row % chunk != 0 || slab.first_row + n > slab.total ||
                (n % chunk != 0 && slab.first_row + n != slab.total)))
    throw std::invalid_argument(fmt::format("a snapshot slab of rows {} to {} of {} does not hold whole chunks of {}",
                                            slab.first_row, slab.first_row + n, slab.total, chunk));
}

// One process's rows of a dataset as it sends them to the first, one buffer: the first row, the rows, the number of
// chunks and each one's size (deflated: encoded, tools/snapshot_chunk.hpp; none without), then their bytes (or the
// rows' own, undeflated). Read in place (PieceView): the first process holds one copy of a process's piece.
constexpr size_t kPieceHeader = 3 * 8;

struct PieceView {
  uint64_t first_row = 0, rows = 0, chunks = 0;
  const unsigned char* sizes = nullptr;  // chunks x uint64
  const unsigned char* bytes = nullptr;
  explicit PieceView(const std::vector<unsigned char>& piece) {
    if (piece.size() < kPieceHeader) return;
    std::memcpy(&first_row, piece.data(), 8);
    std::memcpy(&rows, piece.data() + 8, 8);
    std::memcpy(&chunks, piece.data() + 16, 8);
    sizes = piece.data() + kPieceHeader;
    bytes = sizes + 8 * chunks;
  }
  uint64_t size(size_t k) const {
    uint64_t v = 0;
    std::memcpy(&v, sizes + 8 * k, 8);
    return v;
  }
};

std::vector<unsigned char> piece_with_header(uint64_t first_row, uint64_t rows, const std::vector<uint64_t>& sizes,
                                             size_t data_bytes) {
  std::vector<unsigned char> piece(kPieceHeader + 8 * sizes.size() + data_bytes);
  const uint64_t chunks = sizes.size();
  std::memcpy(piece.data(), &first_row, 8);
  std::memcpy(piece.data() + 8, &rows, 8);
  std::memcpy(piece.data() + 16, &chunks, 8);
  if (chunks) std::memcpy(piece.data() + kPieceHeader, sizes.data(), 8 * chunks);
  return piece;
}

// The slab's chunks [first, first + count) of a dataset, encoded, each by one thread (the bytes do not depend on how
// many).
std::vector<std::vector<unsigned char>> encoded_chunks(const SnapshotDataset& dataset, const SnapshotSlab& slab,
                                                       size_t first, size_t count) {
  const size_t n = slab.fields.pressure.size(), chunk = SnapshotWriter::chunk_rows(slab.total);
  std::vector<std::vector<unsigned char>> each(count);
  std::vector<std::exception_ptr> failed(count);
  parallel_for_blocks(count, count * chunk, [&](size_t k) {
    try {  // (an exception must not leave a thread)
      const size_t begin = (first + k) * chunk, rows_here = std::min(chunk, n - begin);
      std::vector<unsigned char> rows(rows_here * dataset.row_bytes());
      dataset.fill(begin, rows_here, rows.data());
      each[k] = encoded_chunk(rows, chunk * dataset.row_bytes(), stored_bytes(dataset.stored), true);
    } catch (...) {
      failed[k] = std::current_exception();
    }
  });
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
  return each;
}

// The slab's rows of a dataset as a piece to send: deflated, its chunks encoded; undeflated, the rows as they are.
std::vector<unsigned char> dataset_piece(const SnapshotDataset& dataset, const SnapshotSlab& slab, bool deflate) {
  const size_t n = slab.fields.pressure.size(), chunk = SnapshotWriter::chunk_rows(slab.total);
  if (!deflate) {
    std::vector<unsigned char> piece = piece_with_header(slab.first_row, n, {}, n * dataset.row_bytes());
    if (n > 0) dataset.fill(0, n, piece.data() + kPieceHeader);
    return piece;
  }
  std::vector<std::vector<unsigned char>> each = encoded_chunks(dataset, slab, 0, (n + chunk - 1) / chunk);
  std::vector<uint64_t> sizes;
  size_t bytes = 0;
  for (const auto& e : each) {
    sizes.push_back(e.size());
    bytes += e.size();
  }
  std::vector<unsigned char> piece = piece_with_header(slab.first_row, n, sizes, bytes);
  unsigned char* at = piece.data() + kPieceHeader + 8 * each.size();
  for (auto& e : each) {
    if (!e.empty()) std::memcpy(at, e.data(), e.size());
    at += e.size();
    std::vector<unsigned char>().swap(e);
  }
  return piece;
}

// Creates a dataset of `total` rows, deflated in chunks (with the byte shuffle) or contiguous, and writes every
// process's piece into it, the first's, then each other process's in turn (a collective each: SnapshotWriter::send is
// the others' side), so that the first holds no more than one process's piece of one dataset at a time. Deflated, the
// chunks go in as they are (H5Dwrite_chunk); contiguous, the rows (H5Dwrite of their rows).
void write_dataset_of_processes(hid_t file, const std::filesystem::path& path, const SnapshotDataset& dataset,
                                const SnapshotSlab& mine, bool deflate, const Communicator& world) {
  const size_t total = mine.total, chunk = SnapshotWriter::chunk_rows(total);
  const int rank = dataset.cols == 0 ? 1 : 2;
  const hsize_t dims[2] = {static_cast<hsize_t>(total), static_cast<hsize_t>(dataset.cols)};
  H5Handle space = check(H5Screate_simple(rank, dims, nullptr), H5Sclose, path,
                         fmt::format("cannot create dataspace for /{}", dataset.name));
  H5Handle dcpl = untimed_properties(H5P_DATASET_CREATE, path);
  if (deflate && total > 0) {
    const hsize_t chunk_dims[2] = {static_cast<hsize_t>(chunk), static_cast<hsize_t>(dataset.cols)};
    check(H5Pset_chunk(dcpl.get(), rank, chunk_dims), path, fmt::format("cannot chunk /{}", dataset.name));
    check(H5Pset_shuffle(dcpl.get()), path, fmt::format("cannot shuffle /{}", dataset.name));
    check(H5Pset_deflate(dcpl.get(), 1), path, fmt::format("cannot deflate /{} (HDF5 without zlib?)", dataset.name));
  }
  const hid_t type = file_type(dataset.stored);
  H5Handle ds = check(H5Dcreate2(file, dataset.name, type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                      H5Dclose, path, fmt::format("cannot create dataset /{}", dataset.name));
  const auto write = [&](const std::vector<unsigned char>& piece) {
    const PieceView p(piece);
    if (p.rows == 0) return;
    if (!deflate) {  // the rows [first_row, first_row + rows), held as the file stores them
      const hsize_t start[2] = {p.first_row, 0}, count[2] = {p.rows, dataset.cols};
      H5Handle rows = check(H5Screate_simple(rank, count, nullptr), H5Sclose, path, "cannot create dataspace");
      H5Handle in_file = check(H5Dget_space(ds.get()), H5Sclose, path, "cannot get dataspace");
      check(H5Sselect_hyperslab(in_file.get(), H5S_SELECT_SET, start, nullptr, count, nullptr), path,
            fmt::format("cannot select rows of /{}", dataset.name));
      check(H5Dwrite(ds.get(), type, rows.get(), in_file.get(), H5P_DEFAULT, p.bytes), path,
            fmt::format("cannot write dataset /{}", dataset.name));
      return;
    }
    const unsigned char* at = p.bytes;
    for (size_t k = 0; k < p.chunks; ++k) {
      const hsize_t offset[2] = {static_cast<hsize_t>(p.first_row + k * chunk), 0};
      check(H5Dwrite_chunk(ds.get(), H5P_DEFAULT, 0, offset, p.size(k), at), path,
            fmt::format("cannot write dataset /{}", dataset.name));
      at += p.size(k);
    }
  };
  // This process's own rows: deflated, as many chunks at a time as there are threads, each written once encoded (the
  // memory of a few chunks, as HDF5's own filter held).
  const size_t n = mine.fields.pressure.size();
  if (deflate && n > 0) {
    const size_t chunks = (n + chunk - 1) / chunk, batch = static_cast<size_t>(std::max(1, thread_count()));
    for (size_t c = 0; c < chunks; c += batch) {
      const auto each = encoded_chunks(dataset, mine, c, std::min(batch, chunks - c));
      for (size_t k = 0; k < each.size(); ++k) {
        const hsize_t offset[2] = {static_cast<hsize_t>(mine.first_row + (c + k) * chunk), 0};
        check(H5Dwrite_chunk(ds.get(), H5P_DEFAULT, 0, offset, each[k].size(), each[k].data()), path,
              fmt::format("cannot write dataset /{}", dataset.name));
      }
    }
  } else if (total > 0) {
    write(dataset_piece(dataset, mine, deflate));
  }
  if (total > 0)
    for (int r = 1; r < world.size(); ++r) write(gather_bytes_on_first(world, {}));
  check(ds.close(), path, fmt::format("cannot close dataset /{}", dataset.name));
}

}  // namespace

const std::vector<std::string>& SnapshotFormat::field_names() { return cases::snapshot_field_names(); }

bool SnapshotFormat::holds(std::string_view field) const {
  return field == "position" || field == "kind" || field == "id" ||
         std::find(fields.begin(), fields.end(), field) != fields.end();
}

size_t SnapshotWriter::chunk_rows(size_t total) { return std::max<size_t>(1, std::min(total, kChunkRows)); }

std::string SnapshotWriter::snapshot_name(size_t index) { return fmt::format("{:06d}", index); }

std::string SnapshotWriter::snapshot_relative_path(size_t index) {
  return fmt::format("snapshots/snapshot_{:06d}.h5", index);
}

SnapshotWriter::SnapshotWriter(std::filesystem::path out_dir, SnapshotLegend legend, bool new_series,
                               SnapshotFormat format)
    : out_dir_(std::move(out_dir)), legend_(std::move(legend)), format_(std::move(format)) {
  const auto& names = SnapshotFormat::field_names();
  for (const std::string& field : format_.fields)
    if (std::find(names.begin(), names.end(), field) == names.end())
      throw std::invalid_argument(fmt::format("snapshot field '{}' is not one of {}", field, fmt::join(names, ", ")));
  std::error_code ec;
  std::filesystem::create_directories(out_dir_ / "snapshots", ec);
  if (ec) {
    throw std::runtime_error(fmt::format("cannot create output folder '{}': {}",
                                         (out_dir_ / "snapshots").string(), ec.message()));
  }
  // A new series: drop snapshot files of an earlier run so the folder matches the master file.
  if (new_series) remove_snapshot_files_from(0);
  prepare_hdf5();
}

void SnapshotWriter::remove_snapshot_files_from(size_t first) const {
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(out_dir_ / "snapshots", ec)) {
    const std::string name = e.path().filename().string();
    if (!name.starts_with("snapshot_")) continue;
    const bool temporary = name.find(".h5.tmp.") != std::string::npos;
    const std::string digits = name.substr(9, 6);
    const bool numbered = name.ends_with(".h5") && name.size() == std::string("snapshot_000000.h5").size() &&
                          digits.find_first_not_of("0123456789") == std::string::npos;
    const bool later = numbered && std::stoul(digits) >= first;
    if (temporary || later) {
      std::error_code rm_ec;
      std::filesystem::remove(e.path(), rm_ec);
    }
  }
}

void SnapshotWriter::continue_series(std::vector<Entry> entries) {
  for (size_t i = 0; i < entries.size(); ++i)
    if (!std::filesystem::exists(out_dir_ / snapshot_relative_path(i)))
      throw std::runtime_error(fmt::format("snapshot file '{}' of the checkpoint's series is missing",
                                           (out_dir_ / snapshot_relative_path(i)).string()));
  remove_snapshot_files_from(entries.size());
  entries_ = std::move(entries);
  write_master();
  write_xdmf();
}

void SnapshotWriter::write(double time, long step, const SnapshotFields& f) {
  write(time, step, SnapshotSlab{f, 0, f.pressure.size()}, SerialCommunicator());
}

void SnapshotWriter::write(double time, long step, const SnapshotSlab& mine, const Communicator& world) {
  check_slab(mine);
  const size_t index = entries_.size();
  write_snapshot_file(out_dir_ / snapshot_relative_path(index), time, step, mine, world);
  entries_.push_back(Entry{time, step, mine.total});
  try {
    write_master();
    write_xdmf();
  } catch (...) {
    // The series stays as it was: the master file is written again without this snapshot where it still can be.
    entries_.pop_back();
    try {
      write_master();
    } catch (const std::exception&) {
    }
    throw;
  }
}

void SnapshotWriter::send(const SnapshotSlab& mine, const SnapshotFormat& format, const Communicator& world) {
  check_slab(mine);
  const std::vector<unsigned char> none;
  for (const SnapshotDataset& dataset : snapshot_datasets(mine, format)) {
    if (mine.total == 0) continue;
    const std::vector<unsigned char> piece = dataset_piece(dataset, mine, format.deflate);
    for (int r = 1; r < world.size(); ++r) gather_bytes_on_first(world, r == world.rank() ? piece : none);
  }
}

void SnapshotWriter::write_snapshot_file(const std::filesystem::path& final_path, double time, long step,
                                         const SnapshotSlab& mine, const Communicator& world) const {
  const std::filesystem::path tmp = temporary_path_for(final_path);
  TempGuard guard{tmp};
  {
    H5Handle file = create_file(tmp);
    const hid_t fid = file.get();
    for (const SnapshotDataset& dataset : snapshot_datasets(mine, format_))
      write_dataset_of_processes(fid, tmp, dataset, mine, format_.deflate, world);

    write_dataset_attribute(fid, tmp, kPositionSpec.name, "units", kPositionSpec.units);
    for (const FieldSpec& spec : kFieldSpecs)
      if (format_.holds(spec.name)) write_dataset_attribute(fid, tmp, spec.name, "units", spec.units);
    if (!legend_.kind_codes.empty()) write_dataset_attribute(fid, tmp, "kind", "codes", legend_.kind_codes);
    if (!legend_.phase_codes.empty() && format_.holds("phase"))
      write_dataset_attribute(fid, tmp, "phase", "codes", legend_.phase_codes);
    if (!legend_.code.empty()) write_string_attribute(fid, tmp, "code", legend_.code);

    const int64_t step64 = step;
    const int32_t dim32 = mine.fields.dim;
    write_scalar_attribute(fid, tmp, "time", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &time);
    write_scalar_attribute(fid, tmp, "step", H5T_STD_I64LE, H5T_NATIVE_INT64, &step64);
    write_scalar_attribute(fid, tmp, "dim", H5T_STD_I32LE, H5T_NATIVE_INT32, &dim32);
    check(file.close(), tmp, "cannot close file");
  }
  guard.active = false;  // commit_temporary_file removes tmp itself on failure
  commit_temporary_file(tmp, final_path);
}

void SnapshotWriter::write_master() const {
  const std::filesystem::path final_path = master_path();
  const std::filesystem::path tmp = temporary_path_for(final_path);
  TempGuard guard{tmp};
  {
    H5Handle file = create_file(tmp);
    const hid_t fid = file.get();
    H5Handle gcpl = untimed_properties(H5P_GROUP_CREATE, tmp);
    H5Handle group = check(H5Gcreate2(fid, "snapshots", H5P_DEFAULT, gcpl.get(), H5P_DEFAULT),
                           H5Gclose, tmp, "cannot create group /snapshots");
    std::vector<double> times;
    std::vector<int64_t> steps;
    times.reserve(entries_.size());
    steps.reserve(entries_.size());
    for (size_t i = 0; i < entries_.size(); ++i) {
      const std::string target = snapshot_relative_path(i);
      const std::string name = snapshot_name(i);
      check(H5Lcreate_external(target.c_str(), "/", group.get(), name.c_str(), H5P_DEFAULT,
                               H5P_DEFAULT),
            tmp, fmt::format("cannot create external link /snapshots/{}", name));
      times.push_back(entries_[i].time);
      steps.push_back(entries_[i].step);
    }
    check(group.close(), tmp, "cannot close group /snapshots");
    write_dataset(fid, tmp, "times", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, times.data(),
                  times.size());
    write_dataset(fid, tmp, "steps", H5T_STD_I64LE, H5T_NATIVE_INT64, steps.data(),
                  steps.size());
    check(file.close(), tmp, "cannot close file");
  }
  guard.active = false;
  commit_temporary_file(tmp, final_path);
}

void SnapshotWriter::write_xdmf() const {
  std::string x;
  x.reserve(1024 + entries_.size() * 2048);
  x += "<?xml version=\"1.0\" ?>\n";
  x += "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n";
  x += "<Xdmf Version=\"3.0\" xmlns:xi=\"http://www.w3.org/2001/XInclude\">\n";
  x += "  <Domain>\n";
  x += "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  auto out = std::back_inserter(x);
  const int real_precision = format_.single_precision ? 4 : 8;
  for (size_t i = 0; i < entries_.size(); ++i) {
    const Entry& e = entries_[i];
    const std::string file = snapshot_relative_path(i);
    fmt::format_to(out, "      <Grid Name=\"snapshot_{}\" GridType=\"Uniform\">\n",
                   snapshot_name(i));
    fmt::format_to(out, "        <Time Value=\"{}\"/>\n", fmt_double(e.time));
    fmt::format_to(out,
                   "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"{0}\" NodesPerElement=\"1\">\n"
                   "          <DataItem Dimensions=\"{0}\" NumberType=\"UInt\" Precision=\"4\" "
                   "Format=\"HDF\">{1}:/connectivity</DataItem>\n"
                   "        </Topology>\n",
                   e.n, file);
    fmt::format_to(out,
                   "        <Geometry GeometryType=\"XYZ\">\n"
                   "          <Information Name=\"units\" Value=\"{2}\"/>\n"
                   "          <DataItem Dimensions=\"{0} 3\" NumberType=\"Float\" Precision=\"{3}\" "
                   "Format=\"HDF\">{1}:/position</DataItem>\n"
                   "        </Geometry>\n",
                   e.n, file, kPositionSpec.units, real_precision);
    for (const FieldSpec& spec : kFieldSpecs) {
      if (!format_.holds(spec.name)) continue;
      const int precision = std::string_view(spec.number_type) == "Float" ? real_precision : spec.precision;
      const std::string dims =
          std::string_view(spec.xdmf_type) == "Vector" ? fmt::format("{} 3", e.n) : fmt::format("{}", e.n);
      fmt::format_to(out, "        <Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"Node\">\n", spec.name,
                     spec.xdmf_type);
      fmt::format_to(out, "          <Information Name=\"units\" Value=\"{}\"/>\n", spec.units);
      const std::string& codes = std::string_view(spec.name) == "kind"    ? legend_.kind_codes
                                 : std::string_view(spec.name) == "phase" ? legend_.phase_codes
                                                                          : std::string();
      if (!codes.empty())
        fmt::format_to(out, "          <Information Name=\"codes\" Value=\"{}\"/>\n", markup_escaped(codes));
      fmt::format_to(out,
                     "          <DataItem Dimensions=\"{}\" NumberType=\"{}\" Precision=\"{}\" "
                     "Format=\"HDF\">{}:/{}</DataItem>\n"
                     "        </Attribute>\n",
                     dims, spec.number_type, precision, file, spec.name);
    }
    x += "      </Grid>\n";
  }
  x += "    </Grid>\n";
  x += "  </Domain>\n";
  x += "</Xdmf>\n";
  write_file_atomically(xdmf_path(), x);
}

}  // namespace slide::tools
