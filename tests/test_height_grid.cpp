// Terrains from height grids (cases/height_grid.hpp) and as walls of a 3-D scene (walls[].type: terrain).
#include <map>
#include <gtest/gtest.h>

#include <cmath>

#include "cases/height_grid.hpp"
#include "cases/scene.hpp"
#include "coupling/rigid_bodies.hpp"
#include "tests/cli_helpers.hpp"

namespace slide::cases {
namespace {

// z = 0.1 + 0.2 x - 0.05 y on x = 0, 0.5, 1.5 and y = -1, 0, 2: planar, so the triangles hold it exactly.
double plane(double x, double y) { return 0.1 + 0.2 * x - 0.05 * y; }

std::string csv_of_plane() {
  std::string s = "y\\x,0,0.5,1.5\n";
  for (const double y : {-1.0, 0.0, 2.0}) {
    s += fmt::format("{}", y);
    for (const double x : {0.0, 0.5, 1.5}) s += fmt::format(",{}", plane(x, y));
    s += "\n";
  }
  return s;
}

TEST(HeightGrid, CsvAndEsriGridsReadTheSameSurfaceExactlyOnAPlane) {
  const auto dir = testing::fresh_directory("height_grid");
  testing::write_file(dir / "plane.csv", csv_of_plane());
  const HeightGrid g = read_height_grid(dir / "plane.csv");
  ASSERT_EQ(g.x.size(), 3u);
  ASSERT_EQ(g.y.size(), 3u);
  for (double x = 0.0; x <= 1.5; x += 0.0937)
    for (double y = -1.0; y <= 2.0; y += 0.1131) ASSERT_NEAR(terrain_height(g, x, y), plane(x, y), 1e-14);
  EXPECT_TRUE(std::isnan(terrain_height(g, -0.01, 0.0)));
  EXPECT_TRUE(std::isnan(terrain_height(g, 0.5, 2.01)));
  // The same kind of plane on an ESRI grid: cell centres from xllcorner + cellsize / 2, the first row the largest y.
  std::string asc = "ncols 4\nnrows 3\nxllcorner -0.25\nyllcorner 0.75\ncellsize 0.5\nNODATA_value -9999\n";
  for (int r = 0; r < 3; ++r) {
    const double y = 1.0 + 0.5 * (2 - r);
    for (int i = 0; i < 4; ++i) asc += fmt::format("{} ", plane(0.5 * i, y));
    asc += "\n";
  }
  testing::write_file(dir / "plane.asc", asc);
  const HeightGrid e = read_height_grid(dir / "plane.asc");
  ASSERT_EQ(e.x.size(), 4u);
  EXPECT_NEAR(e.x[0], 0.0, 1e-15);
  EXPECT_NEAR(e.y[2], 2.0, 1e-15);
  for (double x = 0.0; x <= 1.5; x += 0.0937)
    for (double y = 1.0; y <= 2.0; y += 0.0731) ASSERT_NEAR(terrain_height(e, x, y), plane(x, y), 1e-14);
  // The surface faces up and covers the grid's area (its projection).
  const rigid::TriangleSurface s = terrain_surface(g);
  double projected = 0.0;
  for (const auto& t : s.triangles) {
    const rigid::Vec3 n = (s.vertices[t[1]] - s.vertices[t[0]]).cross(s.vertices[t[2]] - s.vertices[t[0]]);
    EXPECT_GT(n[2], 0.0);
    projected += 0.5 * n[2];
  }
  EXPECT_NEAR(projected, 1.5 * 3.0, 1e-12);
}

TEST(HeightGrid, RefusesWhatIsWrongSayingWhere) {
  const auto dir = testing::fresh_directory("height_grid_bad");
  const auto what = [&](const std::string& name, const std::string& text) {
    testing::write_file(dir / name, text);
    try {
      read_height_grid(dir / name);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_NE(what("a.csv", "y\\x,0,1\n0,1,1\n1,1\n").find("line 3 has 2 cells"), std::string::npos);
  EXPECT_NE(what("b.csv", "y\\x,1,0\n0,1,1\n1,1,1\n").find("x values must increase"), std::string::npos);
  EXPECT_NE(what("c.csv", "y\\x,0,1\n0,1,x\n1,1,1\n").find("line 2, column 3: 'x' is not a number"), std::string::npos);
  EXPECT_NE(what("d.asc", "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\nNODATA_value -9999\n1 -9999\n1 1\n")
                .find("row 1, value 2 is no data"),
            std::string::npos);
  EXPECT_NE(what("e.asc", "ncols 2\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 1\n1\n").find("the file ends"),
            std::string::npos);
  EXPECT_NE(what("f.txt", "").find(".csv or .asc"), std::string::npos);
}

// A 15 degree slope (z = 0.02 + tan(15) x) across a 0.3 m x 0.1 m tank, water to 0.1 m above it (fcc): the terrain's
// particles lie below its surface at their depth, its wall layer half a (111) plane spacing h = 0.9165 dp down, one
// point per column and row of its lattice (cases/terrain_layers.hpp); the water stands above it, h/2 clear.
TEST(Terrain3D, SlopeHoldsItsLayersBelowAndTheWaterAbove) {
  const auto dir = testing::fresh_directory("terrain_slope");
  const double slope = std::tan(15.0 * M_PI / 180.0);
  testing::write_file(dir / "slope.csv", fmt::format("y\\x,0,0.3\n0,0.02,{0}\n0.1,0.02,{0}\n", 0.02 + 0.3 * slope));
  testing::write_file(dir / "s.yaml", R"(dimension: 3
particle_spacing: 0.01
end_time: 0.01
method: {initial_state: lattice}
fluid:
  phases: [{name: water, density: 1000}]
  regions: [{type: below_level, level: 0.1}]
walls:
  - {type: tank, min: [0, 0, 0], max: [0.3, 0.1, 0.2]}
  - {name: slope, type: terrain, file: slope.csv}
)");
  const auto scene = build_scene<3>(load_scene(dir / "s.yaml", {}), "s", dir);
  const auto& P = scene->simulation->particles();
  const auto height = [&](const Vec<3>& p) { return 0.02 + slope * p[0]; };
  const double cos15 = std::cos(15.0 * M_PI / 180.0);
  const double h = std::sqrt(2.0) * std::pow(2.0, -1.0 / 3.0) * 0.01 * std::sqrt(2.0 / 3.0);  // fcc (111) spacing
  std::size_t wall_layer = 0, fluid = 0;
  std::map<long, std::pair<double, double>> row_ends;  // the wall layer's rows (by y in microns): least and most x
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    const Vec<3>& p = P.position[i];
    const double above = (p[2] - height(p)) * cos15;  // distance from the slope's plane, + above
    if (P.kind[i] == Kind::fluid) {
      ++fluid;
      EXPECT_GE(above, 0.5 * h - 1e-9) << p.transpose();
      continue;
    }
    if (p[0] < 0.0 || p[0] > 0.3 || p[1] < 0.0 || p[1] > 0.1 || p[2] <= 0.0) continue;  // the tank's own
    EXPECT_LT(above, 0.0);
    if (std::abs(p[0] - 0.15) < 0.1) {  // away from the slope's ends, the plane is the nearest surface
      EXPECT_NEAR(P.wall_depth[i], -above, 1e-12);
      EXPECT_NEAR(P.wall_normal[i].dot(Vec<3>(-std::sin(15.0 * M_PI / 180.0), 0.0, cos15)), 1.0, 1e-12);
    }
    if (P.kind[i] != Kind::wall) continue;
    ++wall_layer;
    // On an edge, a point moved down the normal out of the grid is moved back onto it: its depth changes by that
    // shift (h/2 sin 15) times sin 15.
    const double edge_shift = 0.5 * h * std::pow(std::sin(15.0 * M_PI / 180.0), 2);
    EXPECT_NEAR(-above, 0.5 * h, p[0] > 0.0 && p[0] < 0.3 ? 1e-12 : edge_shift + 1e-12);
    auto [it, fresh] = row_ends.try_emplace(std::lround(p[1] * 1e6), p[0], p[0]);
    it->second = {std::min(it->second.first, p[0]), std::max(it->second.second, p[0])};
  }
  // Whole numbers of columns and rows across the grid at the spacing a sqrt(cos 15) (a = 1.1225 dp): 27 columns of
  // 0.3 m over 1.103 dp, 10 rows of 0.1 m over 0.955 dp; one point each in the wall layer.
  const double spacing = h * std::sqrt(1.5) * std::sqrt(cos15);
  const long columns = std::lround(0.3 / spacing), rows = std::lround(0.1 / (0.5 * std::sqrt(3.0) * spacing));
  EXPECT_EQ(columns * rows, 270);
  // Odd rows start and end on the grid's edges: one point more each (the 5 odd rows' edge points at x = 0.3 were lost
  // to rounding and those at x = 0, moved down the slope's normal out of the grid, were dropped before stop 44).
  EXPECT_EQ(long(wall_layer), columns * rows + rows / 2);
  // No row leaves more than half a column free at either end, beyond the layer's shift down the slope's normal along x
  // (its depth h/2 times sin 15): water would run down under the terrain through it.
  const double column = 0.3 / double(columns), shift = 0.5 * h * std::sin(15.0 * M_PI / 180.0);
  ASSERT_EQ(long(row_ends.size()), rows);
  for (const auto& [y, ends] : row_ends) {
    EXPECT_LE(ends.first, 0.5 * column + shift + 1e-12) << "row at y = " << y * 1e-6 << " m";
    EXPECT_GE(ends.second, 0.3 - 0.5 * column - shift - 1e-12) << "row at y = " << y * 1e-6 << " m";
  }
  EXPECT_GT(fluid, 1000u);
}

TEST(Terrain3D, AMissingOrBadGridIsRefusedNamingTheKeyAndTheFile) {
  const auto dir = testing::fresh_directory("terrain_bad");
  testing::write_file(dir / "bad.csv", "y\\x,0,0.3\n0,0.02\n");
  const auto message = [&](const std::string& file) {
    try {
      build_scene<3>(load_scene_text("dimension: 3\nparticle_spacing: 0.01\nend_time: 0.01\n"
                                     "fluid: {phases: [{name: water}], regions: [{type: below_level, level: 0.1}]}\n"
                                     "walls: [{type: tank, min: [0, 0, 0], max: [0.3, 0.1, 0.2]}, {type: terrain, file: " +
                                         file + "}]\n",
                                     {}),
                     "s", dir);
    } catch (const SceneError& e) {
      return e.key_path + ": " + e.what();
    }
    return std::string("(accepted)");
  };
  EXPECT_NE(message("none.csv").find("walls[1].file"), std::string::npos) << message("none.csv");
  EXPECT_NE(message("none.csv").find("none.csv: no such file"), std::string::npos) << message("none.csv");
  EXPECT_NE(message("bad.csv").find("bad.csv: line 2 has 2 cells"), std::string::npos) << message("bad.csv");
}

}  // namespace
}  // namespace slide::cases
