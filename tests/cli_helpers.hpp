#pragma once
// Helpers for tests that run the slide program as a user would.
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

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

// A fresh folder under the system's temporary directory.
inline std::filesystem::path fresh_directory(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("slide_test_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
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
