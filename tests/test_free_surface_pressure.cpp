// Free-surface pressure (fluid/free_surface_pressure.hpp): a surface particle continues the bulk's hydrostatic field,
// and never goes negative; or carries the head of half a row.
#include <gtest/gtest.h>

#include <cmath>

#include "fluid/free_surface_pressure.hpp"
#include "fluid/lattice.hpp"

namespace slide {
namespace {

// Still water on the lattice x = (i + 1/2) dp, y = (j + 1/2) dp, rows 0..19, its edge at H = 20 dp, carrying
// p = rho g (H - y); the top row is the free surface (not bulk). Optionally one stray particle above the water.
struct StillWater {
  static constexpr double dp = 0.01, rho = 1000.0, g = 9.81, H = 20 * dp, re = 2.1 * dp;
  Particles<2> P;
  NeighborGrid<2> grid;
  NeighborList list;

  explicit StillWater(double stray_height) {
    for (int j = 0; j < 20; ++j)
      for (int i = 0; i < 20; ++i) {
        const std::size_t f = P.add(Vec<2>((i + 0.5) * dp, (j + 0.5) * dp), Kind::fluid, 0, rho, 1e-3);
        P.pressure[f] = rho * g * (H - P.position[f][1]);
      }
    P.add(Vec<2>(10.5 * dp, H + stray_height), Kind::fluid, 0, rho, 1e-3);
    grid = NeighborGrid<2>(Vec<2>(-dp, -dp), Vec<2>(21 * dp, 21 * dp + stray_height), re);
    grid.bin(P.position);
    build_neighbor_list(grid, P.position, re, list);
  }
  bool is_bulk(std::uint32_t b) const { return P.position[b][1] < H - dp; }
  double surface_pressure(std::size_t s) const {
    return extrapolated_surface_pressure<2>(s, P, list, re, Vec<2>(0.0, -g), [&](std::uint32_t b) { return is_bulk(b); });
  }
};

TEST(FreeSurfacePressure, TopRowCarriesTheHeadOfHalfASpacing) {
  const StillWater s(10 * StillWater::dp);
  for (std::size_t i = 0; i < 20; ++i) {
    const std::size_t top = 19 * 20 + i;  // the top row, edge of the water at dp / 2 above it
    const double exact = s.rho * s.g * 0.5 * s.dp;
    EXPECT_NEAR(s.surface_pressure(top), exact, 1e-9 * exact) << i;
  }
}

// half_layer: the head of half a row, the same as the extrapolation gives a flat row of still water on the square
// lattice; on the hexagonal and fcc lattices half their row spacing (0.9306 dp / 2 and 0.7937 dp / 2).
TEST(FreeSurfacePressure, HalfLayerIsTheHeadOfHalfARow) {
  const StillWater s(10 * StillWater::dp);
  const double dp = StillWater::dp;
  const double half_row = half_layer_pressure(s.rho, s.g, row_spacing(LatticeKind::square, dp));
  EXPECT_NEAR(half_row, s.surface_pressure(19 * 20 + 7), 1e-9 * half_row);
  EXPECT_DOUBLE_EQ(half_row, 1000.0 * 9.81 * 0.005);
  EXPECT_NEAR(half_layer_pressure(s.rho, s.g, row_spacing(LatticeKind::hexagonal, dp)),
              0.5 * s.rho * s.g * 0.5 * std::sqrt(3.0) * std::sqrt(2.0 / std::sqrt(3.0)) * dp, 1e-12);
  EXPECT_NEAR(half_layer_pressure(s.rho, s.g, row_spacing(LatticeKind::fcc, dp)),
              0.5 * s.rho * s.g * std::pow(2.0, -1.0 / 3.0) * dp, 1e-12);
}

TEST(FreeSurfacePressure, NoBulkNeighbourOrAboveTheFieldGivesZero) {
  const StillWater far(10 * StillWater::dp);  // a droplet 10 dp above the water: no bulk neighbour within re
  EXPECT_EQ(far.surface_pressure(far.P.size() - 1), 0.0);
  const StillWater near(0.3 * StillWater::dp);  // 0.3 dp above the edge, within re of the bulk: the field there is < 0
  EXPECT_EQ(near.surface_pressure(near.P.size() - 1), 0.0);
}

}  // namespace
}  // namespace slide
