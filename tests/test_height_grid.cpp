// Terrains from height grids (cases/height_grid.hpp) and as walls of a 3-D scene (walls[].type: terrain).
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <set>

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
// particles are the water's lattice below its surface, to re, at their depth (cases/terrain_layers.hpp); the water
// takes the lattice above it, without a hole between them.
TEST(Terrain3D, SlopeIsTheWatersLatticeBelowItsSurface) {
  const auto dir = testing::fresh_directory("terrain_slope");
  const double slope = std::tan(15.0 * M_PI / 180.0), sin15 = std::sin(15.0 * M_PI / 180.0);
  const double cos15 = std::cos(15.0 * M_PI / 180.0), re = 2.1 * 0.01;
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
  const double s = 0.01 * std::pow(2.0, -1.0 / 3.0);  // the fcc's plane spacing
  // Each particle's site on the simple cubic lattice of spacing s: ((i + 1/2) s, (j + 1/2) s, (k + 1/2) s).
  const auto site = [&](const Vec<3>& p) {
    return std::array<long, 3>{std::lround(p[0] / s - 0.5), std::lround(p[1] / s - 0.5), std::lround(p[2] / s - 0.5)};
  };
  std::set<std::array<long, 3>> sites;
  std::size_t terrain = 0, wall_layer = 0;
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    const Vec<3>& p = P.position[i];
    const auto c = site(p);
    // Every particle, water, tank and terrain alike, on the one fcc lattice, each site once.
    ASSERT_NEAR((p - s * Vec<3>(c[0] + 0.5, c[1] + 0.5, c[2] + 0.5)).norm(), 0.0, 1e-12) << p.transpose();
    EXPECT_EQ(((c[0] + c[1] + c[2]) % 2 + 2) % 2, 0) << p.transpose();
    EXPECT_TRUE(sites.insert(c).second) << "two particles at " << p.transpose();
    const double above = (p[2] - height(p)) * cos15;  // distance from the slope's plane, + above
    if (P.kind[i] == Kind::fluid) {
      EXPECT_GT(above, 0.0) << p.transpose();
      continue;
    }
    if (p[0] < 0.0 || p[0] > 0.3 || p[1] < 0.0 || p[1] > 0.1 || p[2] <= 0.0) continue;  // the tank's own
    ++terrain;
    EXPECT_LE(above, 0.0);
    EXPECT_LE(-above, re + 1e-12);
    EXPECT_EQ(P.kind[i] == Kind::wall, -above < s) << p.transpose();  // layer 0: within a plane spacing
    wall_layer += P.kind[i] == Kind::wall;
    // Away from the slope's ends its plane is the nearest surface: the particle carries its true depth and normal.
    if (p[0] > 0.03 && p[0] < 0.27) {
      EXPECT_NEAR(P.wall_depth[i], -above, 1e-12);
      EXPECT_NEAR(P.wall_normal[i].dot(Vec<3>(-sin15, 0.0, cos15)), 1.0, 1e-12);
    }
  }
  // The lattice has no hole where water meets the terrain: every water particle more than two planes below the water's
  // surface has all its 12 nearest sites taken (by water, the terrain or the tank).
  std::size_t checked = 0;
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    if (P.kind[i] != Kind::fluid || P.position[i][2] > 0.1 - 2.0 * s) continue;
    const auto c = site(P.position[i]);
    for (int a = 0; a < 3; ++a)
      for (const int u : {-1, 1})
        for (const int v : {-1, 1}) {
          auto n = c;
          n[(a + 1) % 3] += u;
          n[(a + 2) % 3] += v;
          EXPECT_TRUE(sites.count(n)) << "a hole beside the water particle at " << P.position[i].transpose();
        }
    ++checked;
  }
  EXPECT_GT(checked, 800u);
  // The terrain's particles fill the band re deep under 0.3 m x 0.1 m of slope, one per dp^3: 0.3 / cos15 x 0.1 x re /
  // dp^3 = 652 (676 built); the wall layer a plane spacing deep, 246 (253 built); the lattice's steps make the rest.
  EXPECT_NEAR(double(terrain), 0.3 / cos15 * 0.1 * re / 1e-6, 0.05 * 652);
  EXPECT_NEAR(double(wall_layer), 0.3 / cos15 * 0.1 * s / 1e-6, 0.05 * 246);
}

// Where the terrain runs into a tank: a tank whose min x face lies on a plane of lattice points (x = s/2: its own wall
// points there), a grid wider than the tank and reaching below its floor, the terrain listed before the tank. Every
// particle on its own site; the terrain's strictly inside the tank.
TEST(Terrain3D, MeetsATankOnTheLatticeWithoutDoubledParticles) {
  const auto dir = testing::fresh_directory("terrain_tank_meet");
  const double s = 0.01 * std::pow(2.0, -1.0 / 3.0);
  testing::write_file(dir / "slope.csv", "y\\x,-0.1,0.4\n-0.1,0.03,-0.02\n0.2,0.03,-0.02\n");
  testing::write_file(dir / "s.yaml", fmt::format(R"(dimension: 3
particle_spacing: 0.01
end_time: 0.01
method: {{initial_state: lattice}}
fluid:
  phases: [{{name: water, density: 1000}}]
  regions: [{{type: below_level, level: 0.1}}]
walls:
  - {{name: slope, type: terrain, file: slope.csv}}
  - {{type: tank, min: [{}, 0, 0], max: [0.3, 0.1, 0.2]}}
)", 0.5 * s));
  const auto scene = build_scene<3>(load_scene(dir / "s.yaml", {}), "s", dir);
  const auto& P = scene->simulation->particles();
  std::set<std::array<long, 3>> sites;
  std::size_t tank_face = 0;
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    const Vec<3>& p = P.position[i];
    EXPECT_TRUE(sites.insert({std::lround(p[0] / s - 0.5), std::lround(p[1] / s - 0.5), std::lround(p[2] / s - 0.5)}).second)
        << "two particles at " << p.transpose();
    tank_face += P.kind[i] != Kind::fluid && std::abs(p[0] - 0.5 * s) < 1e-12 && p[2] > 0.0;
  }
  EXPECT_GT(tank_face, 0u);  // the face's own points are there, once
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
