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

// The default (scene key method.initial_state): settled, the start that leaves still water at rest on the
// hexagonal lattice (fluid/method_options.hpp says why that lattice).
inline constexpr InitialState default_initial_state = InitialState::settled;

inline std::string_view to_string(InitialState s) { return initial_state_names.name(s); }

}  // namespace slide::cases
