// A declarative schema for YAML scene files.
//
// The scene format is described once, in C++, as a tree of Schema nodes. The same tree
//  * validates a scene before anything runs (unknown keys, missing keys, wrong types and
//    out-of-range values are reported with the full key path, e.g. `fluid.regions[1].level`),
//  * fills in defaults, so the rest of the program reads a complete, normalised YAML tree,
//  * prints the Markdown reference document, so the documentation cannot drift from the code.
#pragma once

#include <climits>
#include <cstddef>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace slide::cases {

// A problem in a scene file (or in a command-line override), located by its key path.
// what() = "<key_path>: <message>" ("<root>" stands for an empty path).
struct SceneError : std::runtime_error {
  SceneError(std::string key_path, std::string message);
  std::string key_path;
  std::string message;
};

// One node of the schema tree. A value type: copies share the (immutable) description.
class Schema {
 public:
  enum class Kind { Number, Integer, Boolean, Choice, Text, Vector, Map, List, Variant };

  static constexpr double inf = std::numeric_limits<double>::infinity();

  // Leaves. `doc` is one sentence; `unit` may be "" (dimensionless/none). No default => required.
  // Factories throw std::invalid_argument when the description itself is inconsistent
  // (e.g. a default outside the accepted range): that is a programming error, not a scene error.
  static Schema number(std::string doc, std::string unit, std::optional<double> default_value,
                       double min = -inf, double max = inf, bool min_exclusive = false,
                       bool max_exclusive = false);
  static Schema integer(std::string doc, std::optional<long> default_value, long min = LONG_MIN,
                        long max = LONG_MAX);
  static Schema boolean(std::string doc, std::optional<bool> default_value);
  static Schema choice(std::string doc, std::vector<std::string> choices,
                       std::optional<std::string> default_value);
  static Schema text(std::string doc, std::optional<std::string> default_value);
  // Fixed-length (length >= 1) or any-length (length = -1) list of numbers, each in [min, max].
  static Schema vector(std::string doc, std::string unit, int length,
                       std::optional<std::vector<double>> default_value, double min = -inf,
                       double max = inf);
  // A mapping with named fields, kept in order. An optional (required=false) map may be absent:
  // it is then filled from its fields' defaults, or left out of the resolved output when some
  // field has no default (the consumer tests for its presence).
  static Schema map(std::string doc, std::vector<std::pair<std::string, Schema>> fields,
                    bool required = true);
  // A list whose items all follow `item`. Absent => empty list if min_items == 0, else required.
  static Schema list(std::string doc, Schema item, std::size_t min_items = 0);
  // A map discriminated by the string value of key `tag`; each variant is a map() of the other fields. With a
  // default tag, the tag may be left out (and the whole variant, when that variant's fields all have defaults).
  static Schema variant(std::string doc, std::string tag,
                        std::vector<std::pair<std::string, Schema>> variants,
                        std::optional<std::string> default_tag = std::nullopt);

  Kind kind() const;
  const std::string& doc() const;
  // True when the key may be left out of its parent map (it has a default, or is an optional
  // map, or a list that may be empty).
  bool is_optional() const;

  // Checks `input` and returns a new tree with every default filled in (map keys in schema
  // order). Throws SceneError on the first problem. `path` is the key path of `input`.
  YAML::Node resolve(const YAML::Node& input, const std::string& path = "") const;

  // Markdown reference: a title, the root's description and one table row per key path.
  // A Markdown page: its title at heading `level` (1: '#'), the schema's documentation and a table of every key.
  std::string document(const std::string& title, int level = 1) const;

  struct Node;  // the description; defined in schema.cpp

 private:
  friend struct SchemaAccess;
  explicit Schema(std::shared_ptr<const Node> node);
  std::shared_ptr<const Node> node_;
};

// Applies one command-line override "a.b[2].c=value" (or "a.b.2.c=value") to the raw scene,
// before resolve(). Missing map keys are created; the value is parsed as YAML. Throws SceneError
// with key path "--set" on a malformed assignment.
void apply_override(YAML::Node& root, const std::string& assignment);

}  // namespace slide::cases
