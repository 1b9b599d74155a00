#pragma once
// Pressure of free-surface particles (number density below beta n0).
#include <string_view>

#include "fluid/continued_pressure.hpp"
#include "fluid/name_table.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"

namespace slide {

// zero: the classic MPS free-surface condition, p = 0 on every particle with n < beta n0.
// extrapolated: such a particle continues the pressure of its bulk neighbours (those with n >= beta n0), hydrostatic
// head included, the same extrapolation a wall particle gets (fluid/wall_pressure.hpp).
enum class SurfacePressure { zero, extrapolated };

inline constexpr auto surface_pressure_names = make_name_table<SurfacePressure>(
    std::pair{SurfacePressure::zero, "zero"}, std::pair{SurfacePressure::extrapolated, "extrapolated"});

inline std::string_view to_string(SurfacePressure s) { return surface_pressure_names.name(s); }

// Pressure of a free-surface particle s from its bulk fluid neighbours b (is_bulk(b)), continued along g as a wall's
// is (fluid/continued_pressure.hpp, after Adami, Hu & Adams 2012, eq. 27), never below zero:
//   p_s = max(0, ( sum_b p_b W_sb + g . sum_b rho_b (r_s - r_b) W_sb ) / sum_b W_sb ),   0 with no bulk neighbour.
// Why: a particle of the top row stands about dp / 2 below the water's edge, so its pressure is rho g dp / 2, not 0.
// Given 0, the top row is supported only by the row below, through a one-sided sum that carries about half the
// gradient; the rows below then hold the water's weight only with a steeper pressure near the top, and the
// pressure line of the bulk reaches zero above the particles' edge, which lifts a floating body by as much. Measured
// (floating boxes of 300-900 kg/m^3 placed at their drafts, 1 s at rest): mean draft error 0.82 % at dp 0.005 and
// 1.73 % at dp 0.01, against 1.45 % and 2.59 % with zero.
// Its limit: the head is hydrostatic, so it is right only where the water near the surface is at rest. Where the
// surface is not level or the water accelerates (a released column's side) it adds pressure the flow does not have.
template <int D, class IsBulk>
double extrapolated_surface_pressure(std::size_t s, const Particles<D>& P, const NeighborList& nl, double re,
                                     const Vec<D>& gravity, const IsBulk& is_bulk) {
  double p = 0.0;
  continued_pressure<D>(s, P, nl, re, gravity, is_bulk, p);
  return p > 0.0 ? p : 0.0;
}

}  // namespace slide
