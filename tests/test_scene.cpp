// Scenes: the schema document is current, shipped scenes build what they say, region types fill as documented.
#include <gtest/gtest.h>

#include "tests/cli_helpers.hpp"
#include "tests/scene_runner.hpp"

namespace slide::testing {
namespace {

TEST(Scene, SchemaDocumentIsCurrent) {
  const std::string generated = cases::scene_schema().document("slide scene reference");
  EXPECT_EQ(read_file(source_dir() / "cases/SCHEMA.md"), generated)
      << "cases/SCHEMA.md is stale: regenerate it with build/slide schema > cases/SCHEMA.md";
}

TEST(Scene, ShippedScenesBuild) {
  auto tank = load_shipped_scene("hydrostatic_2d.yaml", {"method.initial_state=hydrostatic"});
  EXPECT_EQ(tank->fluid_count, 5000u);  // 1 m x 0.5 m at dp = 0.01 m
  EXPECT_NEAR(tank->simulation->options.sound_speed, 10.0 * std::sqrt(9.81 * 0.5), 1e-9);
  EXPECT_TRUE(tank->equilibrium.has_value());
  auto bench = load_shipped_scene("dam_break_bench_2d.yaml");
  EXPECT_EQ(bench->fluid_count, 20000u);
  EXPECT_NEAR(bench->deepest_water, 2.0, 1e-9);
  auto block = load_shipped_scene("floating_block_2d.yaml", {"method.initial_state=hydrostatic"});
  EXPECT_EQ(block->fluid_count, 2900u);  // 100 x 30 lattice points less the block's 20 x 5 below the level
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
method: {sound_speed: 5, initial_state: lattice}
fluid:
  phases: [{name: water}]
  regions: [{type: polygon, points: [[0, 0], [1, 0], [0, 1]]}]
)");
  auto scene = cases::build_scene(cases::load_scene(dir / "s.yaml", {}), "s");
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
    cases::build_scene(cases::load_scene(dir / "s.yaml", {}), "s");
    FAIL() << "expected a SceneError";
  } catch (const cases::SceneError& e) {
    EXPECT_EQ(e.key_path, "fluid.regions[0].phase");
  }
}

}  // namespace
}  // namespace slide::testing
