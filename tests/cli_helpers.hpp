#pragma once
// Helpers for tests that run the slide program as a user would.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace slide::testing {

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

inline CommandResult run_command(const std::string& command) {
  CommandResult r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return r;
  std::array<char, 4096> buffer;
  while (std::fgets(buffer.data(), buffer.size(), pipe)) r.output += buffer.data();
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

// A small valid scene (a water column, not at rest, so it starts from the lattice rather than settling); each bad-input
// test changes one thing.
inline const char* kGoodScene = R"(particle_spacing: 0.02
end_time: 0.01
fluid:
  phases: [{name: water}]
  regions: [{type: rectangle, min: [0, 0], max: [0.2, 0.2]}]
walls:
  - points: [[0, 0.4], [0, 0], [0.6, 0], [0.6, 0.4]]
method: {initial_state: lattice}
)";

inline std::string slide_binary() { return SLIDE_BINARY; }
inline std::filesystem::path source_dir() { return SLIDE_SOURCE_DIR; }

// The folders fresh_directory made in this process, removed when it exits (each test runs in a process of its own
// under ctest), unless SLIDE_KEEP_TEST_DIRS is set, to look at what a failed test left: a run of the whole suite had
// left some 2,000 of them behind.
class TestDirectories {
 public:
  static TestDirectories& made() {
    static TestDirectories d;
    return d;
  }
  void add(const std::filesystem::path& p) { paths_.push_back(p); }
  ~TestDirectories() {
    // A forked child that exits normally must not take its parent's folders with it.
    if (std::getenv("SLIDE_KEEP_TEST_DIRS") || ::getpid() != owner_) return;
    std::error_code ignored;  // a folder already gone, or not removable, is no reason to fail at exit
    for (const auto& p : paths_) std::filesystem::remove_all(p, ignored);
  }

 private:
  std::vector<std::filesystem::path> paths_;
  pid_t owner_ = ::getpid();
};

// A fresh folder under the system's temporary directory, removed when the process exits (TestDirectories).
inline std::filesystem::path fresh_directory(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("slide_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  TestDirectories::made().add(dir);
  return dir;
}

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream out(p);
  out << text;
}

}  // namespace slide::testing
