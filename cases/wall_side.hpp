#pragma once
// The side of a wall's face polyline where the fluid is, walking from its first vertex (scene key
// `walls[].fluid_side`).
#include "fluid/name_table.hpp"

namespace slide::cases {

enum class FluidSide { left, right };

inline constexpr auto fluid_side_names =
    make_name_table<FluidSide>(std::pair{FluidSide::left, "left"}, std::pair{FluidSide::right, "right"});

inline std::string_view to_string(FluidSide s) { return fluid_side_names.name(s); }

}  // namespace slide::cases
