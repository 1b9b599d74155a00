#pragma once
// The other choices of a rigid body in a scene: what it does while the water settles (`bodies[].during_settling`),
// the law of a prescribed motion (`bodies[].prescribed.type`), and the components a free body holds fixed
// (`bodies[].locked`).
#include "fluid/name_table.hpp"

namespace slide::cases {

enum class DuringSettling {
  held,  // kept where it is put while the water settles
  free,  // floats with the water under the same damping (free bodies only)
};

inline constexpr auto during_settling_names = make_name_table<DuringSettling>(
    std::pair{DuringSettling::held, "held"}, std::pair{DuringSettling::free, "free"});

inline std::string_view to_string(DuringSettling s) { return during_settling_names.name(s); }

enum class PrescribedLaw {
  series,   // a CSV time series of the centre of mass, interpolated by cubic Hermite
  ln_cosh,  // s(t) = s0 ln cosh((t - start_time) / t0) along a direction
};

inline constexpr auto prescribed_law_names = make_name_table<PrescribedLaw>(
    std::pair{PrescribedLaw::series, "series"}, std::pair{PrescribedLaw::ln_cosh, "ln_cosh"});

inline std::string_view to_string(PrescribedLaw l) { return prescribed_law_names.name(l); }

// The values index rigid::BodySpec::locked.
enum class LockedComponent { x = 0, y = 1, rotation = 2 };

inline constexpr auto locked_component_names = make_name_table<LockedComponent>(
    std::pair{LockedComponent::x, "x"}, std::pair{LockedComponent::y, "y"},
    std::pair{LockedComponent::rotation, "rotation"});

inline std::string_view to_string(LockedComponent c) { return locked_component_names.name(c); }

}  // namespace slide::cases
