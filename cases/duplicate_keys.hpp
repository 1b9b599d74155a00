#pragma once
// Repeated keys in a YAML mapping. yaml-cpp keeps both entries and a lookup returns the first, so a scene that says
// `end_time` twice would silently run with one of them: every reader of YAML (scene, --set value, sweep file) refuses
// it instead, naming the key.
#include <yaml-cpp/yaml.h>

#include <optional>
#include <set>
#include <string>

namespace slide::cases {

struct DuplicateKey {
  std::string path;     // e.g. "time_step.cfl" or "bodies[0].density" below the node's own path
  int first_line = 0;   // 1-based; 0 where the node was not read from text with positions
  int second_line = 0;
};

// The first repeated key in the tree under `node`, in document order; `path` is the node's own key path.
inline std::optional<DuplicateKey> find_duplicate_key(const YAML::Node& node, const std::string& path = "") {
  if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i)
      if (auto d = find_duplicate_key(node[i], path + "[" + std::to_string(i) + "]")) return d;
  } else if (node.IsMap()) {
    std::set<std::string> seen;
    for (const auto& kv : node) {
      const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "<non-scalar key>";
      const std::string here = path.empty() ? key : path + "." + key;
      if (!seen.insert(key).second) {
        int first = 0;
        for (const auto& earlier : node)
          if (earlier.first.IsScalar() && earlier.first.Scalar() == key) {
            first = earlier.first.Mark().line + 1;
            break;
          }
        return DuplicateKey{here, first, kv.first.Mark().line + 1};
      }
      if (auto d = find_duplicate_key(kv.second, here)) return d;
    }
  }
  return std::nullopt;
}

// "appears twice (lines 3 and 9); keep one" (lines only where known).
inline std::string duplicate_key_message(const DuplicateKey& d) {
  if (d.first_line > 0 && d.second_line > 0)
    return "appears twice (lines " + std::to_string(d.first_line) + " and " + std::to_string(d.second_line) +
           "); keep one";
  return "appears twice; keep one";
}

}  // namespace slide::cases
