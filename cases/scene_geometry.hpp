#pragma once
// The plane geometry a scene is built with: points read from the scene, the wall faces and the signed distance from
// them, point-in-polygon for regions, and the part of a body's outline below a level. Convex-outline operations
// (area, centroid, contains, distance to the outline) are rigid/polygon.hpp's.
#include <yaml-cpp/yaml.h>

#include <vector>

#include "fluid/vec.hpp"
#include "rigid/polygon.hpp"

namespace slide::cases {

// A point [x, y] and a list of points, as the schema has checked them.
Vec<2> vec2(const YAML::Node& n);
std::vector<Vec<2>> points_of(const YAML::Node& n);

// The same point for the fluid side (Vec<2>) and the rigid side (rigid::Vec2).
inline rigid::Vec2 to_rigid(const Vec<2>& v) { return rigid::Vec2(v[0], v[1]); }
inline Vec<2> from_rigid(const rigid::Vec2& v) { return Vec<2>(v[0], v[1]); }

// Inside a closed polygon, convex or not (crossing number).
bool inside_polygon(const std::vector<Vec<2>>& poly, const Vec<2>& p);

// One straight piece of a wall face, with the unit normal pointing into the fluid.
struct FaceSegment {
  Vec<2> a, b, inward;
};

// The segments of a face polyline, the fluid on its left (walking from the first vertex) or on its right.
std::vector<FaceSegment> face_segments(const std::vector<Vec<2>>& face, bool fluid_on_left);

// Signed distance of p from the nearest face segment: positive on the fluid side.
double signed_face_distance(const std::vector<FaceSegment>& faces, const Vec<2>& p);

// Bounding box of the face segments (empty list: lo = +inf, hi = -inf).
void face_bounds(const std::vector<FaceSegment>& faces, Vec<2>& lo, Vec<2>& hi);

// Whether the ray from p along direction d (not zero) meets the segment a-b.
bool ray_meets_segment(const Vec<2>& p, const Vec<2>& d, const Vec<2>& a, const Vec<2>& b);

// Area of the part of a convex polygon below a level (Sutherland-Hodgman against one half-plane).
double area_below(const std::vector<rigid::Vec2>& v, double level);

}  // namespace slide::cases
