// Dam break against Martin & Moyce (1952): the surge front Z = front / a against T = t sqrt(2 g / a), mean relative
// error over the reference points with 0 < T <= 3 (all four transcriptions) below 12 % at a/20 (the shipped
// resolution), a/40 and a/80.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "tests/cli_helpers.hpp"

namespace slide::testing {
namespace {

namespace fs = std::filesystem;

struct Series {
  std::vector<double> T, Z;
};

// Reads two named columns of a CSV file (lines starting with '#' are comments).
Series read_columns(const fs::path& file, const std::string& t_column, const std::string& z_column) {
  std::ifstream in(file);
  std::string line;
  std::vector<std::string> header;
  Series s;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
    if (header.empty()) {
      header = cells;
      continue;
    }
    auto at = [&](const std::string& name) {
      for (std::size_t k = 0; k < header.size(); ++k)
        if (header[k] == name) return std::stod(cells.at(k));
      throw std::runtime_error("no column " + name + " in " + file.string());
    };
    s.T.push_back(at(t_column));
    s.Z.push_back(at(z_column));
  }
  return s;
}

double interpolate(const Series& s, double T) {
  if (T <= s.T.front()) return s.Z.front();
  for (std::size_t k = 1; k < s.T.size(); ++k)
    if (T <= s.T[k]) return s.Z[k - 1] + (s.Z[k] - s.Z[k - 1]) * (T - s.T[k - 1]) / (s.T[k] - s.T[k - 1]);
  return s.Z.back();
}

double front_error(int a_over_dp) {
  const double a = 0.05715;
  const fs::path out = fresh_directory("dam_break_" + std::to_string(a_over_dp));
  std::ostringstream set;
  set.precision(17);
  set << " --set particle_spacing=" << a / a_over_dp << " --set output.snapshots=false";
  const CommandResult r = run_command(slide_binary() + " run " + (source_dir() / "cases/dam_break_2d.yaml").string() +
                                      " --quiet --out " + out.string() + set.str());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const Series sim = read_columns(out / "surge_front.csv", "T", "Z");
  const Series ref = read_columns(source_dir() / "cases/reference/martin_moyce_1952_surge_front.csv",
                                  "T_dimless_t_sqrt_2g_over_a", "Z_dimless_xfront_over_a");
  EXPECT_GT(sim.T.back(), 3.0);
  double sum = 0.0;
  int count = 0;
  for (std::size_t k = 0; k < ref.T.size(); ++k) {
    if (ref.T[k] <= 0.0 || ref.T[k] > 3.0) continue;
    sum += std::abs(interpolate(sim, ref.T[k]) - ref.Z[k]) / ref.Z[k];
    ++count;
  }
  EXPECT_EQ(count, 35);
  const double error = sum / count;
  std::printf("dam break a/%d: mean relative error in Z over %d reference points with 0 < T <= 3: %.2f %%\n",
              a_over_dp, count, 100 * error);
  return error;
}

TEST(DamBreak, FrontErrorAtShippedResolution) { EXPECT_LT(front_error(20), 0.12); }
TEST(DamBreak, FrontErrorAtA40) { EXPECT_LT(front_error(40), 0.12); }
TEST(DamBreak, FrontErrorAtA80) { EXPECT_LT(front_error(80), 0.12); }

}  // namespace
}  // namespace slide::testing
