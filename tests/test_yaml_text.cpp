// YAML text that stands for a cycle or an exponential tree through its aliases, or nests without end (issue 30):
// refused with exit 2 and a message before yaml-cpp builds a node, by every reader of YAML (cases/yaml_text.hpp).
#include <gtest/gtest.h>

#include "cases/yaml_text.hpp"
#include "tests/cli_helpers.hpp"

namespace slide::testing {
namespace {

namespace fs = std::filesystem;
using cases::yaml_text_problem;
using cases::YamlLimits;

// `levels` lines, each a sequence aliasing the one before nine times: 9^levels leaves in a few hundred bytes.
std::string billion_laughs(int levels) {
  std::string text = "l0: &l0 [x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i < levels; ++i) {
    const std::string level = std::to_string(i);
    text.append("l").append(level).append(": &l").append(level).append(" [");
    for (int k = 0; k < 9; ++k) {
      text += k ? ", *l" : "*l";
      text += std::to_string(i - 1);
    }
    text += "]\n";
  }
  return text;
}

// The count is the walk's: the map, its keys and values, and each alias as many nodes as its anchor holds.
TEST(YamlText, NodesAreCountedWithEveryAliasExpanded) {
  // map 1 + key a 1 + seq 1 + 2 scalars + key b 1 + alias of 3 nodes = 9
  const std::string text = "a: &s [1, 2]\nb: *s\n";
  EXPECT_FALSE(yaml_text_problem(text, YamlLimits{.max_nodes = 9}));
  const auto over = yaml_text_problem(text, YamlLimits{.max_nodes = 8});
  ASSERT_TRUE(over);
  EXPECT_NE(over->find("more than 8 nodes"), std::string::npos) << *over;
  EXPECT_NE(over->find("line 2"), std::string::npos) << *over;
}

TEST(YamlText, AnAliasInsideItsOwnAnchorIsACycle) {
  for (const char* text : {"a: &a [*a]\n", "a: &a {b: [1, {c: *a}]}\n", "x: &x\n  y: *x\n"}) {
    const auto p = yaml_text_problem(text);
    ASSERT_TRUE(p) << text;
    EXPECT_NE(p->find("an alias refers to the anchor that contains it"), std::string::npos) << *p;
  }
  // An alias to an anchor closed before it is a plain repeat, not a cycle.
  EXPECT_FALSE(yaml_text_problem("a: &a [1]\nb: [*a, *a]\n"));
}

TEST(YamlText, ExponentialAliasesDeepNestingAndSizeAreRefused) {
  EXPECT_FALSE(yaml_text_problem(billion_laughs(5)));  // 9^5 = 59049 leaves: allowed
  const auto laughs = yaml_text_problem(billion_laughs(9));
  ASSERT_TRUE(laughs);
  EXPECT_NE(laughs->find("more than 1000000 nodes once its aliases are expanded"), std::string::npos) << *laughs;

  const std::string deep = "a: " + std::string(64, '[') + std::string(64, ']') + "\n";
  EXPECT_FALSE(yaml_text_problem(deep, YamlLimits{.max_depth = 65}));  // the root map and 64 sequences
  const auto too_deep = yaml_text_problem(deep, YamlLimits{.max_depth = 64});
  ASSERT_TRUE(too_deep);
  EXPECT_NE(too_deep->find("nested deeper than 64 levels"), std::string::npos) << *too_deep;

  const auto big = yaml_text_problem(std::string(100, '#'), YamlLimits{.max_bytes = 99});
  ASSERT_TRUE(big);
  EXPECT_NE(big->find("100 bytes, more than the 99"), std::string::npos) << *big;

  const auto broken = yaml_text_problem("a: [1, 2\n");
  ASSERT_TRUE(broken);
  EXPECT_NE(broken->find("not valid YAML"), std::string::npos) << *broken;
  const auto second = yaml_text_problem("a: 1\n---\nb: 2\n");
  ASSERT_TRUE(second);
  EXPECT_NE(second->find("line 2: a second YAML document begins here"), std::string::npos) << *second;
  EXPECT_FALSE(yaml_text_problem("a: 1\n...\n# the end\n"));
  EXPECT_FALSE(yaml_text_problem(""));
  // yaml-cpp 0.7 returns empty documents without end after this line (found by the fuzzer): refused at the second.
  const auto endless = yaml_text_problem("# c\n, 3) to x\n");
  ASSERT_TRUE(endless);
  EXPECT_NE(endless->find("a second YAML document"), std::string::npos) << *endless;
  const auto undefined = yaml_text_problem("a: *nowhere\n");
  ASSERT_TRUE(undefined);
  EXPECT_NE(undefined->find("not valid YAML"), std::string::npos) << *undefined;
}

void expect_refused(const CommandResult& r, const std::string& said) {
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find(said), std::string::npos) << "no \"" << said << "\" in: " << r.output;
}

// As a user meets them: `run` and `check` of such a scene, a --set value and a sweep file; nothing is written.
TEST(YamlText, ScenesSetValuesAndSweepsWithSuchAliasesExitTwo) {
  const fs::path dir = fresh_directory("yaml_aliases");
  write_file(dir / "cycle.yaml", "a: &a [*a]\n");
  write_file(dir / "laughs.yaml", billion_laughs(9));
  write_file(dir / "scene.yaml", kGoodScene);
  write_file(dir / "sweep.yaml", "scene: scene.yaml\nvary: &v {particle_spacing: [0.02, *v]}\n");
  const std::string cycle = "an alias refers to the anchor that contains it";
  for (const std::string& command : {" run --quiet --out " + (dir / "out").string() + " ", std::string(" check ")}) {
    expect_refused(run_command(slide_binary() + command + (dir / "cycle.yaml").string()), cycle);
    expect_refused(run_command(slide_binary() + command + (dir / "laughs.yaml").string()),
                   "once its aliases are expanded");
  }
  expect_refused(run_command(slide_binary() + " check " + (dir / "scene.yaml").string() + " --set 'end_time=&e [*e]'"),
                 cycle);
  expect_refused(run_command(slide_binary() + " sweep " + (dir / "sweep.yaml").string() + " --plan-only"), cycle);
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
}  // namespace slide::testing
