// Boundary-particle pressure (fluid/wall_pressure.hpp): both models continue a hydrostatic field exactly into a wall,
// along g - a_w when the wall accelerates.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "fluid/image_neighbours.hpp"
#include "fluid/wall_pressure.hpp"

namespace slide {
namespace {

// Water on the lattice x = (i + 1/2) dp, y = (j + 1/2) dp above a floor at y = 0, carrying the hydrostatic pressure
// of the effective downward acceleration `head` (p = rho head (H - y)), and two wall particles with their normals
// up: one in the first layer, half a spacing below the floor, and one in the third layer, whose mirror image lies
// among a complete neighbourhood (where a Shepard interpolation of a linear field is exact).
struct FloorWithWater {
  static constexpr double dp = 0.01, rho = 1000.0, top = 0.2, re = 2.1 * dp;
  Particles<2> P;
  std::size_t first_layer = 0, third_layer = 0;
  NeighborGrid<2> grid;
  NeighborList list;

  explicit FloorWithWater(double head) {
    for (int j = 0; j < 20; ++j)
      for (int i = 0; i < 20; ++i) {
        const std::size_t f = P.add(Vec<2>((i + 0.5) * dp, (j + 0.5) * dp), Kind::fluid, 0, rho, 1e-3);
        P.pressure[f] = rho * head * (top - P.position[f][1]);
      }
    for (const int layer : {0, 2}) {
      const std::size_t w = P.add(Vec<2>(10.5 * dp, -(layer + 0.5) * dp), Kind::wall, 0, rho, 1e-3);
      P.wall_normal[w] = Vec<2>(0.0, 1.0);
      P.wall_depth[w] = (layer + 0.5) * dp;
      (layer == 0 ? first_layer : third_layer) = w;
    }
    grid = NeighborGrid<2>(Vec<2>(-dp, -3 * dp), Vec<2>(21 * dp, 21 * dp), re);
    grid.bin(P.position);
    build_neighbor_list(grid, P.position, re, list);
  }
  // The hydrostatic field continued to particle w.
  double exact(std::size_t w, double head) const { return rho * head * (top - P.position[w][1]); }
};

// The wall accelerates upwards at 3 m/s^2 into the water: the water's effective gravity is g + 3 downwards, and the
// wall's pressure must continue that field, not the one of g alone.
constexpr double g = 9.81, lift = 3.0;

TEST(WallPressure, MirrorContinuesTheHydrostaticFieldOfTheWallsFrame) {
  for (const double a : {0.0, lift}) {
    FloorWithWater s(g + a);
    const Vec<2> head_acceleration = Vec<2>(0.0, -g) - Vec<2>(0.0, a);
    const double exact = s.exact(s.third_layer, g + a);
    EXPECT_NEAR(mirror_wall_pressure<2>(s.third_layer, s.P, s.grid, s.dp, head_acceleration), exact, 1e-9 * exact)
        << a;
  }
  // Ignoring the wall's acceleration misses the head between particle and image (5 dp) by rho a 5 dp.
  FloorWithWater s(g + lift);
  EXPECT_NEAR(s.exact(s.third_layer, g + lift) - mirror_wall_pressure<2>(s.third_layer, s.P, s.grid, s.dp, Vec<2>(0.0, -g)),
              s.rho * lift * 5 * s.dp, 1e-9);
}

TEST(WallPressure, ExtrapolatedContinuesTheHydrostaticFieldOfTheWallsFrame) {
  for (const double a : {0.0, lift}) {
    FloorWithWater s(g + a);
    const Vec<2> head_acceleration = Vec<2>(0.0, -g) - Vec<2>(0.0, a);
    const double exact = s.exact(s.first_layer, g + a);
    EXPECT_NEAR(extrapolated_wall_pressure<2>(s.first_layer, s.P, s.list, s.re, head_acceleration), exact, 1e-9 * exact) << a;
  }
}

// The wall pressure from the image's fluid neighbours that the mirror fill kept (fluid/image_neighbours.hpp, as the
// step uses it) is the grid search's to the bit, and the fill is the plain mirror_fill's: every boundary particle of
// a disordered floor with water above, some images among the water and some beside it.
TEST(WallPressure, KeptImageNeighboursGiveTheGridSearchsPressureAndFill) {
  FloorWithWater s(g);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> jitter(-0.2 * s.dp, 0.2 * s.dp);
  for (int i = 0; i < 20; ++i)
    for (const int layer : {0, 1, 2}) {
      const std::size_t w = s.P.add(Vec<2>((i + 0.5) * s.dp + jitter(rng), -(layer + 0.5) * s.dp), Kind::wall, 0,
                                    s.rho, 1e-3);
      s.P.wall_normal[w] = Vec<2>(0.0, 1.0);
      s.P.wall_depth[w] = (layer + 0.5) * s.dp;
    }
  for (std::size_t f = 0; f < s.P.size(); ++f)
    if (s.P.kind[f] == Kind::fluid) s.P.position[f] += Vec<2>(jitter(rng), jitter(rng));
  s.grid.bin(s.P.position);
  build_neighbor_list(s.grid, s.P.position, s.re, s.list);
  ImageNeighbours images;
  std::vector<double> fill(s.P.size(), -1.0);
  images.take(s.P.size(), [&](std::size_t i, auto&& keep) {
    if (s.P.kind[i] == Kind::fluid) return false;
    fill[i] = mirror_fill<2>(i, s.P, s.grid, s.list, s.dp, keep);
    return true;
  });
  const Vec<2> head_acceleration(0.0, -g);
  std::vector<double> read(s.P.size(), -1.0);
  std::size_t kept = 0;
  images.for_each([&](std::size_t w, const ImageNeighbour* begin, const ImageNeighbour* end) {
    read[w] = mirror_wall_pressure<2>(w, s.P, begin, end, head_acceleration);
#pragma omp atomic
    kept += end - begin;
  });
  std::size_t walls = 0;
  for (std::size_t w = 0; w < s.P.size(); ++w) {
    if (s.P.kind[w] == Kind::fluid) {
      EXPECT_EQ(read[w], -1.0) << "a fluid particle has no image: " << w;
      continue;
    }
    ++walls;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(fill[w]), std::bit_cast<std::uint64_t>(mirror_fill<2>(w, s.P, s.grid, s.list, s.dp)));
    const double searched = mirror_wall_pressure<2>(w, s.P, s.grid, s.dp, head_acceleration);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(read[w]), std::bit_cast<std::uint64_t>(searched)) << w;
    EXPECT_GT(read[w], 0.0) << w;
  }
  EXPECT_EQ(walls, 62u);
  EXPECT_GT(kept, 5 * walls);
}

}  // namespace
}  // namespace slide
