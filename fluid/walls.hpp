#pragma once
// Boundary particles from a wall described by its face: a polyline in 2-D with the fluid on one side.
// Layer k (k = 0 the wall layer, k >= 1 dummy layers) lies at (k + 1/2) dp behind the face, so the first fluid
// particles, half a spacing in front of the face, are one spacing from the wall layer.
#include <cmath>
#include <stdexcept>
#include <vector>

#include "fluid/particles.hpp"

namespace slide {

struct BoundaryPoint {
  Vec<2> position;
  Vec<2> normal;  // unit, from the face into the fluid
  double depth;   // distance behind the face
  int layer;      // 0 wall, >= 1 dummy
};

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

}  // namespace slide
