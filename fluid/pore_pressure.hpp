#pragma once
// Effective stress in a saturated sediment: the frictional strengths (the Mohr-Coulomb yield stress, mu(I)'s
// eta = mu p / g, the Coulomb basal friction, fluid/basal_friction.hpp) act on the stress the grains carry, the total
// pressure less the pore water's (Terzaghi's principle, Terzaghi 1943, Theoretical Soil Mechanics, ch. 2):
//   p' = p - p_w.
// A sediment particle of this MPS mixture carries the total pressure p of water and grains together (its number
// density's, seed eq. 7, at the mixture's density). Under water at rest p grows with depth as the water's head plus
// the sediment's own weight, so a strength on p counts the water's head as if the grains carried it: at the base of
// a 9 cm slide under 4 cm of water, 2.6 times the effective stress (issue 29), and a submerged slide never moved.
//
// The pore pressure is the drained, hydrostatic one below the water's local free surface (fluid/water_surface.hpp):
//   p_w(x) = rho_w |g| max(0, eta(x) - h(x)),
// rho_w the pore water's density, h the height along -g, eta the surface above x. It is the drained limit: the pore
// water keeps its hydrostatic head, as in depth-averaged models of saturated debris at their hydrostatic pore-pressure
// ratio (the basal ratio lambda = p_w / sigma_n = rho_w / rho of Iverson & Denlinger 2001, J. Geophys. Res. 106(B1),
// 537-552). Particle mixture models of a saturated bed likewise put the effective, not the total, pressure in their
// yield criterion (Fourtakas & Rogers 2016, Adv. Water Resour. 92, 186-199, Drucker-Prager). Above the water (a slide
// before it enters) p_w = 0, and it grows from 0 continuously as a particle goes under: no jump at the surface.
// Chosen against the water phase's own pressure interpolated at the sediment particle: inside a slide thicker than
// the kernel radius a sediment particle has no water neighbours to interpolate from, so that alternative needs the
// hydrostatic head anyway below the slide's first rows.
// What it leaves out (docs/slides-under-water.md): pore pressure that differs from hydrostatic, the excess pore
// pressure of a contracting or dilating grain skeleton and its diffusion (Pailha & Pouliquen 2009, J. Fluid Mech.
// 633, 115-135; Iverson 2000), consolidation, and the waves' dynamic pressure inside the slide.
#include <algorithm>

#include "fluid/name_table.hpp"
#include "fluid/water_surface.hpp"

namespace slide {

// How the pore water's pressure is estimated: none (the frictional strengths act on the total pressure, the model
// before issue 29: right for a dry material) or hydrostatic (above).
enum class PorePressureModel { none, hydrostatic };

inline constexpr auto pore_pressure_names = make_name_table<PorePressureModel>(
    std::pair{PorePressureModel::hydrostatic, "hydrostatic"}, std::pair{PorePressureModel::none, "none"});

inline std::string_view to_string(PorePressureModel m) { return pore_pressure_names.name(m); }

// p_w = rho_w g z for a depth z >= 0 below the water's surface, Pa.
inline double hydrostatic_pore_pressure(double water_density_kg_m3, double gravity_m_s2, double depth_m) {
  return water_density_kg_m3 * gravity_m_s2 * std::max(depth_m, 0.0);
}

// p' = p - p_w, Pa: what the grains carry. Not clamped: a negative effective pressure has no frictional strength, and
// every rheology says so itself (fluid/rheology/).
inline double effective_pressure(double total_pa, double pore_pa) { return total_pa - pore_pa; }

// The pore pressure at any point of a scene: the water's density, gravity's magnitude and the water's surface.
template <int D>
struct PorePressureField {
  double water_density_kg_m3 = 0.0;
  double gravity_m_s2 = 0.0;
  const WaterSurface<D>* surface = nullptr;  // null: no pore water (a dry scene, or the model none)

  double at(const Vec<D>& x) const {
    if (!surface) return 0.0;
    return hydrostatic_pore_pressure(water_density_kg_m3, gravity_m_s2, surface->depth_below_surface(x));
  }
};

}  // namespace slide
