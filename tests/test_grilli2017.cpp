// Grilli et al. (2017) Test 17 (cases/grilli2017_granular_slide_2d.yaml): the submerged glass-bead slide against its
// measured upper surfaces (slide_shapes.csv, coupling/slide_shape_error.hpp) at experiment times 0.17, 0.32, 0.47 and
// 0.62 s (model time + 0.12 s), at two spacings, with both slide models; the ctest label `long`.
// Issue 29's goal is the front within 10 % of its travel and the surfaces within 1 cm rms; it is NOT met yet (the
// figures are printed, docs/slides-under-water.md). What these tests hold: the slides move down the slope under water
// (on the total pressure the granular slide moved 1.4 mm in 2 s, and the rigid triangle did not move; below).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "cases/csv_table.hpp"
#include "tests/cli_helpers.hpp"

namespace slide::testing {
namespace {

CsvTable run_grilli(const std::string& name, const std::vector<std::string>& sets) {
  const auto dir = fresh_directory(name);
  std::string cmd = slide_binary() + " run " + (source_dir() / "cases" / "grilli2017_granular_slide_2d.yaml").string() +
                    " --quiet --out " + dir.string() + " --set end_time=0.75 --set output.snapshots=false";
  for (const auto& s : sets) cmd += " --set " + s;
  const CommandResult r = run_command(cmd);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  return read_csv(dir / "slide_shapes.csv");
}

struct ShapeRun {
  std::vector<double> t, front_error, rms, travel, model_front;
};

ShapeRun run_model(const std::string& model, double dp) {
  const CsvTable shapes = run_grilli("grilli_" + model + "_" + std::to_string(dp),
                                     {"bodies[0].model=" + model, "particle_spacing=" + std::to_string(dp)});
  ShapeRun r{shapes.numbers("time_measured"), shapes.numbers("front_error_percent"), shapes.numbers("surface_rms"),
             shapes.numbers("travel_measured"), shapes.numbers("front_model")};
  EXPECT_EQ(r.t.size(), 6u);
  for (std::size_t k = 2; k < r.t.size(); ++k)
    std::printf("%s, dp %g, t = %.2f s: front %+.1f %% of its travel (model front at x = %.4f m), surface rms "
                "%.2f cm\n",
                model.c_str(), dp, r.t[k], r.front_error[k], r.model_front[k], 100.0 * r.rms[k]);
  return r;
}

// The rigid triangle (mass 11.2 kg/m, friction 0.477 against the slope) slides: it moves more than a spacing by 0.62 s,
// and less than a rigid block with that friction under its buoyant weight alone would in the 0.74 s since release
// (a = (rho_s - rho_w) / rho_s g (sin 35 - 0.477 cos 35) = 0.858 m/s^2, 0.235 m along the slope, 0.192 m in x; the
// water's drag and added mass only slow it). The granular slide's front leads the rigid one's: the material both
// slides and spreads down the slope.
void expect_the_slides_move(double dp) {
  const ShapeRun granular = run_model("granular", dp), rigid = run_model("rigid", dp);
  const double rigid_moved = rigid.model_front.back() - 0.448;
  EXPECT_GT(rigid_moved, dp);
  EXPECT_LT(rigid_moved, 0.192);
  EXPECT_GT(granular.model_front.back(), rigid.model_front.back());
}

TEST(LongGrilli2017, SlidesMoveDownTheSlopeUnderWater) { expect_the_slides_move(0.008); }

TEST(LongGrilli2017, SlidesMoveDownTheSlopeUnderWaterAtAFinerSpacing) { expect_the_slides_move(0.006); }

}  // namespace
}  // namespace slide::testing
