#pragma once
// What the deformable-slide tests share: the slide's particles (its phase) by id,
// centre of mass and largest displacement (tests/test_sediment_block.cpp, tests/test_basal_friction.cpp).
#include <algorithm>
#include <memory>
#include <string>
#include <unordered_map>

#include "cases/scene.hpp"
#include "tests/scene_runner.hpp"

namespace slide::testing {

// The positions of the slide's particles by id (periodic ghosts, fluid/periodic.hpp, are not particles of their own:
// real particles only, here and below).
inline std::unordered_map<std::uint32_t, Vec<2>> slide_positions(const Particles<2>& P, std::uint8_t phase) {
  std::unordered_map<std::uint32_t, Vec<2>> out;
  for (std::size_t i = 0; i < P.real_count(); ++i)
    if (P.kind[i] == Kind::fluid && P.phase[i] == phase) out.emplace(P.id[i], P.position[i]);
  return out;
}

inline Vec<2> centre_of_mass(const Particles<2>& P, std::uint8_t phase) {
  double x = 0.0, y = 0.0;  // two scalars: GCC 12 warns (falsely) of an uninitialised Vec<2> sum
  long n = 0;
  for (std::size_t i = 0; i < P.real_count(); ++i)
    if (P.kind[i] == Kind::fluid && P.phase[i] == phase) x += P.position[i][0], y += P.position[i][1], ++n;
  return Vec<2>(x / n, y / n);
}

// Largest distance of a slide particle from where it was at t = 0.
inline double largest_displacement(const Particles<2>& P, std::uint8_t phase,
                                   const std::unordered_map<std::uint32_t, Vec<2>>& start) {
  double most = 0.0;
  for (std::size_t i = 0; i < P.real_count(); ++i)
    if (P.kind[i] == Kind::fluid && P.phase[i] == phase)
      most = std::max(most, (P.position[i] - start.at(P.id[i])).norm());
  return most;
}

}  // namespace slide::testing
