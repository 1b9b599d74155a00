// Dam break against Martin & Moyce (1952): the surge front Z = front / a against T = t sqrt(2 g / a), mean relative
// error over the reference points with 0 < T <= 3 (all four transcriptions) below 12 % at a/20 (the shipped
// resolution), a/40 and a/80. And the wall condition of the viscous term against the run-to-run spread.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "cases/csv_table.hpp"
#include "tests/cli_helpers.hpp"
#include "tools/measures/dam_break_front.hpp"
#include "tools/measures/series.hpp"

namespace slide::testing {
namespace {

namespace fs = std::filesystem;

struct Series {
  std::vector<double> T, Z;
};

Series read_columns(const fs::path& file, const std::string& t_column, const std::string& z_column) {
  const CsvTable t = read_csv(file);
  return {t.numbers(t_column), t.numbers(z_column)};
}

double interpolate(const Series& s, double T) { return tools::interpolate(s.T, s.Z, T); }

double front_error(int a_over_dp) {
  const double a = 0.05715;
  const fs::path out = fresh_directory("dam_break_" + std::to_string(a_over_dp));
  std::ostringstream set;
  set.precision(17);
  set << " --set particle_spacing=" << a / a_over_dp << " --set output.snapshots=false";
  const CommandResult r = run_command(slide_binary() + " run " + (source_dir() / "cases/dam_break_2d.yaml").string() +
                                      " --quiet --out " + out.string() + set.str());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  const tools::FrontError e =
      tools::dam_break_front_error(read_csv(out / "surge_front.csv"),
                                   read_csv(source_dir() / "cases/reference/martin_moyce_1952_surge_front.csv"));
  EXPECT_EQ(e.points, 35);
  const double error = e.mean_relative;
  const int count = e.points;
  std::printf("dam break a/%d: mean relative error in Z over %d reference points with 0 < T <= 3: %.2f %%\n",
              a_over_dp, count, 100 * error);
  return error;
}

TEST(DamBreak, FrontErrorAtShippedResolution) { EXPECT_LT(front_error(20), 0.12); }
TEST(DamBreak, FrontErrorAtA40) { EXPECT_LT(front_error(40), 0.12); }
TEST(DamBreak, FrontErrorAtA80) { EXPECT_LT(front_error(80), 0.12); }

// The series averaged over a window of width `window` centred on each of 601 points of T in [0, T_max] (linearly
// interpolated between samples; the window is cut at the ends).
std::vector<double> smoothed(const Series& s, double T_max, double window) {
  constexpr int points = 601;
  std::vector<double> T(points), v(points), out(points);
  for (int k = 0; k < points; ++k) T[k] = T_max * k / (points - 1), v[k] = interpolate(s, T[k]);
  for (int k = 0; k < points; ++k) {
    double sum = 0.0;
    int count = 0;
    for (int m = 0; m < points; ++m)
      if (std::abs(T[m] - T[k]) <= 0.5 * window) sum += v[m], ++count;
    out[k] = sum / count;
  }
  return out;
}

// Largest difference of two smoothed series, absolute or relative to the first.
double largest_difference(const std::vector<double>& a, const std::vector<double>& b, bool relative) {
  double d = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const double dk = std::abs(b[k] - a[k]) / (relative ? a[k] : 1.0);
    if (!std::isfinite(dk)) return dk;  // a NaN height or front fails the comparison, not passes it
    d = std::max(d, dk);
  }
  return d;
}

// Issue 12: with water's viscosity the no-slip boundary layer sqrt(nu t) is a fraction of a spacing here, so free-
// and no-slip walls should give the same flow. But the water height at the wall and the front are chaotic at the
// particles' scale: a change of g by 1e-12 of itself changes them by 2-6 % of 2a and of Z at T <= 3 (measured
// here, a/40, point by point; 1e-14 does the same), so no two runs can agree within 1 % point by point. What can be
// asserted: over T <= 3, averaged over windows of Delta T = 0.5, the free-slip run differs from the no-slip run by no
// more than the largest of four no-slip runs with g changed by +-1e-12 and +-1e-14 do. Measured (stop 21, the column
// filled to 796 of its 800 dp^2): free slip moves the height by 1.54 % of 2a and the front by 0.69 % (relative), the
// four perturbed runs by 1.12 / 1.63 / 0.71 / 0.86 % and 0.71 / 0.17 / 1.09 / 0.70 %: free slip is one more sample
// of the same spread. On the shipped square-lattice method
// (cases/dam_break_2d.yaml) the same comparison fails: free slip moves its smoothed front by 6.30 % against a spread
// of 1.82 / 1.92 % (g +-1e-12, stop 20), a wall effect that method has and the default does not (its height: 3.37 %
// against 0.86 / 3.78 %).
// About 5 minutes of one core (six runs, each settling for 1 s first).
// cases/dam_break_gated_2d.yaml at a/40 to T = 3.05.
TEST(DamBreak, WallSlipChangesNoMoreThanTheRunToRunSpread) {
  const fs::path dir = fresh_directory("dam_break_slip");
  auto run = [&](const std::string& name, const std::string& sets) {
    const fs::path out = dir / name;
    const CommandResult r = run_command(slide_binary() + " run " +
                                        (source_dir() / "cases/dam_break_gated_2d.yaml").string() + " --quiet --out " +
                                        out.string() + " --set particle_spacing=0.00142875 --set end_time=0.1645" +
                                        " --set output.snapshots=false" + sets);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    const double T_max = 3.0, window = 0.5;
    return std::pair{smoothed(read_columns(out / "surge_front.csv", "T", "H_over_2a"), T_max, window),
                     smoothed(read_columns(out / "surge_front.csv", "T", "Z"), T_max, window)};
  };
  const auto no_slip = run("no_slip", "");
  const auto free_slip = run("free_slip", " --set method.wall_slip=free_slip");
  // The spread of the chaos: four no-slip runs with g changed by +-1e-12 and +-1e-14 of itself.
  std::vector<std::pair<std::vector<double>, std::vector<double>>> perturbed;
  for (const std::string g : {"9.81000000001", "9.80999999999", "9.8100000000001", "9.8099999999999"})
    perturbed.push_back(run("g_" + g, " --set gravity=[0,-" + g + "]"));
  const double height_slip = largest_difference(no_slip.first, free_slip.first, false);
  const double front_slip = largest_difference(no_slip.second, free_slip.second, true);
  double height_spread = 0.0, front_spread = 0.0;
  std::string spreads;
  for (const auto& p : perturbed) {
    const double h = largest_difference(no_slip.first, p.first, false);
    const double z = largest_difference(no_slip.second, p.second, true);
    height_spread = std::max(height_spread, h), front_spread = std::max(front_spread, z);
    spreads += fmt::format(" {:.2f}/{:.2f}", 100 * h, 100 * z);
  }
  std::printf("dam break a/40, T <= 3, smoothed over Delta T = 0.5: free against no slip: height %.2f %% of 2a, "
              "front %.2f %%; g * (1 +-1e-12), (1 +-1e-14), height/front %%:%s\n",
              100 * height_slip, 100 * front_slip, spreads.c_str());
  EXPECT_LE(height_slip, height_spread);
  EXPECT_LE(front_slip, front_spread);
}

}  // namespace
}  // namespace slide::testing
