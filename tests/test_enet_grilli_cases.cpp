// The two Enet & Grilli (2007) scenes: the slide moved by the measured law (enet_grilli_slide_3d.yaml) and let go on
// its rail (enet_grilli_slide_rail_3d.yaml) differ in how the slide moves and nothing else.
#include <gtest/gtest.h>

#include <string>

#include "cases/scene.hpp"
#include "tests/cli_helpers.hpp"

namespace slide::testing {
namespace {

// A resolved scene without the keys that say how its first body moves, as text.
std::string without_the_slides_motion(const std::filesystem::path& file) {
  YAML::Node r = cases::load_scene(file, {});
  r.remove("description");
  YAML::Node body = r["bodies"][0];
  for (const char* key : {"motion", "prescribed", "rail"}) body.remove(key);
  YAML::Emitter out;
  out << r;
  return out.c_str();
}

TEST(EnetGrilliCases, TheRailSceneIsThePrescribedOneButForTheSlidesMotion) {
  const auto cases = source_dir() / "cases";
  const YAML::Node rail = cases::load_scene(cases / "enet_grilli_slide_rail_3d.yaml", {});
  EXPECT_EQ(rail["bodies"][0]["motion"].as<std::string>(), "rail");
  EXPECT_EQ(rail["bodies"][0]["rail"]["friction"].as<double>(), 0.0);
  const std::string prescribed = without_the_slides_motion(cases / "enet_grilli_slide_3d.yaml");
  EXPECT_NE(prescribed.find("enet_grilli_slope.csv"), std::string::npos);  // the whole scene is in the text
  EXPECT_EQ(prescribed.find("ln_cosh"), std::string::npos);
  EXPECT_EQ(prescribed, without_the_slides_motion(cases / "enet_grilli_slide_rail_3d.yaml"));
}

}  // namespace
}  // namespace slide::testing
