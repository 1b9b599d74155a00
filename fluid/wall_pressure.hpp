#pragma once
#include <algorithm>
#include <vector>

#include "fluid/continued_pressure.hpp"
#include "fluid/kernel.hpp"
#include "fluid/name_table.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"

namespace slide {

// Pressure of boundary particles. extrapolated: wall and dummy particles continue the fluid's pressure field; mirror:
// they take the pressure at their mirror image in the fluid plus the hydrostatic head (both below). Classic MPS's
// third model, wall-layer particles taking the pressure of their own number density (seed eq. 7) and dummies none,
// was removed (issue 12): it missed the exact wall tests by 8-11 % at every spacing, its wall layer seeing water on
// one side only, and no case or test found a use for it (its figures: tests/test_wall_models.cpp).
enum class WallPressure { extrapolated, mirror };

inline constexpr auto wall_pressure_names = make_name_table<WallPressure>(
    std::pair{WallPressure::mirror, "mirror"}, std::pair{WallPressure::extrapolated, "extrapolated"});

inline std::string_view to_string(WallPressure w) { return wall_pressure_names.name(w); }

// Pressure of a boundary particle (wall or dummy) extrapolated from its fluid neighbours: the fluid's pressure
// continued into the wall along g - a_w, a_w the wall's acceleration (`head_acceleration`; g for a wall at rest),
// fluid/continued_pressure.hpp (Adami, Hu & Adams 2012, eq. 27). It continues the fluid's pressure field,
// hydrostatic part included, into the wall, so the pressure gradient near a wall sees a complete and consistent
// neighbourhood. A boundary particle with no fluid neighbour has p = 0.
template <int D>
double extrapolated_wall_pressure(std::size_t w, const Particles<D>& P, const NeighborList& nl, double re,
                                  const Vec<D>& head_acceleration) {
  double p = 0.0;
  continued_pressure<D>(w, P, nl, re, head_acceleration, [](std::uint32_t) { return true; }, p);
  return p;
}

// The mirror image of boundary particle w: x_m = x_w + 2 d_w n_w, as far in front of its face as w lies behind it.
template <int D>
Vec<D> mirror_image(std::size_t w, const Particles<D>& P) {
  return P.position[w] + (2.0 * P.wall_depth[w]) * P.wall_normal[w];
}

// The weight of a fluid particle at distance r from a mirror image in the image's pressure (mirror_wall_pressure):
//   w_f = W(r; dp) + 0.05 W(r; 1.5 dp).
inline double mirror_pressure_weight(double r, double dp) {
  return kernel_weight(r, dp) + 0.05 * kernel_weight(r, 1.5 * dp);
}

// How much fluid surrounds a boundary particle's mirror image, relative to a full lattice neighbourhood (capped at 1):
//   fill_w = min(1, sum_f W(|x_f - x_m|; 1.5 dp) / (sum_lattice W(; 1.5 dp) / 2)).
// The half makes any image inside the water count fully, even one beside the wall, whose lattice neighbourhood
// lacks the wall side, or one among disordered particles; an image a spacing above the surface gets 0.06.
// In the mirror model a boundary particle counts in the fluid's number density with this weight: beside water it
// stands for the mirrored fluid particle (weight 1), above the water it is not counted, so a free surface meeting a
// wall has the same number density, hence pressure, as anywhere else instead of being crowded by the dry wall.
// A fluid particle closer to the boundary particle than the lattice spacing (one that presses into the wall, wet or
// dry) also raises the weight, to 1 at half a spacing: proximity = sum_f W(|x_f - x_w|; dp) / W(dp / 2; dp), so
// the wall can never vanish in front of a particle that approaches it.
// The image is a point, found through the grid; the particle's own neighbours within dp are in its list (its radius,
// re + skin, is larger), walked in the grid's order, so the sum is the grid search's to the bit, for a third of its
// candidates (the grid search was 6 % of the bench case, perf).
// keep(f, w_f) is called for each fluid particle f within 1.5 dp of the image, in the grid's order, with its
// pressure weight: mirror_wall_pressure at the same positions needs exactly these, and finding them through the grid
// again was 5 % of the bench case (perf, stop 26).
template <int D, class Keep>
double mirror_fill(std::size_t w, const Particles<D>& P, const NeighborGrid<D>& grid, const NeighborList& nl, double dp,
                   Keep&& keep) {
  const double radius = 1.5 * dp;
  // Full neighbourhood on the lattice: the point itself and its 2 D nearest neighbours at dp; half of it.
  const double half_full = 0.5 * (1.0 + 2 * D * kernel_weight(dp, radius));
  double sum_w = 0.0;
  grid.for_each_near(mirror_image<D>(w, P), radius, P.position, [&](std::uint32_t f, double r2) {
    if (P.kind[f] != Kind::fluid) return;
    const double r = std::sqrt(r2);
    sum_w += kernel_weight(r, radius);
    keep(f, mirror_pressure_weight(r, dp));
  });
  double proximity = 0.0;
  for (const std::uint32_t* q = nl.begin(w); q != nl.end(w); ++q) {
    const double r2 = distance_squared<D>(P.position[*q], P.position[w]);
    if (r2 < dp * dp && P.kind[*q] == Kind::fluid) proximity += kernel_weight(std::sqrt(r2), dp);
  }
  return std::min(1.0, sum_w / half_full + proximity / kernel_weight(0.5 * dp, dp));
}

template <int D>
double mirror_fill(std::size_t w, const Particles<D>& P, const NeighborGrid<D>& grid, const NeighborList& nl,
                   double dp) {
  return mirror_fill<D>(w, P, grid, nl, dp, [](std::uint32_t, double) {});
}

// One fluid particle around a mirror image, with its pressure weight w_f (mirror_pressure_weight).
struct ImageNeighbour {
  std::uint32_t fluid;
  double weight;
};

// Pressure of a boundary particle from its mirror image in the fluid (fixed ghost particles: Takeda, Miyama & Sekiya
// 1994; Marrone et al. 2011): the image point x_m = x_w + 2 d_w n_w lies as far in front of the face as the particle
// lies behind it; its pressure is a Shepard interpolation of the fluid's pressure around x_m, and the hydrostatic
// head between image and particle is added, along g - a_w for a wall accelerating at a_w (`head_acceleration`):
//   p_w = sum_f p_f w_f / sum_f w_f + rho_0 (g - a_w) . (x_w - x_m),
//   w_f = W(|x_f - x_m|; dp) + 0.05 W(|x_f - x_m|; 1.5 dp).
// The narrow kernel makes a particle sitting on the image (the mirrored lattice partner) dominate, so a wall beside
// still water carries exactly its partner's pressure, including at a free surface where the pressure profile is not
// linear; the wide kernel's small share takes over smoothly when no particle is near the image. Why not the plain
// weighted mean around the wall particle: near a free surface it smears the surface's zero pressure into the rows
// below, and the wall pushes the surface particles off it. No fluid near the image (a wall above the water): p = 0.
// The formula above from the image's fluid neighbours (kept by mirror_fill at the same positions).
template <int D>
double mirror_wall_pressure(std::size_t w, const Particles<D>& P, const ImageNeighbour* begin, const ImageNeighbour* end,
                            const Vec<D>& head_acceleration) {
  double sum_w = 0.0, sum_pw = 0.0, sum_rho_w = 0.0;
  for (const ImageNeighbour* q = begin; q != end; ++q) {
    sum_w += q->weight;
    sum_pw += q->weight * P.pressure[q->fluid];
    sum_rho_w += q->weight * P.density[q->fluid];
  }
  if (sum_w <= 0.0) return 0.0;
  return (sum_pw + sum_rho_w * head_acceleration.dot(P.position[w] - mirror_image<D>(w, P))) / sum_w;
}

// The same, finding the image's fluid neighbours through the grid (the step uses the kept ones; this is for a
// boundary particle alone, and the tests). The scratch is the thread's own, so a call allocates nothing once grown.
template <int D>
double mirror_wall_pressure(std::size_t w, const Particles<D>& P, const NeighborGrid<D>& grid, double dp,
                            const Vec<D>& head_acceleration) {
  thread_local std::vector<ImageNeighbour> near;
  near.clear();
  grid.for_each_near(mirror_image<D>(w, P), 1.5 * dp, P.position, [&](std::uint32_t f, double r2) {
    if (P.kind[f] == Kind::fluid) near.push_back({f, mirror_pressure_weight(std::sqrt(r2), dp)});
  });
  return mirror_wall_pressure<D>(w, P, near.data(), near.data() + near.size(), head_acceleration);
}

}  // namespace slide
