#pragma once
// A position for messages, "(x, y)" or "(x, y, z)", each to 6 significant digits: one format for every message that
// names where a particle is (instabilities, particles that left the domain, scene errors).
#include <fmt/format.h>

#include <string>
#include <vector>

#include "fluid/vec.hpp"

namespace slide {

inline std::string position_text(const std::vector<double>& p) {
  std::string out = "(";
  for (std::size_t k = 0; k < p.size(); ++k) out += (k ? ", " : "") + fmt::format("{:.6g}", p[k]);
  return out + ")";
}

template <int D>
std::string position_text(const Vec<D>& p) {
  return position_text(std::vector<double>(p.begin(), p.end()));
}

}  // namespace slide
