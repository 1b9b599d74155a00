#pragma once
// The snapshot fields a scene may select (output.snapshot_fields) besides position, kind and id, which every snapshot
// holds: the one name table, read by the schema and by the writer (tools/snapshot_writer.cpp), whose datasets and
// XDMF attributes carry these names.
#include <string>
#include <vector>

namespace slide::cases {

inline const std::vector<std::string>& snapshot_field_names() {
  static const std::vector<std::string> names{"velocity", "pressure", "number_density", "density", "phase"};
  return names;
}

}  // namespace slide::cases
