#pragma once
// Boundary particles from a wall described by its face: a polyline in 2-D with the fluid on one side.
// Layer k (k = 0 the wall layer, k >= 1 dummy layers) lies at (k + 1/2) dp behind the face, so the first fluid
// particles, half a spacing in front of the face, are one spacing from the wall layer.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "fluid/lattice.hpp"
#include "fluid/particles.hpp"

namespace slide {

template <int D>
struct BoundaryPointOf {
  Vec<D> position;
  Vec<D> normal;  // unit, from the face into the fluid
  double depth;   // distance behind the face
  int layer;      // 0 wall, >= 1 dummy
};
using BoundaryPoint = BoundaryPointOf<2>;

// Layers needed so that a fluid particle half a spacing from the face has its whole kernel support filled:
// the deepest layer, at (L - 1/2) dp, must reach re - dp/2 behind the face.
inline int boundary_layers(double re_over_dp) { return static_cast<int>(std::ceil(re_over_dp - 1e-9)); }

// face: vertices in order; fluid_on_left: whether the fluid lies to the left of the direction of travel.
// Points are spaced dp along each offset segment, anchored at the corners so that a rectangular tank whose sides
// are multiples of dp gives an exact square lattice continuing the fluid's.
inline std::vector<BoundaryPoint> polyline_boundary(const std::vector<Vec<2>>& face, bool fluid_on_left, double dp,
                                                    int layers) {
  const std::size_t nv = face.size();
  if (nv < 2) throw std::invalid_argument("a wall needs at least two vertices");
  const std::size_t ns = nv - 1;
  std::vector<Vec<2>> dir(ns), inward(ns);
  for (std::size_t s = 0; s < ns; ++s) {
    const Vec<2> d = face[s + 1] - face[s];
    const double len = d.norm();
    if (len <= 0.0) throw std::invalid_argument("a wall has two equal consecutive vertices");
    dir[s] = d / len;
    const Vec<2> left(-dir[s][1], dir[s][0]);
    inward[s] = fluid_on_left ? left : Vec<2>(-left);
  }
  // A closed face (last vertex equal to the first) has a corner at every vertex.
  const bool closed = ns >= 3 && (face.front() - face.back()).norm() <= 1e-12 * (1.0 + face.front().norm());
  std::vector<BoundaryPoint> out;
  for (int k = 0; k < layers; ++k) {
    const double off = (k + 0.5) * dp;
    // Offset vertices with mitred corners.
    std::vector<Vec<2>> v(nv);
    for (std::size_t i = 0; i < nv; ++i) {
      if (closed && (i == 0 || i == nv - 1)) {
        const Vec<2> a = inward[ns - 1], b = inward[0];
        v[i] = face[i] - off * (a + b) / (1.0 + a.dot(b));
      } else if (i == 0) {
        v[i] = face[i] - off * inward[0];
      } else if (i == nv - 1) {
        v[i] = face[i] - off * inward[ns - 1];
      } else {
        const Vec<2> a = inward[i - 1], b = inward[i];
        v[i] = face[i] - off * (a + b) / (1.0 + a.dot(b));
      }
    }
    for (std::size_t s = 0; s < ns; ++s) {
      const Vec<2> p0 = v[s], p1 = v[s + 1];
      const double len = (p1 - p0).norm();
      if (len <= 1e-12) continue;
      const Vec<2> t = (p1 - p0) / len;
      const bool start_corner = closed || s > 0, end_corner = closed || s + 1 < ns;
      auto push = [&](const Vec<2>& x) {
        // A particle on a mitred corner belongs to both faces: its normal is the bisector and its depth the
        // distance to the face's vertex, so that its mirror image (x + 2 depth normal) is the fluid corner.
        if (start_corner && (x - p0).squaredNorm() < 1e-20 * dp * dp) {
          const Vec<2> to_face = face[s] - x;
          out.push_back({x, to_face.normalized(), to_face.norm(), k});
        } else {
          out.push_back({x, inward[s], off, k});
        }
      };
      if (start_corner && end_corner) {
        const int n = std::max(1, static_cast<int>(std::lround(len / dp)));
        for (int m = 0; m < n; ++m) push(p0 + (len * m / n) * t);
      } else if (start_corner || !end_corner) {
        // Anchored at the start; the open end stops where the next point would overshoot.
        for (int m = 0; m * dp <= len + 1e-9 * dp; ++m) push(p0 + (m * dp) * t);
      } else {
        // First segment of several: anchored at its end corner, walking back to the open start.
        for (int m = 1; m * dp <= len + 1e-9 * dp; ++m) push(p1 - (m * dp) * t);
      }
    }
  }
  return out;
}

// Whether a face segment runs along the hexagonal lattice's rows (horizontal) or its columns (vertical), where the
// lattice's own points make its wall (lattice_boundary). Any other direction gets rows of its own.
inline bool along_lattice_axes(const Vec<2>& a, const Vec<2>& b) {
  const Vec<2> d = b - a;
  return std::abs(d[0]) <= 1e-9 * d.norm() || std::abs(d[1]) <= 1e-9 * d.norm();
}

// How far in front of a wall face the water's lattice points start: half a spacing on the square lattice (its wall
// layers lie at (k + 1/2) dp behind the face); on the hexagonal lattice at the face itself where the wall is the
// lattice's own points (they split one lattice), and half a row spacing where the wall has rows laid along the face
// (lattice_boundary), so that no water lies closer to the first row than a row spacing.
inline double water_clearance(LatticeKind kind, double dp, const Vec<2>& a, const Vec<2>& b) {
  if (kind == LatticeKind::square) return 0.5 * dp;
  return along_lattice_axes(a, b) ? 0.0 : 0.5 * row_spacing(kind, dp);
}

// Boundary particles for the hexagonal lattice, whose rows cannot follow a face. Each lattice point behind the face,
// no deeper than re, belongs to its nearest face segment (the first of equally near ones); a point whose nearest face
// point is an open end of the polyline is left out (a closed polyline, such as a body's outline, has none).
//  * A segment along the lattice's rows or columns (along_lattice_axes) takes the fluid's own lattice points: fluid
//    and boundary form one unbroken lattice, so the fluid next to such a wall has the number density of the bulk.
//  * Any other segment takes a hexagonal lattice of the same spacings laid along it (fluid/lattice.hpp,
//    face_lattice_point): rows parallel to the face at (k + 1/2) h behind it (h the row spacing), points a apart
//    along each row, odd rows shifted by a / 2, anchored at the segment's first vertex. Why: the fluid's lattice
//    cut along a slope is a staircase of steps one row high, and a slide on it was held as if by friction (a stiff
//    sediment block on a frictionless 20 / 35 / 45 degree slope accelerated 46 / 16 / 23 % below g sin(beta), and
//    hopped 0.8 dp off the steps; with rows along the face, -2.7 / +0.0 / -1.6 %: tests/test_slope_slide.cpp). A
//    face made of rows along it is a plane: the water's first row meets one flat row, whatever the angle. Measured
//    and rejected: the variational gradient's wall pairs split as the symmetric model's (normal part p_i + p_j,
//    tangential p_j - p_i) made still water against a 35 degree slope stir itself (largest speed 55 % of
//    sqrt(g H) after 1 s, against 3 %), and a wall pushing only along its normal left the water's first rows with
//    half their pressure gradient along the face.
// Normal and depth are those of the nearest face point (the bisecting direction behind a corner); layer 0 (the wall
// layer) is everything less than one row spacing deep. Where two segments' points meet behind a vertex they may lie
// closer than a spacing; the caller leaves out a point within dp / 2 of one already placed.
inline std::vector<BoundaryPoint> lattice_boundary(const std::vector<Vec<2>>& face, bool fluid_on_left, double dp,
                                                   double re, LatticeKind kind,
                                                   const Vec<2>& offset = Vec<2>::Zero()) {
  const std::size_t nv = face.size();
  if (nv < 2) throw std::invalid_argument("a wall needs at least two vertices");
  for (std::size_t s = 0; s + 1 < nv; ++s)
    if ((face[s + 1] - face[s]).norm() <= 0.0) throw std::invalid_argument("a wall has two equal consecutive vertices");
  const double eps = 1e-9 * dp, row = row_spacing(kind, dp), a = nearest_spacing(kind, dp);
  // A closed face (last vertex equal to the first, a body's outline) has no open ends.
  const bool closed = nv >= 4 && (face.front() - face.back()).norm() <= 1e-12 * (1.0 + face.front().norm());
  std::vector<BoundaryPoint> out;
  // Keeps p if owns(its nearest segment) (the first of equally near ones) and it lies behind the face within re.
  auto keep = [&](auto&& owns, const Vec<2>& p) {
    double best = std::numeric_limits<double>::infinity();
    Vec<2> nearest = Vec<2>::Zero(), inward = Vec<2>::Zero();
    bool open_end = false;
    std::size_t nearest_segment = 0;
    for (std::size_t s = 0; s + 1 < nv; ++s) {
      const Vec<2> d = face[s + 1] - face[s];
      const Vec<2> left = Vec<2>(-d[1], d[0]).normalized();
      const double t = std::clamp((p - face[s]).dot(d) / d.squaredNorm(), 0.0, 1.0);
      const Vec<2> c = face[s] + t * d;
      const double dist = (p - c).norm();
      if (dist < best - eps) {
        best = dist;
        nearest = c;
        nearest_segment = s;
        inward = fluid_on_left ? left : Vec<2>(-left);
        open_end = !closed && ((t == 0.0 && s == 0) || (t == 1.0 && s + 2 == nv));
      }
    }
    if (!owns(nearest_segment) || open_end || best > re + eps || (p - nearest).dot(inward) > eps) return;
    // Behind a corner the nearest face point is the vertex: the normal points from the particle to it.
    const bool corner = best > eps && (nearest - p).normalized().dot(inward) < 1.0 - 1e-9;
    const Vec<2> normal = corner ? Vec<2>((nearest - p).normalized()) : inward;
    out.push_back({p, normal, best, best < row - eps ? 0 : 1});
  };
  // The lattice's own points first, in the lattice's order (the order of the walls before rows along faces).
  auto on_lattice = [&](std::size_t s) {
    return kind == LatticeKind::square || along_lattice_axes(face[s], face[s + 1]);
  };
  Vec<2> lo = face[0], hi = face[0];
  for (const auto& q : face) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  for_each_lattice_point(kind, dp, lo - Vec<2>::Constant(re), hi + Vec<2>::Constant(re),
                         [&](const Vec<2>& p) { keep(on_lattice, p); }, offset);
  for (std::size_t s = 0; s + 1 < nv; ++s) {
    if (on_lattice(s)) continue;
    const Vec<2> along = (face[s + 1] - face[s]).normalized(), left(-along[1], along[0]);
    const Vec<2> out_of_wall = fluid_on_left ? left : Vec<2>(-left);
    const long rows = static_cast<long>(std::floor(re / row - 0.5 + 1e-9)) + 1;
    const long last = static_cast<long>(std::ceil(((face[s + 1] - face[s]).norm() + re) / a)) + 1;
    for (long k = -1; k >= -rows; --k)
      for (long i = static_cast<long>(std::floor(-re / a)) - 1; i <= last; ++i)
        keep([s](std::size_t own) { return own == s; },
             face_lattice_point(kind, dp, face[s], along, out_of_wall, i, k));
  }
  return out;
}

}  // namespace slide
