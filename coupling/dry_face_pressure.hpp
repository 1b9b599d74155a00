#pragma once
// The water under a body that rests on a wall. A body's fluid force is the sum of the pair terms its boundary particles
// exchange with fluid particles (coupling/rigid_bodies.hpp); where a face lies on a wall no fluid particle fits
// between, so that face got no pressure at all: a submerged body resting on a slope was pressed onto it by the water
// on its top and front and lifted by nothing (issue 29: 179 N/m of normal force against a buoyant weight of 43 N/m),
// and any friction held it. In reality the contact is wet, pore water fills the bed's roughness and the film between,
// and carries the water's pressure of its depth.
// So each face of the outline is sampled at points at most dp apart; a sample is in contact when no fluid particle
// lies within dp of its probe point, half a spacing out along the outward normal n (where the first row of a wetted
// face stands), and a boundary particle of something else (a wall, another body) lies within 1.5 dp of it (a wall's
// first layer stands dp / 2 behind its face; a row spacing on the hexagonal lattice). A contact sample under the
// water's surface receives the hydrostatic pressure of its depth (fluid/pore_pressure.hpp, fluid/water_surface.hpp):
//   F = sum over contact samples of -p_w(x_s) n ds,   T = sum (x_s - c) x F_s   (each sum exact).
// With the wetted faces' pair terms (which integrate -p n over those faces) this closes the surface integral, so a
// body at rest in still water feels its buoyancy whatever part of it rests on a wall. Why the wall must be there: a
// face with neither water nor a wall in front of it borders air, a cavity behind a body moving fast through the water
// (measured: the subaerial Heinrich wedge, given the hydrostatic head on such faces too, ran 2.70 m in 1.5 s instead of
// 1.73 m); air carries no water pressure. Above the water p_w = 0: a face of a body in air gets nothing. A floating
// body has no contact face: it is left as it was.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "fluid/exact_sum.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"
#include "fluid/pore_pressure.hpp"

namespace slide {

struct ForceAndTorque {
  Vec<2> force = Vec<2>::Zero();  // N per unit width
  double torque = 0.0;            // N m per unit width, about the centre
};

// Whether any particle for which `is(j)` holds lies within `radius` of `point` (grid: P's binning).
template <class Is>
bool any_near(const Vec<2>& point, double radius, const Particles<2>& P, const NeighborGrid<2>& grid, Is&& is) {
  bool found = false;
  grid.for_each_near(point, radius, P.position, [&](std::uint32_t j, double) { found = found || is(j); });
  return found;
}

// outline: counter-clockwise, in world coordinates, of body `body` (Particles::body_of); centre: its centre of mass.
// Adds the force's x and y and the torque of each contact sample at x for which counted(x) holds to `sums`, exactly
// (fluid/exact_sum.hpp): on several processes each counts the samples in its own cells (Domain::owns_point) and the
// sums are combined, the same to the bit whatever the split.
template <class Counted>
void add_dry_face_samples(const std::vector<Vec<2>>& outline, int body, const Vec<2>& centre, const Particles<2>& P,
                          const NeighborGrid<2>& grid, const PorePressureField<2>& pore, double dp, Counted&& counted,
                          std::array<ExactSum, 3>& sums) {
  const auto fluid = [&](std::uint32_t j) { return P.kind[j] == Kind::fluid; };
  const auto something_else = [&](std::uint32_t j) { return P.kind[j] != Kind::fluid && P.body_of(j) != body; };
  const std::size_t nv = outline.size();
  for (std::size_t k = 0; k < nv; ++k) {
    const Vec<2> a = outline[k], b = outline[(k + 1) % nv];
    const double length = (b - a).norm();
    if (length <= 0.0) continue;
    const Vec<2> t = (b - a) / length;
    const Vec<2> n(t[1], -t[0]);  // outward for a counter-clockwise outline
    const int samples = std::max(1, static_cast<int>(std::ceil(length / dp)));
    const double ds = length / samples;
    for (int m = 0; m < samples; ++m) {
      const Vec<2> x = a + ((m + 0.5) * ds) * t;
      if (!counted(x)) continue;
      const double p = pore.at(x);
      if (p <= 0.0 || any_near(x + 0.5 * dp * n, dp, P, grid, fluid) ||
          !any_near(x, 1.5 * dp, P, grid, something_else))
        continue;
      const Vec<2> f = (-p * ds) * n;
      const Vec<2> arm = x - centre;
      sums[0].add(f[0]);
      sums[1].add(f[1]);
      sums[2].add(arm[0] * f[1] - arm[1] * f[0]);
    }
  }
}

// The same on one process: the force and torque of every contact sample.
inline ForceAndTorque dry_face_pressure(const std::vector<Vec<2>>& outline, int body, const Vec<2>& centre,
                                        const Particles<2>& P, const NeighborGrid<2>& grid,
                                        const PorePressureField<2>& pore, double dp) {
  std::array<ExactSum, 3> sums;
  add_dry_face_samples(outline, body, centre, P, grid, pore, dp, [](const Vec<2>&) { return true; }, sums);
  ForceAndTorque out;
  out.force = Vec<2>(sums[0].value(), sums[1].value());
  out.torque = sums[2].value();
  return out;
}

}  // namespace slide
