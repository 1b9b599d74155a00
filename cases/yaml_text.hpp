#pragma once
// Reading YAML text safely. Anchors and aliases make a YAML document a graph, not a tree: a few bytes can stand for a
// cycle (`a: &a [*a]`, an alias inside its own anchor, which yaml-cpp builds into a node that contains itself, so any
// walk of it recurses until the stack overflows) or for an exponential tree (each line aliasing the one before nine
// times: nine lines stand for 9^9 nodes, a minute of walking). One pass over the parser's events, linear in the
// text's length, measures the document as a walk would see it before yaml-cpp builds any node. Every YAML reader of
// slide (scene, --set value, sweep file, a checkpoint's scene) goes through `load_yaml_text`.
#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>

namespace slide::cases {

struct YamlLimits {
  std::size_t max_bytes = std::size_t{16} << 20;  // a scene is settings: data (terrain, meshes) come in files it names
  std::size_t max_nodes = 1'000'000;              // counted with every alias expanded; shipped scenes have < 1000
  int max_depth = 64;                             // nesting of sequences and maps; shipped scenes reach 5
};

// Why the text cannot be read safely (with its line where one applies), or nothing. Also reports YAML syntax errors
// in its first document and a second document (which YAML::Load would ignore).
std::optional<std::string> yaml_text_problem(const std::string& text, const YamlLimits& limits = {});

// The first document of `text`, refused first by yaml_text_problem. Throws YamlTextRefused.
YAML::Node load_yaml_text(const std::string& text, const YamlLimits& limits = {});

struct YamlTextRefused : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace slide::cases
