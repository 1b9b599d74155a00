#include "cases/scene_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slide::cases {

std::vector<Vec<2>> points_of(const YAML::Node& n) {
  std::vector<Vec<2>> out;
  for (const auto& p : n) out.push_back(vec2(p));
  return out;
}

bool inside_polygon(const std::vector<Vec<2>>& poly, const Vec<2>& p) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const auto &a = poly[i], &b = poly[j];
    if ((a[1] > p[1]) != (b[1] > p[1]) && p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0]) in = !in;
  }
  return in;
}

std::vector<FaceSegment> face_segments(const std::vector<Vec<2>>& face, bool fluid_on_left) {
  std::vector<FaceSegment> out;
  for (std::size_t s = 0; s + 1 < face.size(); ++s) {
    const Vec<2> d = (face[s + 1] - face[s]).normalized();
    const Vec<2> l(-d[1], d[0]);
    out.push_back({face[s], face[s + 1], fluid_on_left ? l : Vec<2>(-l)});
  }
  return out;
}

double signed_face_distance(const std::vector<FaceSegment>& faces, const Vec<2>& p) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  double best = inf, signed_best = -inf;
  for (const auto& f : faces) {
    const Vec<2> ab = f.b - f.a;
    const double t = std::clamp((p - f.a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    const Vec<2> q = f.a + t * ab;
    const double d = (p - q).norm();
    const double s = (p - q).dot(f.inward) >= 0.0 ? d : -d;
    // A point outside a corner is as far from the vertex along both faces; it lies behind the wall.
    if (d < best - 1e-12 || (d <= best + 1e-12 && s < signed_best)) {
      best = std::min(best, d);
      signed_best = s;
    }
  }
  return signed_best;
}

bool clear_of_faces(const std::vector<FaceSegment>& faces, const Vec<2>& p, double eps) {
  if (signed_face_distance(faces, p) < eps) return false;
  for (const auto& f : faces) {
    const Vec<2> ab = f.b - f.a;
    const double t = std::clamp((p - f.a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    if ((p - (f.a + t * ab)).norm() < f.clearance - eps) return false;
  }
  return true;
}

std::optional<FaceSegment> resting_face(const std::vector<FaceSegment>& faces, const std::vector<rigid::Vec2>& outline,
                                        double dp, const Vec<2>& down) {
  std::optional<FaceSegment> found;
  double steepest = -1.0;
  for (const auto& f : faces) {
    int touching = 0;
    for (const auto& v : outline) touching += std::abs(signed_face_distance({f}, from_rigid(v))) < 0.5 * dp;
    if (touching < 2) continue;
    const double steep = std::abs((f.b - f.a).normalized().dot(down));  // sin theta
    if (steep > steepest) steepest = steep, found = f;
  }
  return found;
}

void face_bounds(const std::vector<FaceSegment>& faces, Vec<2>& lo, Vec<2>& hi) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  lo = Vec<2>::Constant(inf);
  hi = Vec<2>::Constant(-inf);
  for (const auto& f : faces) {
    lo = lo.cwiseMin(f.a).cwiseMin(f.b);
    hi = hi.cwiseMax(f.a).cwiseMax(f.b);
  }
}

double area_below(const std::vector<rigid::Vec2>& v, double level) {
  std::vector<rigid::Vec2> clipped;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const rigid::Vec2 a = v[k], b = v[(k + 1) % v.size()];
    const bool ain = a[1] <= level, bin = b[1] <= level;
    if (ain) clipped.push_back(a);
    if (ain != bin) clipped.push_back(a + (level - a[1]) / (b[1] - a[1]) * (b - a));
  }
  return clipped.size() < 3 ? 0.0 : std::abs(rigid::signed_area(clipped));
}

// p + t d = a + s (b - a) with t >= 0 and s in [0, 1], solved by Cramer's rule; a segment parallel to the ray is
// met only when it lies on it.
bool ray_meets_segment(const Vec<2>& p, const Vec<2>& d, const Vec<2>& a, const Vec<2>& b) {
  const Vec<2> e = b - a, w = a - p;
  const double det = e[0] * d[1] - e[1] * d[0];  // cross(e, d)
  if (det == 0.0) {
    if (w[0] * d[1] - w[1] * d[0] != 0.0) return false;  // parallel, off the ray's line
    return w.dot(d) >= 0.0 || (b - p).dot(d) >= 0.0;
  }
  const double t = (e[0] * w[1] - e[1] * w[0]) / det;  // cross(e, w) / cross(e, d)
  const double s = (d[0] * w[1] - d[1] * w[0]) / det;  // cross(d, w) / cross(e, d)
  return t >= 0.0 && s >= 0.0 && s <= 1.0;
}

}  // namespace slide::cases
