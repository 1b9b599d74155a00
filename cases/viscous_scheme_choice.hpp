#pragma once
// The scene's choice of viscous scheme (method.viscous_scheme): auto, or one of fluid/'s schemes.
#include "fluid/method_options.hpp"
#include "fluid/name_table.hpp"

namespace slide::cases {

// auto takes the semi-implicit scheme when some phase (a deformable slide's included) has a non-Newtonian rheology,
// the explicit one otherwise. Why: water-only scenes never meet the viscous limit (water's nu = 1e-6 m^2/s) and the
// explicit term costs nothing extra, while a yield stress makes the explicit viscous step 40-1000x smaller than the
// CFL step (DESIGN.md; the HB Poiseuille channel: tools/bench --sediment).
enum class ViscousSchemeChoice { automatic, explicit_, implicit };

inline constexpr auto viscous_scheme_choice_names = make_name_table<ViscousSchemeChoice>(
    std::pair{ViscousSchemeChoice::automatic, "auto"}, std::pair{ViscousSchemeChoice::explicit_, "explicit"},
    std::pair{ViscousSchemeChoice::implicit, "implicit"});

}  // namespace slide::cases
