#pragma once
// A phase's rheology: one of the models, each in its own file. Every model gives an effective (dynamic) viscosity
// eta(g, p) in Pa s from the local shear rate g = sqrt(2 D:D) (1/s, fluid/strain_rate.hpp) and pressure p (Pa).
#include <algorithm>
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

// The viscosity a phase settles with before t = 0 (coupling/relaxation.hpp), in Pa s: the model without its yield
// term at a shear rate of 1/s (Newtonian: mu; Herschel-Bulkley and Mohr-Coulomb: K; mu(I): its floor min_viscosity).
// Why: at rest a yield-stress model's regularised viscosity (tau_y m, up to 1e6 Pa s) keeps the particles from
// rearranging while they settle, so the pressure they settle to is not the weight's, and a pressure-dependent yield
// stress then holds the wrong amount. Measured on a Mohr-Coulomb layer (phi = 30 deg, m = 1000 s, 0.1 m deep, dp
// 0.01, 1 s of settling, the semi-implicit stage's incremental predictor in place): settled with its rheology,
// 0.88-0.99 of hydrostatic (upper rows lowest); settled as a fluid, 0.98-1.00.
inline double settling_viscosity(const Rheology& r) {
  if (const auto* m = std::get_if<Newtonian>(&r)) return m->viscosity_pa_s;
  if (const auto* m = std::get_if<HerschelBulkley>(&r)) return m->consistency_pa_s_n;
  if (const auto* m = std::get_if<MohrCoulomb>(&r)) return m->consistency_pa_s_n;
  return std::get<GranularMuI>(r).min_viscosity_pa_s;
}

// Whether the model has a yield stress (so an unsheared region stays rigid up to its regularisation): Herschel-
// Bulkley with tau_y > 0, Mohr-Coulomb and mu(I) always.
inline bool has_yield_stress(const Rheology& r) {
  if (const auto* hb = std::get_if<HerschelBulkley>(&r)) return hb->yield_stress_pa > 0.0;
  return std::holds_alternative<MohrCoulomb>(r) || std::holds_alternative<GranularMuI>(r);
}

// Whether the viscosity depends on the pressure (the yield stress of Mohr-Coulomb, mu(I)'s eta = mu p / g): the
// rheology stage then gives it the confining pressure (fluid/confining_pressure.hpp).
inline bool depends_on_pressure(const Rheology& r) {
  return std::holds_alternative<MohrCoulomb>(r) || std::holds_alternative<GranularMuI>(r);
}

// The shear stress the material holds at rest under the (effective) pressure p, Pa: the limit of eta(g, p) g as g -> 0
// of the unregularised model. Herschel-Bulkley: tau_y; Mohr-Coulomb: c + max(p, 0) tan(phi); mu(I): mu_s max(p, 0);
// Newtonian: 0. slide check's estimate at rest (cases/build_bodies.cpp) calls it with the effective stress the solver
// gives the rheology (fluid/pore_pressure.hpp).
inline double strength_at_rest(const Rheology& r, double pressure_pa) {
  if (const auto* hb = std::get_if<HerschelBulkley>(&r)) return hb->yield_stress_pa;
  if (const auto* mc = std::get_if<MohrCoulomb>(&r)) return mc->yield_stress(pressure_pa);
  if (const auto* mi = std::get_if<GranularMuI>(&r)) return mi->mu_s * std::max(pressure_pa, 0.0);
  return 0.0;
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
