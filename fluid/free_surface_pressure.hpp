#pragma once
// Pressure of free-surface particles (number density below beta n0).
#include <string_view>

#include "fluid/continued_pressure.hpp"
#include "fluid/name_table.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"

namespace slide {

// zero: the classic MPS free-surface condition, p = 0 on every particle with n < beta n0.
// half_layer: such a particle carries the head of the half layer of water above its centre (half_layer_pressure).
// extrapolated: such a particle continues the pressure of its bulk neighbours (those with n >= beta n0), hydrostatic
// head included, the same extrapolation a wall particle gets (fluid/wall_pressure.hpp).
enum class SurfacePressure { zero, half_layer, extrapolated };

inline constexpr auto surface_pressure_names = make_name_table<SurfacePressure>(
    std::pair{SurfacePressure::zero, "zero"}, std::pair{SurfacePressure::half_layer, "half_layer"},
    std::pair{SurfacePressure::extrapolated, "extrapolated"});

inline std::string_view to_string(SurfacePressure s) { return surface_pressure_names.name(s); }

// Pressure of a free-surface particle of density rho on a lattice whose layers across g are `layer_thickness` apart
// (fluid/lattice.hpp, row_spacing), the head of the half layer above its centre:
//   p_s = rho |g| layer_thickness / 2.
// Why: the top layer's centres stand half a layer below the water's edge (the edge a still level's particle count
// gives), so their pressure is this, not 0 (see extrapolated_surface_pressure below for what 0 does to a floating
// body). Why not extrapolated: continuing the bulk's pressure to the surface feeds the bulk's compression back into
// the top layer's push on it, and that loop drives the water column's acoustic mode. Measured on still water 0.159 m
// deep in a 0.2 m x 0.2 m tank (fcc, dp 0.01, settled 2 s at damping 3 /s), mean fluid speed 0.06 / 0.3 / 0.6 s after
// the start: extrapolated 1.1e-2 / 2.0e-2 / 2.4e-2 m/s (largest 0.18 m/s) and growing; zero 1.5e-3 / 1.6e-3 /
// 1.9e-3 m/s; half_layer 3.3e-4 / 2.5e-4 / 2.2e-4 m/s (largest 1.2e-3 m/s). That was at c0 = 10 sqrt(g H) and holds
// for that tank only: in others half_layer rings at 10 and extrapolated does not; at the 3-D default c0 (20 sqrt(g H))
// neither rings (docs/three-d.md). Its limit is extrapolated's: the head is that of water at rest under a level
// surface.
inline double half_layer_pressure(double density, double gravity, double layer_thickness) {
  return 0.5 * density * gravity * layer_thickness;
}

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
