#pragma once
// Boundary particles of a tank in 3-D: the inside of an axis-aligned box [lo, hi] holds the fluid, open above (along
// the last axis, z up); its floor and four sides are cut from the fluid's own lattice, as the 2-D walls are
// (fluid/walls.hpp), so that the lattice runs on through them:
//  * square (simple cubic): `layers` layers, the points whose largest distance outside the inside along any one axis
//    is (k + 1/2) dp for k < layers (a tank whose corners lie on multiples of dp continues the fluid's lattice);
//  * fcc: every lattice point on or behind a face to the depth `depth` (re), as the hexagonal lattice's walls in 2-D;
//    layer k: the points whose largest distance outside lies in [k s, (k + 1) s), s the plane spacing.
// A point's normal and depth are those to the nearest point of the inside (extended upwards): behind one face, that
// face's normal and distance; along an edge or at a corner, the direction to the edge or corner, so that its mirror
// image (x + 2 depth normal) lies in the fluid's corner, as polyline_boundary's mitred corners do in 2-D. A point on a
// face (fcc) has that face's normal (the sum of its faces', normalised, on an edge) and depth 0.
// A side in `mirror_sides` (bit 2 a: the min face across axis a, bit 2 a + 1: the max face; a < 2) is a plane of
// symmetry: it has no particles beyond it (the water's and the other walls' mirror images stand there,
// fluid/ghosts.hpp), and the inside runs on through it, so that the floor and the other sides meet it with the normals
// of faces, not edges. A lattice point on it (the fcc lattice is moved to put a plane there: cases/build_geometry_3d.cpp)
// is its own image: inside, it is the water's; in the floor or a side, the wall's.
// The lattice is moved by `offset` (fluid/lattice.hpp: for_each_lattice_point).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "fluid/lattice.hpp"
#include "fluid/walls.hpp"

namespace slide {

// Whether p lies in the tank's inside: strictly (by eps) inside [lo, hi] across, above lo along z (open above).
inline bool inside_tank(const Vec<3>& p, const Vec<3>& lo, const Vec<3>& hi, double eps) {
  return p[0] > lo[0] + eps && p[0] < hi[0] - eps && p[1] > lo[1] + eps && p[1] < hi[1] - eps && p[2] > lo[2] + eps;
}

// The bit of tank_boundary's mirror_sides for the min (max) face across axis a.
inline unsigned tank_side_bit(int axis, bool max_face) { return 1u << (2 * axis + (max_face ? 1 : 0)); }

inline std::vector<BoundaryPointOf<3>> tank_boundary(LatticeKind kind, const Vec<3>& lo, const Vec<3>& hi, double dp,
                                                     int layers, double depth, unsigned mirror_sides = 0,
                                                     const Vec<3>& offset = Vec<3>::Zero()) {
  for (int a = 0; a < 3; ++a)
    if (!(hi[a] > lo[a])) throw std::invalid_argument("a tank's max must exceed its min along every axis");
  if (kind == LatticeKind::square && layers < 1) throw std::invalid_argument("a tank needs at least one boundary layer");
  const bool square = kind == LatticeKind::square;
  const double spacing = row_spacing(kind, dp), thickness = square ? layers * dp : depth, eps = 1e-9 * dp;
  Vec<3> box_lo = lo - Vec<3>::Constant(thickness), box_hi = hi + Vec<3>::Constant(thickness);
  box_hi[2] = hi[2];  // the sides end at the tank's top
  const auto mirror = [&](int a, bool max_face) { return (mirror_sides & tank_side_bit(a, max_face)) != 0; };
  Vec<3> inside_lo = lo, inside_hi = hi;  // the inside, closed on the planes of symmetry
  for (int a = 0; a < 2; ++a) {
    if (mirror(a, false)) inside_lo[a] -= 2.0 * eps;
    if (mirror(a, true)) inside_hi[a] += 2.0 * eps;
  }
  std::vector<BoundaryPointOf<3>> out;
  const auto visit = [&](const Vec<3>& p) {
    if (p[2] > hi[2] + eps || p[2] < box_lo[2] - eps || inside_tank(p, inside_lo, inside_hi, eps)) return;
    for (int a = 0; a < 2; ++a)  // beyond a plane of symmetry: its mirror images' place (a point on it is its own)
      if ((mirror(a, false) && p[a] < lo[a] - eps) || (mirror(a, true) && p[a] > hi[a] + eps)) return;
    Vec<3> nearest = p;  // the nearest point of the inside, open above and through the planes of symmetry
    for (int a = 0; a < 3; ++a)
      if (a == 2 || !mirror(a, false)) nearest[a] = std::max(nearest[a], lo[a]);
    for (int a = 0; a < 2; ++a)
      if (!mirror(a, true)) nearest[a] = std::min(nearest[a], hi[a]);
    const Vec<3> to_inside = nearest - p;
    const double outside = to_inside.cwiseAbs().maxCoeff();  // along one axis: the layer's distance
    if (outside > thickness + eps || (square && outside < eps)) return;
    const int layer = static_cast<int>(std::floor((square ? outside - 0.5 * dp : outside) / spacing + 1e-9));
    if (to_inside.norm() > eps) {
      out.push_back({p, to_inside / to_inside.norm(), to_inside.norm(), std::max(0, layer)});
      return;
    }
    Vec<3> normal = Vec<3>::Zero();  // on a face: its inward normal (a plane of symmetry is none)
    for (int a = 0; a < 3; ++a)
      if (std::abs(p[a] - lo[a]) <= eps && (a == 2 || !mirror(a, false))) normal[a] += 1.0;
    for (int a = 0; a < 2; ++a)
      if (std::abs(p[a] - hi[a]) <= eps && !mirror(a, true)) normal[a] -= 1.0;
    out.push_back({p, normal.normalized(), 0.0, 0});
  };
  for_each_lattice_point(kind, dp, box_lo, box_hi, visit, offset);
  return out;
}

}  // namespace slide
