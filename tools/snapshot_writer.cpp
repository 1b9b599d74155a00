#include "tools/snapshot_writer.hpp"

#include <hdf5.h>

#include <algorithm>
#include <fstream>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "cases/snapshot_field_names.hpp"
#include "tools/atomic_file.hpp"
#include "tools/markup_escape.hpp"

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

// Rows of a deflated dataset's chunk: 32768 rows of a vector are 786 kB in double precision, under HDF5's default
// chunk cache of 1 MB, and a reader of a few particles inflates no more than that.
constexpr size_t kChunkRows = 32768;

// Writes a dataset `name` of rank 1 (cols == 0) or 2 (rows x cols): contiguous, or in chunks with HDF5's byte shuffle
// and deflate at level 1 (the fastest: measured on a 96 k particle snapshot, 0.07 s for 82 -> 37 B a particle).
void write_dataset(hid_t file, const std::filesystem::path& path, const char* name,
                   hid_t file_type, hid_t mem_type, const void* data, size_t rows,
                   size_t cols = 0, bool deflate = false) {
  hsize_t dims[2] = {static_cast<hsize_t>(rows), static_cast<hsize_t>(cols)};
  const int rank = cols == 0 ? 1 : 2;
  H5Handle space = check(H5Screate_simple(rank, dims, nullptr), H5Sclose, path,
                         fmt::format("cannot create dataspace for /{}", name));
  H5Handle dcpl = untimed_properties(H5P_DATASET_CREATE, path);
  if (deflate && rows > 0) {
    const hsize_t chunk[2] = {static_cast<hsize_t>(std::min(rows, kChunkRows)), static_cast<hsize_t>(cols)};
    check(H5Pset_chunk(dcpl.get(), rank, chunk), path, fmt::format("cannot chunk /{}", name));
    check(H5Pset_shuffle(dcpl.get()), path, fmt::format("cannot shuffle /{}", name));
    check(H5Pset_deflate(dcpl.get(), 1), path, fmt::format("cannot deflate /{} (HDF5 without zlib?)", name));
  }
  H5Handle ds = check(H5Dcreate2(file, name, file_type, space.get(), H5P_DEFAULT, dcpl.get(),
                                 H5P_DEFAULT),
                      H5Dclose, path, fmt::format("cannot create dataset /{}", name));
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

}  // namespace

const std::vector<std::string>& SnapshotFormat::field_names() { return cases::snapshot_field_names(); }

bool SnapshotFormat::holds(std::string_view field) const {
  return field == "position" || field == "kind" || field == "id" ||
         std::find(fields.begin(), fields.end(), field) != fields.end();
}

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

  const size_t index = entries_.size();
  write_snapshot_file(out_dir_ / snapshot_relative_path(index), time, step, f);
  entries_.push_back(Entry{time, step, n});
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

void SnapshotWriter::write_snapshot_file(const std::filesystem::path& final_path, double time,
                                         long step, const SnapshotFields& f) const {
  const size_t n = f.pressure.size();
  const size_t d = static_cast<size_t>(f.dim);
  const std::filesystem::path tmp = temporary_path_for(final_path);
  TempGuard guard{tmp};
  {
    H5Handle file = create_file(tmp);
    const hid_t fid = file.get();

    const bool single = format_.single_precision, deflate = format_.deflate;
    // Positions, velocities and scalars in the format's precision; a vector padded to three components (XDMF's XYZ).
    auto write_real = [&](const char* name, std::span<const double> src, size_t cols) {
      if (!single && cols == 0) {  // as it is
        write_dataset(fid, tmp, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, src.data(), n, 0, deflate);
        return;
      }
      const size_t width = cols == 0 ? 1 : cols, given = cols == 0 ? 1 : d;
      std::vector<double> values(n * width, 0.0);
      for (size_t i = 0; i < n; ++i)
        for (size_t k = 0; k < given; ++k) values[i * width + k] = src[i * given + k];
      if (!single) {
        write_dataset(fid, tmp, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, values.data(), n, cols, deflate);
        return;
      }
      const std::vector<float> narrow(values.begin(), values.end());
      write_dataset(fid, tmp, name, H5T_IEEE_F32LE, H5T_NATIVE_FLOAT, narrow.data(), n, cols, deflate);
    };
    write_real("position", f.position, 3);
    if (format_.holds("velocity")) write_real("velocity", f.velocity, 3);
    if (format_.holds("pressure")) write_real("pressure", f.pressure, 0);
    if (format_.holds("number_density")) write_real("number_density", f.number_density, 0);
    if (format_.holds("density")) write_real("density", f.density, 0);
    if (format_.holds("phase"))
      write_dataset(fid, tmp, "phase", H5T_STD_U8LE, H5T_NATIVE_UINT8, f.phase.data(), n, 0, deflate);
    write_dataset(fid, tmp, "kind", H5T_STD_U8LE, H5T_NATIVE_UINT8, f.kind.data(), n, 0, deflate);
    write_dataset(fid, tmp, "id", H5T_STD_U64LE, H5T_NATIVE_UINT64, f.id.data(), n, 0, deflate);
    std::vector<uint32_t> connectivity(n);
    for (size_t i = 0; i < n; ++i) connectivity[i] = static_cast<uint32_t>(i);
    write_dataset(fid, tmp, "connectivity", H5T_STD_U32LE, H5T_NATIVE_UINT32, connectivity.data(), n, 0, deflate);

    write_dataset_attribute(fid, tmp, kPositionSpec.name, "units", kPositionSpec.units);
    for (const FieldSpec& spec : kFieldSpecs)
      if (format_.holds(spec.name)) write_dataset_attribute(fid, tmp, spec.name, "units", spec.units);
    if (!legend_.kind_codes.empty()) write_dataset_attribute(fid, tmp, "kind", "codes", legend_.kind_codes);
    if (!legend_.phase_codes.empty() && format_.holds("phase"))
      write_dataset_attribute(fid, tmp, "phase", "codes", legend_.phase_codes);
    if (!legend_.code.empty()) write_string_attribute(fid, tmp, "code", legend_.code);

    const int64_t step64 = step;
    const int32_t dim32 = f.dim;
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
