#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "tools/atomic_file.hpp"
#include "tools/snapshot_writer.hpp"

namespace fs = std::filesystem;
using slide::tools::CsvWriter;
using slide::tools::SnapshotFields;
using slide::tools::SnapshotWriter;
using slide::tools::write_file_atomically;

namespace {

// Unique temporary folder removed at scope exit.
struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& tag) {
    std::random_device rd;
    path = fs::temp_directory_path() /
           ("slide_test_" + tag + "_" + std::to_string(::getpid()) + "_" + std::to_string(rd()));
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

size_t count_occurrences(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t pos = s.find(what); pos != std::string::npos; pos = s.find(what, pos + 1)) ++n;
  return n;
}

bool any_tmp_files(const fs::path& dir) {
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.path().filename().string().find(".tmp") != std::string::npos) return true;
  return false;
}

// Test data for one snapshot.
struct Snap {
  int dim;
  std::vector<double> position, velocity, pressure, number_density, density;
  std::vector<uint8_t> phase, kind;
  std::vector<uint64_t> id;
  SnapshotFields fields() const {
    return SnapshotFields{dim, position, velocity, pressure, number_density, density,
                          phase, kind, id};
  }
};

Snap make_snap(int dim, size_t n, double seed) {
  Snap s;
  s.dim = dim;
  for (size_t i = 0; i < n; ++i) {
    for (int k = 0; k < dim; ++k) {
      s.position.push_back(seed + 0.1 * static_cast<double>(i) + 1.0 / (3.0 + k));
      s.velocity.push_back(-seed * 1e-7 + static_cast<double>(k) / 7.0 + static_cast<double>(i));
    }
    s.pressure.push_back(seed * 1000.0 / 3.0 + static_cast<double>(i) * 0.1);
    s.number_density.push_back(6.0 + seed / 11.0 + static_cast<double>(i));
    s.density.push_back(1000.0 + std::sqrt(2.0) * static_cast<double>(i) + seed);
    s.phase.push_back(static_cast<uint8_t>(i % 2));
    s.kind.push_back(static_cast<uint8_t>(i % 4));
    s.id.push_back(static_cast<uint64_t>(100 + i * 3));
  }
  return s;
}

struct H5Closer {
  hid_t id;
  herr_t (*close)(hid_t);
  ~H5Closer() {
    if (id >= 0) close(id);
  }
};

template <class T>
std::vector<T> read_dataset(hid_t file, const std::string& name, hid_t mem_type,
                            std::vector<hsize_t>* dims_out = nullptr) {
  H5Closer ds{H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose};
  EXPECT_GE(ds.id, 0) << name;
  if (ds.id < 0) return {};
  H5Closer space{H5Dget_space(ds.id), H5Sclose};
  const int rank = H5Sget_simple_extent_ndims(space.id);
  std::vector<hsize_t> dims(static_cast<size_t>(rank));
  H5Sget_simple_extent_dims(space.id, dims.data(), nullptr);
  size_t total = 1;
  for (hsize_t d : dims) total *= static_cast<size_t>(d);
  std::vector<T> out(total);
  EXPECT_GE(H5Dread(ds.id, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), 0) << name;
  if (dims_out) *dims_out = dims;
  return out;
}

template <class T>
T read_root_attribute(hid_t file, const std::string& path, const char* name, hid_t mem_type) {
  T value{};
  H5Closer attr{H5Aopen_by_name(file, path.c_str(), name, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
  EXPECT_GE(attr.id, 0) << path << " " << name;
  if (attr.id >= 0) {
    EXPECT_GE(H5Aread(attr.id, mem_type, &value), 0);
  }
  return value;
}

std::string read_string_attribute(hid_t file, const std::string& object, const char* name) {
  H5Closer attr{H5Aopen_by_name(file, object.c_str(), name, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
  EXPECT_GE(attr.id, 0) << object << " " << name;
  if (attr.id < 0) return {};
  H5Closer type{H5Aget_type(attr.id), H5Tclose};
  std::string value(H5Tget_size(type.id), '\0');
  EXPECT_GE(H5Aread(attr.id, type.id, value.data()), 0);
  return value.substr(0, value.find('\0'));
}

void expect_snapshot(hid_t master, size_t index, const Snap& s, double time, long step) {
  const std::string base = "snapshots/" + SnapshotWriter::snapshot_name(index);
  const size_t n = s.pressure.size();
  std::vector<hsize_t> dims;
  auto pos = read_dataset<double>(master, base + "/position", H5T_NATIVE_DOUBLE, &dims);
  ASSERT_EQ(dims, (std::vector<hsize_t>{n, 3}));
  auto vel = read_dataset<double>(master, base + "/velocity", H5T_NATIVE_DOUBLE, &dims);
  ASSERT_EQ(dims, (std::vector<hsize_t>{n, 3}));
  for (size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) {
      const double ep = k < s.dim ? s.position[i * s.dim + k] : 0.0;
      const double ev = k < s.dim ? s.velocity[i * s.dim + k] : 0.0;
      EXPECT_EQ(pos[i * 3 + k], ep);
      EXPECT_EQ(vel[i * 3 + k], ev);
    }
  }
  EXPECT_EQ(read_dataset<double>(master, base + "/pressure", H5T_NATIVE_DOUBLE), s.pressure);
  EXPECT_EQ(read_dataset<double>(master, base + "/number_density", H5T_NATIVE_DOUBLE),
            s.number_density);
  EXPECT_EQ(read_dataset<double>(master, base + "/density", H5T_NATIVE_DOUBLE), s.density);
  EXPECT_EQ(read_dataset<uint8_t>(master, base + "/phase", H5T_NATIVE_UINT8), s.phase);
  EXPECT_EQ(read_dataset<uint8_t>(master, base + "/kind", H5T_NATIVE_UINT8), s.kind);
  EXPECT_EQ(read_dataset<uint64_t>(master, base + "/id", H5T_NATIVE_UINT64), s.id);
  std::vector<uint32_t> cells(n);
  for (size_t i = 0; i < n; ++i) cells[i] = static_cast<uint32_t>(i);
  EXPECT_EQ(read_dataset<uint32_t>(master, base + "/connectivity", H5T_NATIVE_UINT32), cells);
  EXPECT_EQ(read_root_attribute<double>(master, base, "time", H5T_NATIVE_DOUBLE), time);
  EXPECT_EQ(read_root_attribute<int64_t>(master, base, "step", H5T_NATIVE_INT64), step);
  EXPECT_EQ(read_root_attribute<int32_t>(master, base, "dim", H5T_NATIVE_INT32), s.dim);
}

bool python_has_h5py() {
  return std::system("/usr/bin/python3 -c 'import h5py' >/dev/null 2>&1") == 0;
}

std::string run_capture(const std::string& cmd) {
  std::string out;
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return out;
  std::array<char, 4096> buf;
  size_t got;
  while ((got = std::fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), got);
  const int rc = ::pclose(p);
  EXPECT_EQ(rc, 0) << cmd << "\n" << out;
  return out;
}

}  // namespace


// The filters of a dataset: (count, whether shuffle and deflate are among them).
std::pair<int, bool> dataset_filters(hid_t file, const std::string& name) {
  H5Closer ds{H5Dopen2(file, name.c_str(), H5P_DEFAULT), H5Dclose};
  H5Closer dcpl{H5Dget_create_plist(ds.id), H5Pclose};
  const int n = H5Pget_nfilters(dcpl.id);
  bool shuffle = false, deflate = false;
  for (int k = 0; k < n; ++k) {
    unsigned flags = 0, config = 0;
    size_t cd_count = 0;
    const H5Z_filter_t f = H5Pget_filter2(dcpl.id, unsigned(k), &flags, &cd_count, nullptr, 0, nullptr, &config);
    shuffle = shuffle || f == H5Z_FILTER_SHUFFLE;
    deflate = deflate || f == H5Z_FILTER_DEFLATE;
  }
  return {n, shuffle && deflate};
}

// The default format deflates every dataset (shuffle + deflate) and keeps the values exactly; `none` writes them
// in chunks without filters. The values read back are the same either way.
TEST(SnapshotWriter, DeflatedSnapshotsHoldTheSameValues) {
  for (const bool deflate : {true, false}) {
    TempDir dir(deflate ? "snap_deflate" : "snap_plain");
    const Snap s = make_snap(3, 70000, 0.25);  // more rows than one chunk (32768)
    {
      slide::tools::SnapshotFormat format;
      format.deflate = deflate;
      SnapshotWriter w(dir.path, {}, true, format);
      w.write(0.5, 9, s.fields());
    }
    H5Closer master{H5Fopen((dir.path / "particles.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
    ASSERT_GE(master.id, 0);
    expect_snapshot(master.id, 0, s, 0.5, 9);
    for (const char* name : {"position", "velocity", "pressure", "phase", "kind", "id", "connectivity"}) {
      const auto [count, shuffled_and_deflated] = dataset_filters(master.id, std::string("snapshots/000000/") + name);
      EXPECT_EQ(count, deflate ? 2 : 0) << name;
      EXPECT_EQ(shuffled_and_deflated, deflate) << name;
    }
  }
}

// output.snapshot_fields and snapshot_precision: only the fields asked for (position, kind and id always), in the
// HDF5 file and the XDMF, and reals as 32-bit floats holding the values rounded to float.
TEST(SnapshotWriter, AFormatWritesTheChosenFieldsInSinglePrecision) {
  TempDir dir("snap_format");
  const Snap s = make_snap(2, 6, 1.5);
  slide::tools::SnapshotFormat format;
  format.fields = {"pressure"};
  format.single_precision = true;
  {
    SnapshotWriter w(dir.path, {"0 fluid", "0 water", "slide test"}, true, format);
    w.write(0.0, 0, s.fields());
  }
  H5Closer master{H5Fopen((dir.path / "particles.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
  ASSERT_GE(master.id, 0);
  const std::string base = "snapshots/000000/";
  for (const char* absent : {"velocity", "number_density", "density", "phase"})
    EXPECT_LE(H5Lexists(master.id, (base + absent).c_str(), H5P_DEFAULT), 0) << absent;
  const auto pressure = read_dataset<float>(master.id, base + "pressure", H5T_NATIVE_FLOAT);
  ASSERT_EQ(pressure.size(), 6u);
  for (size_t i = 0; i < 6; ++i) EXPECT_EQ(pressure[i], static_cast<float>(s.pressure[i]));
  const auto position = read_dataset<float>(master.id, base + "position", H5T_NATIVE_FLOAT);
  ASSERT_EQ(position.size(), 18u);
  for (size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(position[i * 3], static_cast<float>(s.position[i * 2]));
    EXPECT_EQ(position[i * 3 + 1], static_cast<float>(s.position[i * 2 + 1]));
    EXPECT_EQ(position[i * 3 + 2], 0.0f);
  }
  EXPECT_EQ(read_dataset<uint64_t>(master.id, base + "id", H5T_NATIVE_UINT64), s.id);
  EXPECT_EQ(read_dataset<uint8_t>(master.id, base + "kind", H5T_NATIVE_UINT8), s.kind);
  const std::string xdmf = read_text(dir.path / "particles.xdmf");
  EXPECT_EQ(count_occurrences(xdmf, "<Attribute "), 3u);  // pressure, kind, id
  EXPECT_EQ(xdmf.find("velocity"), std::string::npos);
  EXPECT_NE(xdmf.find("Precision=\"4\" Format=\"HDF\">snapshots/snapshot_000000.h5:/position"), std::string::npos);
  EXPECT_NE(xdmf.find("Precision=\"4\" Format=\"HDF\">snapshots/snapshot_000000.h5:/pressure"), std::string::npos);
  format.fields = {"speed"};
  EXPECT_THROW(SnapshotWriter(dir.path / "other", {}, true, format), std::invalid_argument);
}

TEST(AtomicFile, ReplacesContentAndLeavesNoTemporary) {
  TempDir dir("atomic");
  const fs::path p = dir.path / "out.txt";
  write_file_atomically(p, "first version\n");
  EXPECT_EQ(read_text(p), "first version\n");
  write_file_atomically(p, "second");
  EXPECT_EQ(read_text(p), "second");
  write_file_atomically(p, "");
  EXPECT_EQ(read_text(p), "");
  EXPECT_FALSE(any_tmp_files(dir.path));
}

TEST(AtomicFile, ThrowsWithPathOnFailure) {
  TempDir dir("atomic_fail");
  const fs::path p = dir.path / "missing_folder" / "out.txt";
  try {
    write_file_atomically(p, "x");
    FAIL() << "expected std::runtime_error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("out.txt"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("No such file"), std::string::npos) << e.what();
  }
}

TEST(AtomicFile, CsvWriterRoundTripsDoubles) {
  TempDir dir("csv");
  const fs::path p = dir.path / "series.csv";
  CsvWriter csv(p, {"time", "value", "other"});
  const std::vector<std::array<double, 3>> rows = {
      {0.1, 1.0 / 3.0, -2.5e-300},
      {std::numeric_limits<double>::max(), std::numeric_limits<double>::denorm_min(), 0.0},
      {123456789.123456789, -0.0, std::nextafter(1.0, 2.0)},
  };
  csv.add_row(rows[0]);
  csv.flush();
  EXPECT_EQ(count_occurrences(read_text(p), "\n"), 2u);
  csv.add_row(rows[1]);
  csv.add_row({rows[2][0], rows[2][1], rows[2][2]});
  csv.flush();
  EXPECT_EQ(csv.row_count(), 3u);
  EXPECT_THROW(csv.add_row({1.0, 2.0}), std::invalid_argument);

  std::istringstream in(read_text(p));
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  EXPECT_EQ(line, "time,value,other");
  for (const auto& row : rows) {
    ASSERT_TRUE(std::getline(in, line));
    std::istringstream ls(line);
    std::string cell;
    for (double expected : row) {
      ASSERT_TRUE(std::getline(ls, cell, ','));
      const double got = std::strtod(cell.c_str(), nullptr);
      EXPECT_EQ(got, expected) << cell;
      EXPECT_EQ(std::signbit(got), std::signbit(expected)) << cell;
    }
  }
  EXPECT_FALSE(std::getline(in, line));
  EXPECT_FALSE(any_tmp_files(dir.path));
}

TEST(SnapshotWriter, WritesSnapshotsReadableThroughMasterLinks) {
  TempDir dir("snap");
  const Snap s0 = make_snap(2, 5, 0.25);
  const Snap s1 = make_snap(2, 4, 1.75);
  {
    SnapshotWriter w(dir.path, {"0 fluid, 1 wall, 2 dummy", "0 water, 1 sediment", "slide test"});
    EXPECT_EQ(w.count(), 0u);
    w.write(0.0, 0, s0.fields());
    EXPECT_EQ(w.count(), 1u);
    w.write(0.1 + 1e-17, 123, s1.fields());
    EXPECT_EQ(w.count(), 2u);
  }
  EXPECT_TRUE(fs::exists(dir.path / "snapshots" / "snapshot_000000.h5"));
  EXPECT_TRUE(fs::exists(dir.path / "snapshots" / "snapshot_000001.h5"));
  EXPECT_FALSE(any_tmp_files(dir.path));

  const fs::path master_path = dir.path / "particles.h5";
  H5Closer master{H5Fopen(master_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
  ASSERT_GE(master.id, 0);
  expect_snapshot(master.id, 0, s0, 0.0, 0);
  expect_snapshot(master.id, 1, s1, 0.1 + 1e-17, 123);
  EXPECT_EQ(read_dataset<double>(master.id, "times", H5T_NATIVE_DOUBLE),
            (std::vector<double>{0.0, 0.1 + 1e-17}));
  EXPECT_EQ(read_dataset<int64_t>(master.id, "steps", H5T_NATIVE_INT64),
            (std::vector<int64_t>{0, 123}));

  const std::string xdmf = read_text(dir.path / "particles.xdmf");
  EXPECT_NE(xdmf.find("<Xdmf"), std::string::npos);
  EXPECT_NE(xdmf.find("</Xdmf>"), std::string::npos);
  EXPECT_NE(xdmf.find("CollectionType=\"Temporal\""), std::string::npos);
  EXPECT_EQ(count_occurrences(xdmf, "GridType=\"Uniform\""), 2u);
  EXPECT_EQ(count_occurrences(xdmf, "<Grid "), 3u);
  EXPECT_EQ(count_occurrences(xdmf, "</Grid>"), 3u);
  EXPECT_EQ(count_occurrences(xdmf, "TopologyType=\"Polyvertex\""), 2u);
  EXPECT_NE(xdmf.find("snapshots/snapshot_000000.h5:/position"), std::string::npos);
  EXPECT_NE(xdmf.find("snapshots/snapshot_000001.h5:/position"), std::string::npos);
  EXPECT_NE(xdmf.find("snapshots/snapshot_000001.h5:/id"), std::string::npos);
  EXPECT_NE(xdmf.find("NumberOfElements=\"5\""), std::string::npos);
  EXPECT_NE(xdmf.find("NumberOfElements=\"4\""), std::string::npos);
  EXPECT_NE(xdmf.find("NumberType=\"UChar\""), std::string::npos);
  EXPECT_NE(xdmf.find("NumberType=\"UInt\""), std::string::npos);
  EXPECT_EQ(count_occurrences(xdmf, "<Attribute "), 14u);
  EXPECT_EQ(count_occurrences(xdmf, "</Attribute>"), 14u);
  // ParaView's default (Xdmf3) reader makes cells only from a topology's connectivity: one per particle.
  EXPECT_EQ(count_occurrences(xdmf, "</Topology>"), 2u);
  EXPECT_NE(xdmf.find("<DataItem Dimensions=\"5\" NumberType=\"UInt\" Precision=\"4\" Format=\"HDF\">"
                      "snapshots/snapshot_000000.h5:/connectivity</DataItem>"),
            std::string::npos);
  EXPECT_NE(xdmf.find("snapshots/snapshot_000001.h5:/connectivity"), std::string::npos);
  // Units and codes: for the geometry and each of the 7 attributes, per snapshot.
  EXPECT_EQ(count_occurrences(xdmf, "<Information Name=\"units\""), 16u);
  EXPECT_EQ(count_occurrences(xdmf, "<Information Name=\"units\" Value=\"Pa\"/>"), 2u);
  EXPECT_EQ(count_occurrences(xdmf, "<Information Name=\"codes\" Value=\"0 water, 1 sediment\"/>"), 2u);
  EXPECT_EQ(count_occurrences(xdmf, "<Information Name=\"codes\" Value=\"0 fluid, 1 wall, 2 dummy\"/>"), 2u);

  // The same in the HDF5 files, as attributes.
  EXPECT_EQ(read_string_attribute(master.id, "snapshots/000001/position", "units"), "m");
  EXPECT_EQ(read_string_attribute(master.id, "snapshots/000001/velocity", "units"), "m/s");
  EXPECT_EQ(read_string_attribute(master.id, "snapshots/000001/pressure", "units"), "Pa");
  EXPECT_EQ(read_string_attribute(master.id, "snapshots/000001/density", "units"), "kg/m^3");
  EXPECT_EQ(read_string_attribute(master.id, "snapshots/000001/kind", "codes"), "0 fluid, 1 wall, 2 dummy");
  EXPECT_EQ(read_string_attribute(master.id, "snapshots/000001/phase", "codes"), "0 water, 1 sediment");
  EXPECT_EQ(read_string_attribute(master.id, "snapshots/000001", "code"), "slide test");
}

TEST(SnapshotWriter, ThreeDimensionalAndEmpty) {
  TempDir dir("snap3d");
  const Snap s0 = make_snap(3, 3, 2.0);
  const Snap empty = make_snap(3, 0, 0.0);
  SnapshotWriter w(dir.path);
  w.write(1.5, 7, s0.fields());
  w.write(2.5, 8, empty.fields());
  H5Closer master{H5Fopen((dir.path / "particles.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT),
                  H5Fclose};
  ASSERT_GE(master.id, 0);
  expect_snapshot(master.id, 0, s0, 1.5, 7);
  expect_snapshot(master.id, 1, empty, 2.5, 8);
  EXPECT_FALSE(any_tmp_files(dir.path));
}

TEST(SnapshotWriter, RejectsInconsistentFields) {
  TempDir dir("snapbad");
  SnapshotWriter w(dir.path);
  Snap s = make_snap(2, 3, 1.0);
  s.density.pop_back();
  EXPECT_THROW(w.write(0.0, 0, s.fields()), std::invalid_argument);
  Snap t = make_snap(2, 3, 1.0);
  t.dim = 4;
  EXPECT_THROW(w.write(0.0, 0, t.fields()), std::invalid_argument);
  EXPECT_EQ(w.count(), 0u);
}

TEST(SnapshotWriter, NewWriterRemovesOldSnapshotFiles) {
  TempDir dir("snapreuse");
  const Snap s = make_snap(2, 2, 1.0);
  {
    SnapshotWriter w(dir.path);
    for (int i = 0; i < 3; ++i) w.write(i, i, s.fields());
  }
  SnapshotWriter w(dir.path);
  w.write(0.0, 0, s.fields());
  EXPECT_TRUE(fs::exists(dir.path / "snapshots" / "snapshot_000000.h5"));
  EXPECT_FALSE(fs::exists(dir.path / "snapshots" / "snapshot_000001.h5"));
  EXPECT_FALSE(fs::exists(dir.path / "snapshots" / "snapshot_000002.h5"));
}

TEST(SnapshotWriter, H5pyReadsThroughLinksFromAnotherDirectory) {
  if (!python_has_h5py()) GTEST_SKIP() << "/usr/bin/python3 with h5py not available";
  TempDir dir("snappy");
  TempDir other("snappy_cwd");
  const Snap s0 = make_snap(2, 3, 0.5);
  const Snap s1 = make_snap(2, 6, 3.25);
  {
    SnapshotWriter w(dir.path);
    w.write(0.0, 0, s0.fields());
    w.write(0.02, 10, s1.fields());
  }
  // Runs from `other` (neither the output folder nor its parent) and opens the master file by
  // absolute path: the relative external links must resolve against particles.h5's folder.
  const std::string script =
      "import h5py\n"
      "f = h5py.File('" + (dir.path / "particles.h5").string() + "', 'r')\n"
      "for v in f['snapshots/000001/pressure'][()]: print(repr(float(v)))\n"
      "print('times', ' '.join(repr(float(t)) for t in f['times'][()]))\n"
      "print('ids', ' '.join(str(int(i)) for i in f['snapshots/000001/id'][()]))\n";
  const fs::path script_path = other.path / "read.py";
  write_file_atomically(script_path, script);
  const std::string out =
      run_capture("cd '" + other.path.string() + "' && /usr/bin/python3 read.py 2>&1");
  std::istringstream in(out);
  std::string line;
  for (double expected : s1.pressure) {
    ASSERT_TRUE(std::getline(in, line)) << out;
    EXPECT_EQ(std::strtod(line.c_str(), nullptr), expected) << line;
  }
  ASSERT_TRUE(std::getline(in, line)) << out;
  EXPECT_EQ(line, "times 0.0 0.02");
  ASSERT_TRUE(std::getline(in, line)) << out;
  EXPECT_EQ(line, "ids 100 103 106 109 112 115");
}
