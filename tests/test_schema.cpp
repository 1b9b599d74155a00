// Tests for the scene schema: defaults, every kind of error with its key path, variants,
// optional maps, command-line overrides and the generated reference document.
#include "cases/schema.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

namespace slide::cases {
namespace {

// A small scene format exercising every schema kind.
Schema scene_schema() {
  const Schema rectangle = Schema::map("An axis-aligned box.", {
      {"min", Schema::vector("Lower corner.", "m", 2, std::nullopt)},
      {"max", Schema::vector("Upper corner.", "m", 2, std::nullopt)},
  });
  const Schema polygon = Schema::map("A closed polygon.", {
      {"points", Schema::list("Vertices in order.", Schema::vector("Vertex.", "m", 2, std::nullopt), 3)},
  });
  const Schema region = Schema::variant("fluid region", "type", {{"rectangle", rectangle}, {"polygon", polygon}});
  return Schema::map("A test scene.", {
      {"name", Schema::text("Scene name.", "untitled")},
      {"fluid", Schema::map("The fluid.", {
          {"density", Schema::number("Rest density.", "kg/m^3", 1000.0, 0.0, Schema::inf, true)},
          {"spacing", Schema::number("Particle spacing.", "m", std::nullopt, 0.0, 10.0, true, false)},
          {"level", Schema::number("Fill fraction.", "", 0.5, 0.0, 1.0)},
          {"gravity", Schema::vector("Gravity.", "m/s^2", 2, std::vector<double>{0.0, -9.81})},
          {"regions", Schema::list("Regions filled with fluid.", region, 1)},
      })},
      {"time", Schema::map("Time stepping.", {
          {"steps", Schema::integer("Number of steps.", 100, 1, 1000000)},
          {"adaptive", Schema::boolean("Adapt the step to the CFL number.", true)},
          {"scheme", Schema::choice("Time integration scheme.", {"explicit", "semi-implicit"}, "semi-implicit")},
      }, false)},
      {"probe", Schema::map("An optional pressure probe.", {
          {"position", Schema::vector("Probe position.", "m", 2, std::nullopt)},
          {"radius", Schema::number("Averaging radius.", "m", 0.1, 0.0)},
      }, false)},
      {"tags", Schema::list("Free labels.", Schema::text("A label.", std::nullopt))},
  });
}

const char* kValidScene = R"(
fluid:
  spacing: 0.01
  regions:
    - type: rectangle
      min: [0, 0]
      max: [1, 0.5]
)";

// Resolves `yaml` against the test schema and returns the error it raises (fails if none).
SceneError error_of(const std::string& yaml) {
  try {
    scene_schema().resolve(YAML::Load(yaml));
  } catch (const SceneError& e) {
    return e;
  }
  ADD_FAILURE() << "no SceneError for:\n" << yaml;
  return SceneError("", "");
}

#define EXPECT_SCENE_ERROR(yaml, path, fragment)                                     \
  do {                                                                               \
    const SceneError e = error_of(yaml);                                             \
    EXPECT_EQ(e.key_path, path);                                                     \
    EXPECT_NE(e.message.find(fragment), std::string::npos) << "message: " << e.message; \
    EXPECT_EQ(std::string(e.what()), std::string(path) + ": " + e.message);          \
  } while (0)

TEST(Schema, ResolveFillsDefaultsInSchemaOrder) {
  const YAML::Node out = scene_schema().resolve(YAML::Load(kValidScene));
  EXPECT_EQ(out["name"].as<std::string>(), "untitled");
  EXPECT_DOUBLE_EQ(out["fluid"]["density"].as<double>(), 1000.0);
  EXPECT_DOUBLE_EQ(out["fluid"]["spacing"].as<double>(), 0.01);
  EXPECT_DOUBLE_EQ(out["fluid"]["gravity"][1].as<double>(), -9.81);
  EXPECT_EQ(out["time"]["steps"].as<long>(), 100);
  EXPECT_TRUE(out["time"]["adaptive"].as<bool>());
  EXPECT_EQ(out["time"]["scheme"].as<std::string>(), "semi-implicit");
  EXPECT_TRUE(out["tags"].IsSequence());
  EXPECT_EQ(out["tags"].size(), 0u);
  // Keys come out in schema order, whatever the input order.
  std::vector<std::string> keys;
  for (const auto& kv : out["fluid"]) keys.push_back(kv.first.as<std::string>());
  EXPECT_EQ(keys, (std::vector<std::string>{"density", "spacing", "level", "gravity", "regions"}));
  // The variant keeps its tag first.
  EXPECT_EQ(out["fluid"]["regions"][0].begin()->first.as<std::string>(), "type");
}

TEST(Schema, ResolveDoesNotModifyOrAliasTheInput) {
  YAML::Node in = YAML::Load(kValidScene);
  const std::string before = YAML::Dump(in);
  YAML::Node out = scene_schema().resolve(in);
  out["fluid"]["regions"][0]["min"][0] = 42.0;
  EXPECT_EQ(YAML::Dump(in), before);
  const YAML::Node& const_in = in;  // const lookup: must not insert the key
  EXPECT_FALSE(const_in["time"]);
}

TEST(Schema, IntegersAreAcceptedForNumbersAndIntegralNumbersForIntegers) {
  const YAML::Node out = scene_schema().resolve(
      YAML::Load(std::string(kValidScene) + "time: {steps: 1e3}\n"));
  EXPECT_EQ(out["time"]["steps"].as<long>(), 1000);
  EXPECT_DOUBLE_EQ(out["fluid"]["regions"][0]["max"][0].as<double>(), 1.0);
}

TEST(Schema, UnknownKeyListsAcceptedKeys) {
  EXPECT_SCENE_ERROR(std::string(kValidScene) + "  levle: 0.3\n", "fluid.levle",
                     "unknown key; accepted keys: density, spacing, level, gravity, regions");
  EXPECT_SCENE_ERROR(std::string(kValidScene) + "colour: red\n", "colour", "unknown key; accepted keys: name,");
  EXPECT_SCENE_ERROR(std::string(kValidScene) + "      radius: 2\n", "fluid.regions[0].radius",
                     "accepted keys: type, min, max");
}

TEST(Schema, MissingRequiredKey) {
  EXPECT_SCENE_ERROR("fluid: {regions: [{type: rectangle, min: [0, 0], max: [1, 1]}]}", "fluid.spacing",
                     "missing required key (Particle spacing)");
  EXPECT_SCENE_ERROR("name: x", "fluid", "missing required key (The fluid)");
  EXPECT_SCENE_ERROR("fluid: {spacing: 0.1, regions: [{type: rectangle, min: [0, 0]}]}", "fluid.regions[0].max",
                     "missing required key (Upper corner)");
}

TEST(Schema, WrongTypeForNumber) {
  EXPECT_SCENE_ERROR("fluid: {spacing: abc, regions: []}", "fluid.spacing",
                     "expected a number in (0, 10] (m), got string \"abc\"");
  // A quoted number is a string.
  EXPECT_SCENE_ERROR("fluid: {spacing: \"0.1\", regions: []}", "fluid.spacing", "got string \"0.1\"");
  EXPECT_SCENE_ERROR("fluid: {spacing: [1], regions: []}", "fluid.spacing", "got a list of 1 items");
}

TEST(Schema, WrongTypeForInteger) {
  EXPECT_SCENE_ERROR(std::string(kValidScene) + "time: {steps: 2.5}\n", "time.steps",
                     "expected an integer in [1, 1000000], got number 2.5");
  EXPECT_SCENE_ERROR(std::string(kValidScene) + "time: {steps: many}\n", "time.steps",
                     "expected an integer in [1, 1000000], got string \"many\"");
}

TEST(Schema, WrongTypeForBoolean) {
  EXPECT_SCENE_ERROR(std::string(kValidScene) + "time: {adaptive: yes}\n", "time.adaptive",
                     "expected true or false, got string \"yes\"");
  EXPECT_SCENE_ERROR(std::string(kValidScene) + "time: {adaptive: 1}\n", "time.adaptive",
                     "expected true or false, got number 1");
}

TEST(Schema, WrongChoice) {
  EXPECT_SCENE_ERROR(std::string(kValidScene) + "time: {scheme: implicit}\n", "time.scheme",
                     "expected one of: explicit, semi-implicit, got string \"implicit\"");
}

TEST(Schema, WrongVectorLengthAndElement) {
  EXPECT_SCENE_ERROR("fluid: {spacing: 0.1, gravity: [0, -9.81, 0], regions: []}", "fluid.gravity",
                     "expected a list of 2 numbers (m/s^2), got a list of 3 items");
  EXPECT_SCENE_ERROR("fluid: {spacing: 0.1, gravity: 9.81, regions: []}", "fluid.gravity",
                     "expected a list of 2 numbers (m/s^2), got number 9.81");
  EXPECT_SCENE_ERROR("fluid: {spacing: 0.1, gravity: [0, down], regions: []}", "fluid.gravity[1]",
                     "expected a number (m/s^2), got string \"down\"");
}

TEST(Schema, OutOfRangeIncludingExclusiveBounds) {
  EXPECT_SCENE_ERROR("fluid: {spacing: 12, regions: []}", "fluid.spacing",
                     "value 12 is out of range: expected 0 < value <= 10 (m)");
  // The lower bound is exclusive: 0 itself is rejected, 10 (inclusive upper bound) is accepted.
  EXPECT_SCENE_ERROR("fluid: {spacing: 0, regions: []}", "fluid.spacing", "value 0 is out of range");
  EXPECT_SCENE_ERROR("fluid: {spacing: 0.1, level: 1.5, regions: []}", "fluid.level",
                     "value 1.5 is out of range: expected 0 <= value <= 1");
  EXPECT_SCENE_ERROR("fluid: {spacing: 0.1, density: -1, regions: []}", "fluid.density",
                     "value -1 is out of range: expected value > 0 (kg/m^3)");
  EXPECT_SCENE_ERROR(std::string(kValidScene) + "time: {steps: 0}\n", "time.steps",
                     "value 0 is out of range: expected 1 <= value <= 1000000");
  const YAML::Node ok = YAML::Load(kValidScene);
  YAML::Node edge = YAML::Clone(ok);
  edge["fluid"]["spacing"] = 10;
  EXPECT_NO_THROW(scene_schema().resolve(edge));
}

TEST(Schema, NonFiniteNumbersAreRejected) {
  EXPECT_SCENE_ERROR("fluid: {spacing: .nan, regions: []}", "fluid.spacing", "value .nan is not a finite number");
  EXPECT_SCENE_ERROR("fluid: {spacing: 0.1, density: .inf, regions: []}", "fluid.density",
                     "value .inf is not a finite number");
  EXPECT_SCENE_ERROR("fluid: {spacing: 0.1, gravity: [0, -.inf], regions: []}", "fluid.gravity[1]",
                     "not a finite number");
}

TEST(Schema, ListMinItems) {
  EXPECT_SCENE_ERROR("fluid: {spacing: 0.1, regions: []}", "fluid.regions", "expected at least 1 item, got 0");
  EXPECT_SCENE_ERROR("fluid: {spacing: 0.1}", "fluid.regions", "missing required key (Regions filled with fluid)");
  EXPECT_SCENE_ERROR("fluid: {spacing: 0.1, regions: [{type: polygon, points: [[0, 0], [1, 0]]}]}",
                     "fluid.regions[0].points", "expected at least 3 items, got 2");
  EXPECT_SCENE_ERROR("fluid: {spacing: 0.1, regions: {type: polygon}}", "fluid.regions", "expected a list, got a map");
}

TEST(Schema, Variants) {
  const YAML::Node out = scene_schema().resolve(YAML::Load(R"(
fluid:
  spacing: 0.1
  regions:
    - {type: polygon, points: [[0, 0], [1, 0], [0, 1]]}
    - {type: rectangle, min: [0, 0], max: [1, 1]}
)"));
  EXPECT_EQ(out["fluid"]["regions"][0]["type"].as<std::string>(), "polygon");
  EXPECT_EQ(out["fluid"]["regions"][0]["points"].size(), 3u);
  EXPECT_EQ(out["fluid"]["regions"][1]["type"].as<std::string>(), "rectangle");

  EXPECT_SCENE_ERROR("fluid: {spacing: 0.1, regions: [{type: rectangle, min: [0, 0], max: [1, 1]}, {type: circle}]}",
                     "fluid.regions[1].type", "expected one of: rectangle, polygon, got string \"circle\"");
  EXPECT_SCENE_ERROR("fluid: {spacing: 0.1, regions: [{min: [0, 0], max: [1, 1]}]}", "fluid.regions[0].type",
                     "missing required key (selects the kind of fluid region; one of: rectangle, polygon)");
  // Fields of another variant are unknown here.
  EXPECT_SCENE_ERROR("fluid: {spacing: 0.1, regions: [{type: rectangle, points: []}]}", "fluid.regions[0].points",
                     "unknown key; accepted keys: type, min, max");
  EXPECT_SCENE_ERROR("fluid: {spacing: 0.1, regions: [5]}", "fluid.regions[0]", "expected a map with key 'type'");
}

// A variant with a default tag: the tag may be left out, and so may the whole variant when the default variant's
// fields all have defaults; a given tag still selects, and the default variant's unknown keys are still errors.
TEST(Schema, VariantWithADefaultTag) {
  const Schema newtonian = Schema::map("A Newtonian fluid.", {{"viscosity", Schema::number("Viscosity.", "Pa s", 1e-3)}});
  const Schema bingham = Schema::map("A Bingham fluid.", {{"yield_stress", Schema::number("Yield.", "Pa", std::nullopt)}});
  const Schema phase = Schema::map("A phase.", {{"rheology", Schema::variant("rheology", "model",
                                                 {{"newtonian", newtonian}, {"bingham", bingham}}, "newtonian")}});
  const YAML::Node absent = phase.resolve(YAML::Load("{}"));
  EXPECT_EQ(absent["rheology"]["model"].as<std::string>(), "newtonian");
  EXPECT_DOUBLE_EQ(absent["rheology"]["viscosity"].as<double>(), 1e-3);
  const YAML::Node untagged = phase.resolve(YAML::Load("{rheology: {viscosity: 2}}"));
  EXPECT_EQ(untagged["rheology"]["model"].as<std::string>(), "newtonian");
  EXPECT_DOUBLE_EQ(untagged["rheology"]["viscosity"].as<double>(), 2.0);
  const YAML::Node tagged = phase.resolve(YAML::Load("{rheology: {model: bingham, yield_stress: 5}}"));
  EXPECT_DOUBLE_EQ(tagged["rheology"]["yield_stress"].as<double>(), 5.0);
  EXPECT_THROW(phase.resolve(YAML::Load("{rheology: {yield_stress: 5}}")), SceneError);
  EXPECT_THROW(phase.resolve(YAML::Load("{rheology: {model: bingham}}")), SceneError);
  EXPECT_THROW(Schema::variant("v", "model", {{"newtonian", newtonian}}, "plastic"), std::invalid_argument);
  EXPECT_NE(phase.document("t").find("| `rheology.model` | choice |  | \"newtonian\" | one of: newtonian, bingham |"),
            std::string::npos);
}

TEST(Schema, OptionalMaps) {
  // `time` has defaults for all fields: filled in when absent. `probe` has a required field: left out.
  const YAML::Node out = scene_schema().resolve(YAML::Load(kValidScene));
  ASSERT_TRUE(out["time"].IsMap());
  EXPECT_EQ(out["time"]["steps"].as<long>(), 100);
  EXPECT_FALSE(out["probe"].IsDefined());
  // Once present, its required fields are required.
  EXPECT_SCENE_ERROR(std::string(kValidScene) + "probe: {radius: 0.2}\n", "probe.position",
                     "missing required key (Probe position)");
  const YAML::Node with_probe =
      scene_schema().resolve(YAML::Load(std::string(kValidScene) + "probe: {position: [0.5, 0.1]}\n"));
  EXPECT_DOUBLE_EQ(with_probe["probe"]["radius"].as<double>(), 0.1);
  EXPECT_SCENE_ERROR(std::string(kValidScene) + "time: 5\n", "time", "expected a map with keys steps, adaptive, scheme");
}

TEST(Schema, BadDefaultsAreProgrammingErrors) {
  EXPECT_THROW(Schema::number("x", "m", 20.0, 0.0, 10.0), std::invalid_argument);
  EXPECT_THROW(Schema::choice("x", {"a", "b"}, "c"), std::invalid_argument);
  EXPECT_THROW(Schema::vector("x", "m", 2, std::vector<double>{1.0}), std::invalid_argument);
}

TEST(Schema, OverrideMapKeysAndCreatesMissingOnes) {
  YAML::Node root = YAML::Load(kValidScene);
  apply_override(root, "fluid.spacing=0.02");
  apply_override(root, "time.scheme=explicit");      // `time` did not exist
  apply_override(root, "probe.position=[1, 2]");     // value parsed as YAML
  apply_override(root, "time.adaptive=false");
  EXPECT_DOUBLE_EQ(root["fluid"]["spacing"].as<double>(), 0.02);
  EXPECT_EQ(root["time"]["scheme"].as<std::string>(), "explicit");
  EXPECT_FALSE(root["time"]["adaptive"].as<bool>());
  EXPECT_EQ(root["probe"]["position"][1].as<int>(), 2);
  // Siblings are untouched.
  EXPECT_EQ(root["fluid"]["regions"].size(), 1u);
  const YAML::Node out = scene_schema().resolve(root);
  EXPECT_EQ(out["time"]["scheme"].as<std::string>(), "explicit");
  EXPECT_FALSE(out["time"]["adaptive"].as<bool>());

  YAML::Node empty;
  apply_override(empty, "a.b.c=3");
  EXPECT_EQ(empty["a"]["b"]["c"].as<int>(), 3);
}

TEST(Schema, OverrideListIndicesInBothSyntaxes) {
  YAML::Node root = YAML::Load(std::string(kValidScene) + "    - {type: rectangle, min: [2, 0], max: [3, 1]}\n");
  apply_override(root, "fluid.regions[1].max[0]=4");
  apply_override(root, "fluid.regions.0.min.1=0.25");
  apply_override(root, "fluid.regions[0].type=polygon");
  EXPECT_EQ(root["fluid"]["regions"][1]["max"][0].as<double>(), 4.0);
  EXPECT_EQ(root["fluid"]["regions"][0]["min"][1].as<double>(), 0.25);
  EXPECT_EQ(root["fluid"]["regions"][0]["type"].as<std::string>(), "polygon");
  EXPECT_EQ(root["fluid"]["regions"][1]["min"][0].as<double>(), 2.0);
  EXPECT_EQ(root["fluid"]["regions"].size(), 2u);
}

TEST(Schema, MalformedOverrides) {
  const auto error = [](const std::string& assignment) {
    YAML::Node root = YAML::Load(kValidScene);
    try {
      apply_override(root, assignment);
    } catch (const SceneError& e) {
      EXPECT_EQ(e.key_path, "--set");
      return e.message;
    }
    ADD_FAILURE() << "no error for " << assignment;
    return std::string();
  };
  EXPECT_NE(error("fluid.spacing").find("expected key.path=value"), std::string::npos);
  EXPECT_NE(error("=3").find("empty key path"), std::string::npos);
  EXPECT_NE(error("fluid..spacing=3").find("malformed key path"), std::string::npos);
  EXPECT_NE(error("fluid.regions[x]=3").find("malformed key path"), std::string::npos);
  EXPECT_NE(error("fluid.regions[3].type=polygon").find("list index 3 is out of range: \"fluid.regions\" has 1 items"),
            std::string::npos);
  EXPECT_NE(error("fluid.spacing[0]=1").find("cannot index \"fluid.spacing\" with [0]: it is not a list"),
            std::string::npos);
  EXPECT_NE(error("fluid.regions.type=x").find("cannot set key \"type\" inside \"fluid.regions\": it is not a map"),
            std::string::npos);
  EXPECT_NE(error("fluid.spacing=[1, 2").find("cannot parse the value"), std::string::npos);
}

TEST(Schema, DocumentListsEveryKey) {
  const std::string doc = scene_schema().document("Scene reference");
  const auto has = [&](const std::string& row) {
    EXPECT_NE(doc.find(row), std::string::npos) << "missing row: " << row << "\n" << doc;
  };
  EXPECT_EQ(doc.rfind("# Scene reference\n", 0), 0u);
  has("| key | type | unit | default | accepted | description |");
  has("| `name` | string |  | \"untitled\" | any | Scene name. |");
  has("| `fluid` | map |  | required |  | The fluid. |");
  has("| `fluid.density` | number | kg/m^3 | 1000 | > 0 | Rest density. |");
  has("| `fluid.spacing` | number | m | required | 0 < x <= 10 | Particle spacing. |");
  has("| `fluid.gravity` | vector[2] | m/s^2 | [0, -9.81] | length 2 | Gravity. |");
  has("| `fluid.regions` | list of variant |  | required | at least 1 item | Regions filled with fluid. |");
  has("| `fluid.regions[].type` | choice |  | required | one of: rectangle, polygon |");
  has("| `fluid.regions[] (type: rectangle).min` | vector[2] | m | required | length 2 | Lower corner. |");
  has("| `fluid.regions[] (type: polygon).points` | list of vector[2] | m | required | at least 3 items; each length 2 | Vertices in order. |");
  has("| `time` | map |  | optional |  | Time stepping. |");
  has("| `time.steps` | integer |  | 100 | 1 <= x <= 1000000 | Number of steps. |");
  has("| `time.adaptive` | boolean |  | true | true, false |");
  has("| `time.scheme` | choice |  | \"semi-implicit\" | one of: explicit, semi-implicit |");
  has("| `probe.radius` | number | m | 0.1 | >= 0 | Averaging radius. |");
  has("| `tags` | list of string |  | [] | any length | Free labels. |");
}

}  // namespace
}  // namespace slide::cases
