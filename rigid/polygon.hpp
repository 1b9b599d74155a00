#pragma once
// Planar polygons: the outline of a rigid body per unit width. Area, centroid and polar moment by the shoelace
// formulas; convexity; the inset used to keep Bullet's collision margin inside the outline.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace slide::rigid {

using Vec2 = Eigen::Matrix<double, 2, 1, Eigen::DontAlign>;

inline double cross(const Vec2& a, const Vec2& b) { return a[0] * b[1] - a[1] * b[0]; }

// Signed area: positive when the vertices run counter-clockwise. A = 1/2 sum (x_k y_k+1 - x_k+1 y_k).
inline double signed_area(const std::vector<Vec2>& v) {
  double a = 0.0;
  for (std::size_t k = 0; k < v.size(); ++k) a += cross(v[k], v[(k + 1) % v.size()]);
  return 0.5 * a;
}

// Centroid: c = 1/(6A) sum (v_k + v_k+1) (x_k y_k+1 - x_k+1 y_k).
inline Vec2 centroid(const std::vector<Vec2>& v) {
  Vec2 c = Vec2::Zero();
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec2& a = v[k];
    const Vec2& b = v[(k + 1) % v.size()];
    c += cross(a, b) * (a + b);
  }
  return c / (6.0 * signed_area(v));
}

// Polar second moment of area about the centroid (per unit width, m^4):
// J_origin = 1/12 sum cross(v_k, v_k+1) (|v_k|^2 + v_k . v_k+1 + |v_k+1|^2), then J_c = J_origin - A |c|^2.
inline double polar_moment_about_centroid(const std::vector<Vec2>& v) {
  const Vec2 c = centroid(v);
  double j = 0.0;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec2 a = v[k] - c, b = v[(k + 1) % v.size()] - c;
    j += cross(a, b) * (a.squaredNorm() + a.dot(b) + b.squaredNorm());
  }
  return std::abs(j) / 12.0;
}

inline std::vector<Vec2> counter_clockwise(std::vector<Vec2> v) {
  if (signed_area(v) < 0.0) std::reverse(v.begin(), v.end());
  return v;
}

// Strictly convex, counter-clockwise, at least three vertices.
inline bool is_convex_ccw(const std::vector<Vec2>& v) {
  if (v.size() < 3) return false;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec2 e0 = v[(k + 1) % v.size()] - v[k], e1 = v[(k + 2) % v.size()] - v[(k + 1) % v.size()];
    if (cross(e0, e1) <= 0.0) return false;
  }
  return true;
}

// Inside (or on) a convex counter-clockwise polygon.
inline bool contains(const std::vector<Vec2>& v, const Vec2& p) {
  for (std::size_t k = 0; k < v.size(); ++k)
    if (cross(v[(k + 1) % v.size()] - v[k], p - v[k]) < 0.0) return false;
  return true;
}

// Distance from p to the polygon's outline.
inline double distance_to_outline(const std::vector<Vec2>& v, const Vec2& p) {
  double best = INFINITY;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec2 a = v[k], b = v[(k + 1) % v.size()];
    const Vec2 ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    best = std::min(best, (a + t * ab - p).norm());
  }
  return best;
}

// The convex counter-clockwise polygon moved inwards by distance d: each edge's line shifted along its inward
// normal, consecutive lines intersected. Bullet adds its collision margin around a convex hull, so the hull of the
// inset polygon with margin d collides at the true outline (with corners rounded by d).
inline std::vector<Vec2> inset(const std::vector<Vec2>& v, double d) {
  const std::size_t n = v.size();
  std::vector<Vec2> out(n);
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 a = v[(k + n - 1) % n], b = v[k], c = v[(k + 1) % n];
    const Vec2 t0 = (b - a).normalized(), t1 = (c - b).normalized();
    const Vec2 n0(-t0[1], t0[0]), n1(-t1[1], t1[0]);  // inward for counter-clockwise order
    // Point on both shifted lines: b + d (n0 + n1) / (1 + n0 . n1) (the mitre).
    out[k] = b + d * (n0 + n1) / (1.0 + n0.dot(n1));
  }
  if (!is_convex_ccw(out)) throw std::invalid_argument("polygon too small for the collision margin");
  return out;
}

}  // namespace slide::rigid
