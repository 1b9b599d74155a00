// The water gap (coupling/water_gap.hpp) against faces placed at known distances from a flat block of water on
// either lattice: a face on the water's edge reads the gauge's own offset (+0.03 dp square, +0.02 dp hexagonal: the
// contour lies that far inside the water), and moving the face away from the water adds exactly the distance moved.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/water_gap.hpp"
#include "tests/cli_helpers.hpp"
#include "tests/scene_runner.hpp"
#include "tests/water_block_scene.hpp"

namespace slide::testing {
namespace {

// A box under the water, its top face at y = top (counter-clockwise).
std::vector<Vec<2>> box_below(double top) {
  return {Vec<2>(0.05, top - 0.1), Vec<2>(0.35, top - 0.1), Vec<2>(0.35, top), Vec<2>(0.05, top)};
}

void expect_gap_reads_the_distance(const std::string& lattice, double edge_offset_over_dp) {
  const auto scene = free_water_block(lattice, "water_gap");  // its bottom edge is y = 0
  const auto& sim = *scene->simulation;
  const double dp = sim.options.dp;
  for (const double moved_over_dp : {0.0, 0.25, 0.5, -0.3}) {
    const WaterGap gap = water_gap_along_outline(sim, box_below(-moved_over_dp * dp));
    // Only the top face is wetted: 0.3 m less 2 dp at each end, sampled every dp/4.
    EXPECT_NEAR(gap.wetted_length, 0.3 - 4 * dp + 0.25 * dp, 1e-9) << lattice;
    EXPECT_NEAR(gap.mean / dp, moved_over_dp + edge_offset_over_dp, 0.01) << lattice << " moved " << moved_over_dp;
  }
  // A face 2.5 dp inside the water: the search, from 2 dp behind the face, starts in water and finds no edge.
  EXPECT_EQ(water_gap_along_outline(sim, box_below(2.5 * dp)).wetted_length, 0.0) << lattice;
  // A box beside the water, not touching it: no wetted face.
  const std::vector<Vec<2>> away = {Vec<2>(0.6, 0.0), Vec<2>(0.8, 0.0), Vec<2>(0.8, 0.1), Vec<2>(0.6, 0.1)};
  EXPECT_EQ(water_gap_along_outline(sim, away).wetted_length, 0.0);
}

TEST(WaterGap, ReadsTheDistanceFromASquareLattice) { expect_gap_reads_the_distance("square", 0.03); }
TEST(WaterGap, ReadsTheDistanceFromAHexagonalLattice) { expect_gap_reads_the_distance("hexagonal", 0.02); }

}  // namespace
}  // namespace slide::testing
