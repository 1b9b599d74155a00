#include "cases/particle_budget.hpp"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <stdexcept>

#include "fluid/vec.hpp"

namespace slide::cases {

double run_memory_bytes(double n, double neighbours) {
  // fluid/particles.hpp: four vectors, seven doubles, phase and kind, id and body frame (a body's own table aside)
  const double state = 4 * sizeof(Vec<2>) + 7 * sizeof(double) + 2 + 2 * sizeof(std::uint32_t);
  // tools/run_outputs.hpp IdOrdered: position and velocity, pressure, number density and density, phase and kind, id
  const double last_good = 2 * sizeof(Vec<2>) + 3 * sizeof(double) + 2 + sizeof(std::uint32_t);
  const double working = 3 * sizeof(Vec<2>) + 2 * sizeof(std::uint32_t);
  // fluid/neighbor_grid.hpp (first and count too) and fluid/pair_weights.hpp
  const double list = (neighbours + 2) * sizeof(std::uint32_t) + neighbours * sizeof(double);
  // fluid/image_neighbours.hpp: 8 B and about 9 kept fluid neighbours (16 B each) for each wetted boundary particle,
  // which this estimate does not know the number of: in the bench case (3,018 boundary particles of 23,018) they come
  // to about 20 B a particle, counted here for every scene
  const double images = 20.0;
  return n * (state + last_good + working + list + images);
}

double listed_neighbours_estimate(double re_over_dp, double skin_over_dp) {
  const double radius = re_over_dp + skin_over_dp;
  return 1.25 * M_PI * radius * radius;
}

namespace {

std::optional<double> read_number_after(const char* file, const std::string& label) {
  std::ifstream in(file);
  std::string word;
  while (in >> word)
    if (word == label) {
      double v = 0.0;
      if (in >> v) return v;
    }
  return std::nullopt;
}

// "2G", "512M", "100000": bytes.
double parse_size(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  double unit = 1.0;
  const std::string suffix(end);
  if (suffix == "k" || suffix == "K") unit = 1e3;
  else if (suffix == "M") unit = 1e6;
  else if (suffix == "G") unit = 1e9;
  else if (!suffix.empty()) throw std::invalid_argument("SLIDE_MEMORY_LIMIT=" + text + ": expected bytes, or k, M or G");
  if (end == text.c_str() || !std::isfinite(v) || v <= 0)
    throw std::invalid_argument("SLIDE_MEMORY_LIMIT=" + text + ": expected a positive size");
  return v * unit;
}

}  // namespace

std::optional<MemoryLimit> memory_limit() {
  if (const char* env = std::getenv("SLIDE_MEMORY_LIMIT"))
    return MemoryLimit{parse_size(env), "SLIDE_MEMORY_LIMIT"};
  std::optional<MemoryLimit> best;
  if (const auto kb = read_number_after("/proc/meminfo", "MemAvailable:"))
    best = MemoryLimit{*kb * 1024.0, "MemAvailable in /proc/meminfo"};
  std::ifstream max_file("/sys/fs/cgroup/memory.max");
  std::string max_text;
  if (max_file >> max_text && max_text != "max") {
    std::ifstream current_file("/sys/fs/cgroup/memory.current");
    double current = 0.0;
    current_file >> current;
    const double headroom = std::strtod(max_text.c_str(), nullptr) - current;
    if (headroom > 0 && (!best || headroom < best->bytes)) best = MemoryLimit{headroom, "the cgroup's memory.max"};
  }
  return best;
}

}  // namespace slide::cases
