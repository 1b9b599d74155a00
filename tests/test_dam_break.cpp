// Dam break against Martin & Moyce (1952): the surge front Z = front / a against T = t sqrt(2 g / a), mean relative
// error over the reference points with 0 < T <= 3 (all four transcriptions) below 12 % at a/20 (the shipped
// resolution), a/40 and a/80. And what the wall condition of the viscous term changes (free against no slip).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>


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

// Run to T = 3.05 (t = 0.1645 s), just past the last reference point, not the case's end (T = 3.7): at a/40 the
// case's run to its end stops at t = 0.1835 s (exit 3) since the particles' neighbour sums run in id order (issue 32):
// a lone particle left in the dry corner is flung out at c0, its number density rising from 1.05 to 1.28 n0 as it
// moves out of the corner, through the wall particles' mirror fill that it sets itself (fluid/wall_pressure.hpp).
// Runs with g * (1 +- 1e-12) complete. A defect of the mirror wall model, filed with issue 32's note; it does not
// touch the front over T <= 3 measured here.
double front_error(int a_over_dp) {
  const double a = 0.05715;
  const fs::path out = fresh_directory("dam_break_" + std::to_string(a_over_dp));
  std::ostringstream set;
  set.precision(17);
  set << " --set particle_spacing=" << a / a_over_dp << " --set output.snapshots=false --set end_time=0.1645";
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
// and no-slip walls should give nearly the same flow. The water height at the wall and the front are chaotic at the
// particles' scale: a change of g by 1e-12 of itself changes them by up to 1.4 % of 2a and 0.8 % of Z at T <= 3
// (a/40, smoothed over Delta T = 0.5), so the two wall conditions are compared through 3-run means, both families
// perturbing g alike.
// Measured (stop 27, 7 runs each, g * (1, 1 +-1e-12, 1 +-1e-13, 1 +-1e-14)): free slip moves the mean front by 0.68 %
// of Z (at T = 2.92, 4.6 standard errors: a small real wall effect, not chaos) and the mean height by 0.85 % of 2a;
// one run's scatter about its family's mean is up to 0.34 % and 0.56 % (standard deviations). On the shipped
// square-lattice method (cases/dam_break_2d.yaml) free slip moved the front by 6.30 % and the height by 3.37 % (single
// runs, stop 20): a wall effect that method has and the default does not. The bound, 2 %, lies between the two: 2.5
// (height) and 4.7 (front) standard errors of the difference of 3-run means above the default's effect, below the
// square lattice's. The largest difference is taken over T (about six independent windows), so a change in
// round-off could still flip the height's comparison with a chance of a few percent.
// Issue 32 (neighbour sums in id order, a new realisation of the round-off): one run's scatter about its family's
// mean is now up to 1.25 % (height) and 0.67 % (front) (standard deviations, 7 runs each, the largest over T), twice
// stop 27's; 3-run means then gave height 2.55 % and front 1.32 %, 7-run means 1.01 % and 1.30 % (the same 14 runs:
// measured with `slide run cases/dam_break_gated_2d.yaml` and the sets below). The families are therefore 7 runs
// each, as stop 27 measured them, not 3: the bound is unchanged, the standard error of the difference of the means
// about 0.6 % (height) and 0.3 % (front).
// (Until stop 27 this test compared one free-slip run with the spread of four perturbed no-slip runs about one
// no-slip run: a comparison of single samples that a change in round-off flipped: the free-slip run's front was
// 0.93 % from the reference's, the fronts of eight no-slip runs with g perturbed 0.27-0.70 %.)
// About 6 minutes of one core (fourteen runs, each settling for 1 s first). cases/dam_break_gated_2d.yaml at a/40 to
// T = 3.05.
TEST(DamBreak, WallSlipMovesTheMeanFrontAndHeightByUnderTwoPercent) {
  const fs::path dir = fresh_directory("dam_break_slip");
  using Smoothed = std::pair<std::vector<double>, std::vector<double>>;  // H / 2a and Z, smoothed
  auto run = [&](const std::string& name, const std::string& sets) -> Smoothed {
    const fs::path out = dir / name;
    const CommandResult r = run_command(slide_binary() + " run " +
                                        (source_dir() / "cases/dam_break_gated_2d.yaml").string() + " --quiet --out " +
                                        out.string() + " --set particle_spacing=0.00142875 --set end_time=0.1645" +
                                        " --set output.snapshots=false" + sets);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    const double T_max = 3.0, window = 0.5;
    return {smoothed(read_columns(out / "surge_front.csv", "T", "H_over_2a"), T_max, window),
            smoothed(read_columns(out / "surge_front.csv", "T", "Z"), T_max, window)};
  };
  // Each wall condition's mean over g * (1, 1 +- 1e-12, 1 +- 1e-13, 1 +- 1e-14).
  auto family_mean = [&](const std::string& slip) {
    Smoothed mean;
    const std::vector<std::string> gs{"9.81",           "9.81000000001",   "9.80999999999",  "9.810000000001",
                                      "9.809999999999", "9.8100000000001", "9.8099999999999"};
    for (const std::string& g : gs) {
      const Smoothed s = run(slip + "_" + g, " --set method.wall_slip=" + slip + " --set gravity=[0,-" + g + "]");
      if (mean.first.empty()) mean = {std::vector<double>(s.first.size()), std::vector<double>(s.second.size())};
      for (std::size_t k = 0; k < s.first.size(); ++k)
        mean.first[k] += s.first[k] / gs.size(), mean.second[k] += s.second[k] / gs.size();
    }
    return mean;
  };
  const Smoothed no_slip = family_mean("no_slip"), free_slip = family_mean("free_slip");
  const double height = largest_difference(no_slip.first, free_slip.first, false);
  const double front = largest_difference(no_slip.second, free_slip.second, true);
  std::printf("dam break a/40, T <= 3, smoothed over Delta T = 0.5, means of 7 runs (g * (1, 1 +-1e-12, -13, -14)): free against "
              "no slip: height %.2f %% of 2a, front %.2f %% of Z\n",
              100 * height, 100 * front);
  EXPECT_LT(height, 0.02);
  EXPECT_LT(front, 0.02);
}

}  // namespace
}  // namespace slide::testing
