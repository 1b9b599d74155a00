#pragma once
// A free block of water [0, 0.4] x [0, 0.2] at dp = 0.01 on either lattice, no gravity and no walls: nothing moves,
// the lattice is exactly as filled, its edges half a row spacing beyond its outer rows. The fixture of the tests of
// the water's edge (tests/test_gauge.cpp, tests/test_water_gap.cpp).
#include <memory>
#include <string>

#include "cases/scene.hpp"
#include "tests/cli_helpers.hpp"

namespace slide::testing {

inline std::unique_ptr<cases::Scene<2>> free_water_block(const std::string& lattice, const std::string& name) {
  const auto dir = fresh_directory(name + "_" + lattice);
  write_file(dir / "s.yaml", R"(particle_spacing: 0.01
end_time: 1
gravity: [0, 0]
lattice: )" + lattice + R"(
method: {sound_speed: 10, initial_state: lattice, wall_pressure: extrapolated}
fluid:
  phases: [{name: water}]
  regions: [{type: rectangle, min: [0, 0], max: [0.4, 0.2]}]
)");
  return cases::build_scene<2>(cases::load_scene(dir / "s.yaml", {}), "s");
}

}  // namespace slide::testing
