// Faults lose nothing (issue 14): a write that fails during a run (a full disk; here a file-size limit, ulimit -f)
// stops it with a clear message and leaves the earlier outputs whole; a run killed with SIGKILL leaves every file it
// had finished readable.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/cli_helpers.hpp"

namespace slide::testing {
namespace {

namespace fs = std::filesystem;

const std::string kDamBreak = (source_dir() / "cases" / "dam_break_2d.yaml").string();

bool python_has_h5py() { return std::system("/usr/bin/python3 -c 'import h5py' >/dev/null 2>&1") == 0; }

// Every finished output of `run` opens: run.json parses, each CSV row has the header's columns, the XDMF is whole and
// names as many snapshots as exist, and (with h5py) every snapshot the master file links opens.
void expect_readable(const fs::path& run) {
  EXPECT_NO_THROW(nlohmann::json::parse(read_file(run / "run.json"))) << run;
  for (const auto& e : fs::directory_iterator(run)) {
    if (e.path().extension() != ".csv") continue;
    std::istringstream in(read_file(e.path()));
    std::string header, line;
    ASSERT_TRUE(std::getline(in, header)) << e.path();
    const auto columns = std::count(header.begin(), header.end(), ',');
    while (std::getline(in, line)) EXPECT_EQ(std::count(line.begin(), line.end(), ','), columns) << e.path() << line;
  }
  const std::string xdmf = read_file(run / "particles.xdmf");
  EXPECT_TRUE(xdmf.ends_with("</Xdmf>\n"));
  if (python_has_h5py()) {
    const auto r = run_command("/usr/bin/python3 -c \"import h5py; f = h5py.File('" + (run / "particles.h5").string() +
                               "'); n = len(f['times']); [f['snapshots/%06d/position' % i][()] for i in range(n)]; "
                               "print('snapshots', n)\"");
    EXPECT_EQ(r.exit_code, 0) << r.output;
  }
}

TEST(Faults, AFileSizeLimitStopsTheRunWithAClearMessageAndTheEarlierFilesWhole) {
  const auto dir = fresh_directory("file_size_limit");
  // The XDMF grows by one grid per snapshot and passes 150 kB at about the 57th; each other file stays under it.
  const auto r = run_command("bash -c 'ulimit -f 150; " + slide_binary() + " run " + kDamBreak +
                             " --quiet --threads 1 --set output.snapshot_interval=0.002 --out " +
                             (dir / "run").string() + "'");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("slide: error: stopped at t = "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("particles.xdmf"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("File too large"), std::string::npos) << r.output;
  const auto j = nlohmann::json::parse(read_file(dir / "run" / "run.json"));
  EXPECT_EQ(j["status"], "failed");
  EXPECT_GT(j["simulated_time"].get<double>(), 0.05);
  expect_readable(dir / "run");
  fs::remove_all(dir);
}

TEST(Faults, ARunKilledWithSigkillLeavesEveryFinishedFileReadable) {
  const auto dir = fresh_directory("sigkill");
  const fs::path run = dir / "run";
  const std::string script = "(" + slide_binary() + " run " + kDamBreak + " --quiet --threads 1 --set end_time=30 " +
                             "--set output.snapshot_interval=0.005 --out " + run.string() + " & pid=$!; " +
                             "for i in $(seq 600); do [ -f " + (run / "snapshots" / "snapshot_000004.h5").string() +
                             " ] && break; sleep 0.1; done; kill -KILL $pid; wait $pid; echo exit=$?)";
  const auto r = run_command(script);
  EXPECT_NE(r.output.find("exit=137"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(run / "snapshots" / "snapshot_000004.h5"));
  expect_readable(run);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace slide::testing
