// Scenes: the schema document is current, shipped scenes build what they say, region types fill as documented.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>

#include <fmt/format.h>

#include "fluid/lattice.hpp"
#include "tests/cli_helpers.hpp"
#include "tests/scene_runner.hpp"

namespace slide::testing {
namespace {

TEST(Scene, SchemaDocumentIsCurrent) {
  const std::string generated = cases::scene_reference();
  EXPECT_EQ(read_file(source_dir() / "cases/SCHEMA.md"), generated)
      << "cases/SCHEMA.md is stale: regenerate it with build/slide schema > cases/SCHEMA.md";
}

TEST(Scene, ShippedScenesBuild) {
  auto square_tank = load_shipped_scene("hydrostatic_2d.yaml", {"lattice=square", "method.wall_pressure=mirror",
                                                                 "method.initial_state=hydrostatic"});
  EXPECT_EQ(square_tank->fluid_count, 5000u);  // 1 m x 0.5 m at dp = 0.01 m
  EXPECT_NEAR(square_tank->simulation->options.sound_speed, 10.0 * std::sqrt(9.81 * 0.5), 1e-9);
  EXPECT_TRUE(square_tank->equilibrium.has_value());
  // The shipped tank is hexagonal: rows h = 0.9306 dp apart with centres below the level (54 rows, 0.5025 m of
  // water), 93 points in front of the side walls in every row (x = 0.54 dp .. 999.4 mm in even rows, 1.07 dp ..
  // 993.8 mm in odd ones; the odd rows' point at x = 0 is the left wall's).
  auto tank = load_shipped_scene("hydrostatic_2d.yaml", {"method.initial_state=lattice"});
  const double h = row_spacing(LatticeKind::hexagonal, 0.01);
  EXPECT_EQ(tank->fluid_count, 54u * 93u);
  EXPECT_NEAR(tank->deepest_water, 54 * h, 1e-12);
  EXPECT_NEAR(tank->simulation->options.sound_speed, 10.0 * std::sqrt(9.81 * 54 * h), 1e-9);
  EXPECT_EQ(tank->simulation->options.lattice, LatticeKind::hexagonal);
  auto bench = load_shipped_scene("dam_break_bench_2d.yaml");
  EXPECT_EQ(bench->fluid_count, 20000u);
  EXPECT_NEAR(bench->deepest_water, 2.0, 1e-9);
  // On the square lattice at dp = 0.01: 100 x 30 lattice points less the block's 20 x 5 below the level.
  auto block = load_shipped_scene("floating_block_2d.yaml",
                                  {"lattice=square", "particle_spacing=0.01", "method.wall_pressure=mirror",
                                   "method.initial_state=hydrostatic", "bodies[0].during_settling=held"});
  EXPECT_EQ(block->fluid_count, 2900u);
  ASSERT_EQ(block->bodies.size(), 1u);
  EXPECT_NEAR(block->bodies[0].mass, 10.0, 1e-12);
  EXPECT_NEAR(block->bodies[0].buoyancy_ratio, 1.0, 1e-12);
  auto dam = load_shipped_scene("dam_break_2d.yaml");
  EXPECT_EQ(dam->fluid_count, 800u);  // a/20 by 2a/20
  EXPECT_TRUE(dam->surge_front.enabled);
}

TEST(Scene, PolygonRegionAndExplicitSoundSpeed) {
  const auto dir = fresh_directory("polygon");
  write_file(dir / "s.yaml", R"(particle_spacing: 0.1
end_time: 1
gravity: [0, 0]
lattice: square
method: {sound_speed: 5, initial_state: lattice}
fluid:
  phases: [{name: water}]
  regions: [{type: polygon, points: [[0, 0], [1, 0], [0, 1]]}]
)");
  auto scene = cases::build_scene<2>(cases::load_scene(dir / "s.yaml", {}), "s");
  // Lattice points (i + 1/2) dp strictly inside the triangle x + y < 1: i + j < 9, i.e. 45 of them.
  EXPECT_EQ(scene->fluid_count, 45u);
  EXPECT_EQ(scene->sound_speed_source, "method.sound_speed");
  EXPECT_DOUBLE_EQ(scene->simulation->options.sound_speed, 5.0);
}

TEST(Scene, UnknownPhaseIsNamed) {
  const auto dir = fresh_directory("phase");
  write_file(dir / "s.yaml", R"(particle_spacing: 0.1
end_time: 1
fluid:
  phases: [{name: water}]
  regions: [{type: rectangle, phase: mud, min: [0, 0], max: [1, 1]}]
)");
  try {
    cases::build_scene<2>(cases::load_scene(dir / "s.yaml", {}), "s");
    FAIL() << "expected a SceneError";
  } catch (const cases::SceneError& e) {
    EXPECT_EQ(e.key_path, "fluid.regions[0].phase");
  }
}

// What the hexagonal lattice cannot do yet is refused, naming the key, before anything runs.
TEST(Scene, HexagonalLatticeRefusesWhatItCannotDo) {
  const auto dir = fresh_directory("hexagonal");
  const std::string tank = R"(particle_spacing: 0.1
end_time: 1
lattice: hexagonal
fluid:
  phases: [{name: water}]
  regions: [{type: below_level, level: 0.5}]
walls: [{points: [[0, 1], [0, 0], [1, 0], [1, 1]]}]
)";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"method: {wall_pressure: mirror, initial_state: lattice}\n", "method.wall_pressure"},
      {"method: {initial_state: hydrostatic}\n", "method.initial_state"},
  };
  for (const auto& [extra, key] : cases) {
    write_file(dir / "s.yaml", tank + extra);
    try {
      cases::build_scene<2>(cases::load_scene(dir / "s.yaml", {}), "s");
      ADD_FAILURE() << "expected a SceneError for " << key;
    } catch (const cases::SceneError& e) {
      EXPECT_EQ(e.key_path, key);
    }
  }
  write_file(dir / "s.yaml", tank + "method: {wall_pressure: extrapolated, initial_state: lattice}\n");
  try {
    cases::build_scene<2>(cases::load_scene(dir / "s.yaml", {"walls[0].layers=3"}), "s");
    ADD_FAILURE() << "expected a SceneError for walls[0].layers";
  } catch (const cases::SceneError& e) {
    EXPECT_EQ(e.key_path, "walls[0].layers");
  }
  // Accepted as it stands: 5 rows (centres (j + 1/2) 0.9306 dp below 0.5 m) of 9 points (x = (i + 1/2) a in even
  // rows, (i + 1) a in odd ones, a = 0.10746 m, below x = 1 m).
  auto scene = cases::build_scene<2>(cases::load_scene(dir / "s.yaml", {}), "s");
  EXPECT_EQ(scene->fluid_count, 5u * 9u);
}

// A periodic domain's period holds a whole number of lattice columns (to 0.1 % of one), or the scene is refused
// naming domain.max and giving the nearest whole periods exactly; then the layer and its floor join across the seam:
// every row holds the same number of points, and no two particles (periodic images included) stand closer than a
// spacing, also where the period is a whole number to within 5e-4 columns only, either way.
TEST(Scene, PeriodicDomainJoinsTheLatticeAcrossItsSeam) {
  const double dp = 0.01, a = nearest_spacing(LatticeKind::hexagonal, dp);
  auto layer = [](double period) {
    return fmt::format(R"(particle_spacing: 0.01
end_time: 1
lattice: hexagonal
domain: {{min: [0, -0.05], max: [{p:.17g}, 0.3], periodic_x: true}}
fluid:
  phases: [{{name: water}}]
  regions: [{{type: rectangle, min: [0, 0], max: [{p:.17g}, 0.1]}}]
method: {{initial_state: lattice}}
walls:
  - {{name: floor, points: [[-0.05, 0], [{end:.17g}, 0]]}}
)",
                       fmt::arg("p", period), fmt::arg("end", period + 0.05));
  };
  const auto dir = fresh_directory("periodic_seam");
  write_file(dir / "s.yaml", layer(0.2));  // 18.61 columns
  try {
    cases::build_scene<2>(cases::load_scene(dir / "s.yaml", {}), "s");
    ADD_FAILURE() << "expected a SceneError for domain.max";
  } catch (const cases::SceneError& e) {
    EXPECT_EQ(e.key_path, "domain.max");
    EXPECT_NE(e.message.find("whole number of columns"), std::string::npos) << e.message;
    EXPECT_NE(e.message.find(fmt::format("{:.17g}", 19.0 * a)), std::string::npos) << e.message;
  }
  // A wall with no point in the period is refused, naming it.
  write_file(dir / "w.yaml", layer(19.0 * a) + "  - {name: outside, points: [[0.3, 0], [0.3, 0.2]]}\n");
  try {
    cases::build_scene<2>(cases::load_scene(dir / "w.yaml", {}), "w");
    ADD_FAILURE() << "expected a SceneError for walls[1].points";
  } catch (const cases::SceneError& e) {
    EXPECT_EQ(e.key_path, "walls[1].points");
  }
  for (const double columns : {19.0, 19.0005, 18.9995}) {
    const double period = columns * a;
    auto scene = build_scene_text("periodic_seam", layer(period));
    const auto& P = scene->simulation->particles();
    std::map<long, int> per_row;  // row index -> points (fluid and wall alike)
    double closest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < P.real_count(); ++i) {
      EXPECT_GE(P.position[i][0], 0.0);
      EXPECT_LT(P.position[i][0], period);
      ++per_row[std::lround(P.position[i][1] / row_spacing(LatticeKind::hexagonal, dp) - 0.5)];
      for (std::size_t j = 0; j < i; ++j) {
        Vec<2> d = P.position[i] - P.position[j];
        d[0] -= period * std::round(d[0] / period);
        closest = std::min(closest, d.norm());
      }
    }
    EXPECT_NEAR(closest, a, 5e-4 * a + 1e-9 * dp) << columns << " columns";
    for (const auto& [row, count] : per_row) EXPECT_EQ(count, 19) << "row " << row << ", " << columns << " columns";
    EXPECT_EQ(scene->fluid_count, 19u * 11u);  // rows 0.9306 dp apart from 0.465 dp: 11 below 0.1 m
  }
}

// With a body on the hexagonal lattice the rows are moved so that the water under the body starts dp / 2 below its
// bottom, as on the square lattice (a wider gap could not close under a held body).
TEST(Scene, HexagonalRowsMeetTheFirstBodysBottom) {
  const auto dir = fresh_directory("hexagonal_body");
  write_file(dir / "s.yaml", R"(particle_spacing: 0.01
end_time: 1
lattice: hexagonal
fluid:
  phases: [{name: water}]
  regions: [{type: below_level, level: 0.3}]
walls: [{points: [[0, 0.5], [0, 0], [1, 0], [1, 0.5]]}]
bodies: [{name: b, shape: {type: box, center: [0.5, 0.3], size: [0.2, 0.1]}, density: 500}]
method: {wall_pressure: extrapolated, initial_state: lattice}
)");
  const auto scene = cases::build_scene<2>(cases::load_scene(dir / "s.yaml", {}), "s");
  const double dp = 0.01, h = row_spacing(LatticeKind::hexagonal, dp);
  EXPECT_LE(std::abs(scene->lattice_offset[1]), 0.5 * h + 1e-15);
  const auto& P = scene->simulation->particles();
  double highest_below = -1.0;
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.kind[i] == Kind::fluid && std::abs(P.position[i][0] - 0.5) < 0.1 && P.position[i][1] < 0.25)
      highest_below = std::max(highest_below, P.position[i][1]);
  EXPECT_NEAR(highest_below, 0.25 - 0.5 * dp, 1e-12);
}

TEST(Scene, FloatingWhileSettlingNeedsAFreeBodyAndASettledStart) {
  const auto dir = fresh_directory("during_settling");
  const std::string base = R"(particle_spacing: 0.05
end_time: 1
fluid:
  phases: [{name: water}]
  regions: [{type: below_level, level: 0.5}]
walls: [{points: [[0, 1], [0, 0], [1, 0], [1, 1]]}]
bodies: [{name: b, shape: {type: box, center: [0.5, 0.5], size: [0.2, 0.2]}, density: 500, during_settling: free}]
lattice: square
)";
  for (const auto& [extra, overrides] : std::vector<std::pair<std::string, std::vector<std::string>>>{
           {"method: {initial_state: hydrostatic}\n", {}},
           {"method: {initial_state: settled, settling_time: 0.1}\n", {"bodies[0].release_time=0.5"}}}) {
    write_file(dir / "s.yaml", base + extra);
    try {
      cases::build_scene<2>(cases::load_scene(dir / "s.yaml", overrides), "s");
      ADD_FAILURE() << "expected a SceneError for " << extra;
    } catch (const cases::SceneError& e) {
      EXPECT_EQ(e.key_path, "bodies[0].during_settling");
    }
  }
}

// Every scene in cases/ reads and builds (with a short settling where it settles): a shipped case is never broken.
TEST(Scene, EveryShippedCaseBuilds) {
  int built = 0;
  for (const auto& entry : std::filesystem::directory_iterator(source_dir() / "cases")) {
    if (entry.path().extension() != ".yaml") continue;
    const std::string name = entry.path().filename().string();
    try {
      const std::vector<std::string> short_settling{"method.settling_time=0.01"};
      const auto resolved = cases::load_scene(entry.path(), short_settling);
      const std::size_t fluid = cases::scene_dimension(resolved) == 3
                                    ? load_shipped_scene<3>(name, short_settling)->fluid_count
                                    : load_shipped_scene<2>(name, short_settling)->fluid_count;
      EXPECT_GT(fluid, 0u) << name;
      ++built;
    } catch (const std::exception& e) {
      ADD_FAILURE() << name << ": " << e.what();
    }
  }
  EXPECT_GE(built, 10);
}


// processes.rebalance_imbalance reaches the domain's options (Simulation::prepare_processes hands it on), and a factor
// of 1 or less, which would share the cells anew at every re-sort, is refused naming the key.
TEST(Scene, TheRebalanceFactorReachesTheOptionsAndMustExceedOne) {
  EXPECT_EQ(load_shipped_scene<2>("dam_break_2d.yaml")->simulation->options.rebalance_imbalance, 1.25);
  EXPECT_EQ(load_shipped_scene<2>("dam_break_2d.yaml", {"processes.rebalance_imbalance=2"})
                ->simulation->options.rebalance_imbalance,
            2.0);
  EXPECT_EQ(load_shipped_scene<3>("dam_break_3d.yaml", {"processes.rebalance_imbalance=1.5"})
                ->simulation->options.rebalance_imbalance,
            1.5);
  try {
    load_shipped_scene<2>("dam_break_2d.yaml", {"processes.rebalance_imbalance=1"});
    FAIL() << "expected a SceneError";
  } catch (const cases::SceneError& e) {
    EXPECT_EQ(e.key_path, "processes.rebalance_imbalance");
  }
}

}  // namespace
}  // namespace slide::testing
