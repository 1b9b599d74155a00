#pragma once
// The plane geometry a scene is built with: points read from the scene, the wall faces and the signed distance from
// them, point-in-polygon for regions, and the part of a body's outline below a level. Convex-outline operations
// (area, centroid, contains, distance to the outline) are rigid/polygon.hpp's.
#include <yaml-cpp/yaml.h>

#include <optional>
#include <string>
#include <vector>

#include "fluid/vec.hpp"
#include "rigid/polygon.hpp"

namespace slide::cases {

// A point [x, y] ([x, y, z] in 3-D) and a list of points, as the schema has checked them.
template <int D>
Vec<D> vec_of(const YAML::Node& n) {
  Vec<D> v;
  for (int k = 0; k < D; ++k) v[k] = n[k].as<double>();
  return v;
}
inline Vec<2> vec2(const YAML::Node& n) { return vec_of<2>(n); }
std::vector<Vec<2>> points_of(const YAML::Node& n);

// The same point for the fluid side (Vec<2>) and the rigid side (rigid::Vec2).
inline rigid::Vec2 to_rigid(const Vec<2>& v) { return rigid::Vec2(v[0], v[1]); }
inline Vec<2> from_rigid(const rigid::Vec2& v) { return Vec<2>(v[0], v[1]); }

// Inside a closed polygon, convex or not (crossing number).
bool inside_polygon(const std::vector<Vec<2>>& poly, const Vec<2>& p);

// One straight piece of a wall face, with the unit normal pointing into the fluid.
struct FaceSegment {
  Vec<2> a, b, inward;
  double clearance = 0.0;  // m: the water starts this far in front of it (water_clearance, fluid/walls.hpp)
};

// The segments of a face polyline, the fluid on its left (walking from the first vertex) or on its right.
std::vector<FaceSegment> face_segments(const std::vector<Vec<2>>& face, bool fluid_on_left);

// Signed distance of p from the nearest face segment: positive on the fluid side.
double signed_face_distance(const std::vector<FaceSegment>& faces, const Vec<2>& p);

// Whether water may start at p: in front of the faces (by more than eps) and no nearer to any of them than its
// clearance (less eps).
bool clear_of_faces(const std::vector<FaceSegment>& faces, const Vec<2>& p, double eps);

// The wall face a polygon rests on: of the faces that two or more of its vertices lie within dp / 2 of (|distance|:
// a vertex far behind a face of another wall polyline, a separate cup, does not touch it), the steepest along the
// unit vector `down`; none when it touches no face.
std::optional<FaceSegment> resting_face(const std::vector<FaceSegment>& faces, const std::vector<rigid::Vec2>& outline,
                                        double dp, const Vec<2>& down);

// Bounding box of the face segments (empty list: lo = +inf, hi = -inf).
void face_bounds(const std::vector<FaceSegment>& faces, Vec<2>& lo, Vec<2>& hi);

// Whether the ray from p along direction d (not zero) meets the segment a-b.
bool ray_meets_segment(const Vec<2>& p, const Vec<2>& d, const Vec<2>& a, const Vec<2>& b);

// Area of the part of a convex polygon below a level (Sutherland-Hodgman against one half-plane).
double area_below(const std::vector<rigid::Vec2>& v, double level);

}  // namespace slide::cases
