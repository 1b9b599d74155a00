// The free-surface gauge (coupling/free_surface_gauge.hpp) on flat water of either lattice: it reads the water's
// edge, half a row spacing above the top row, wherever it stands along the row.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/free_surface_gauge.hpp"
#include "tests/cli_helpers.hpp"
#include "tests/scene_runner.hpp"
#include "tests/water_block_scene.hpp"

namespace slide::testing {
namespace {

void expect_gauge_reads_the_edge(const std::string& lattice) {
  auto scene = free_water_block(lattice, "gauge");
  const auto& sim = *scene->simulation;
  const double dp = sim.options.dp;
  double top = -1.0;
  for (std::size_t i = 0; i < sim.particles().size(); ++i) top = std::max(top, sim.particles().position[i][1]);
  const double edge = top + 0.5 * row_spacing(sim.options.lattice, dp);
  // Eleven gauges across one lattice spacing in the middle of the block.
  const double a = nearest_spacing(sim.options.lattice, dp);
  double mean = 0.0;
  for (int k = 0; k <= 10; ++k) {
    const double eta = free_surface_elevation<2>(sim, Vec<2>(0.2 + 0.1 * k * a, 0.0));
    EXPECT_NEAR(eta, edge, 0.06 * dp) << lattice << " gauge " << k;
    mean += eta / 11.0;
  }
  EXPECT_NEAR(mean, edge, 0.04 * dp) << lattice;
  // No water under the line: NaN.
  EXPECT_TRUE(std::isnan(free_surface_elevation<2>(sim, Vec<2>(0.6, 0.0))));
}

TEST(Gauge, ReadsTheEdgeOfASquareLattice) { expect_gauge_reads_the_edge("square"); }
TEST(Gauge, ReadsTheEdgeOfAHexagonalLattice) { expect_gauge_reads_the_edge("hexagonal"); }

}  // namespace
}  // namespace slide::testing
