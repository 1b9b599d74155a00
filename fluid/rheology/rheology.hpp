#pragma once
// A phase's rheology: one of the models, each in its own file. Every model gives an effective (dynamic) viscosity
// eta(g, p) in Pa s from the local shear rate g = sqrt(2 D:D) (1/s, fluid/strain_rate.hpp) and pressure p (Pa).
#include <string_view>
#include <type_traits>
#include <variant>

#include "fluid/rheology/granular_mu_i.hpp"
#include "fluid/rheology/herschel_bulkley.hpp"
#include "fluid/rheology/mohr_coulomb.hpp"
#include "fluid/rheology/newtonian.hpp"

namespace slide {

using Rheology = std::variant<Newtonian, HerschelBulkley, MohrCoulomb, GranularMuI>;

inline double effective_viscosity(const Rheology& r, double shear_rate_per_s, double pressure_pa) {
  return std::visit([&](const auto& m) { return m.effective_viscosity(shear_rate_per_s, pressure_pa); }, r);
}

// Whether the model has a yield stress (so an unsheared region stays rigid up to its regularisation): Herschel-
// Bulkley with tau_y > 0, Mohr-Coulomb and mu(I) always.
inline bool has_yield_stress(const Rheology& r) {
  if (const auto* hb = std::get_if<HerschelBulkley>(&r)) return hb->yield_stress_pa > 0.0;
  return std::holds_alternative<MohrCoulomb>(r) || std::holds_alternative<GranularMuI>(r);
}

// The model's name as scenes and outputs spell it.
inline std::string_view model_name(const Rheology& r) {
  return std::visit(
      [](const auto& m) -> std::string_view {
        using T = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<T, Newtonian>) return "newtonian";
        else if constexpr (std::is_same_v<T, HerschelBulkley>) return "herschel_bulkley";
        else if constexpr (std::is_same_v<T, MohrCoulomb>) return "mohr_coulomb";
        else {
          static_assert(std::is_same_v<T, GranularMuI>, "every rheology needs a name");
          return "granular";
        }
      },
      r);
}

}  // namespace slide
