#pragma once
// How a scene's water starts (scene key `method.initial_state`).
#include "fluid/name_table.hpp"

namespace slide::cases {

enum class InitialState {
  hydrostatic,  // compressed column by column to the equilibrium column's spacing (coupling/equilibrium_column.hpp)
  settled,      // the same, then damped settling before t = 0 (coupling/relaxation.hpp)
  lattice,      // the uncompressed lattice
};

inline constexpr auto initial_state_names = make_name_table<InitialState>(
    std::pair{InitialState::hydrostatic, "hydrostatic"}, std::pair{InitialState::settled, "settled"},
    std::pair{InitialState::lattice, "lattice"});

inline std::string_view to_string(InitialState s) { return initial_state_names.name(s); }

}  // namespace slide::cases
