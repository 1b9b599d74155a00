#pragma once
// A 3-D body's shape (bodies[].shape, dimension: 3: box, sphere, cylinder, prism, a closed mesh from a file): its
// closed surface, its signed distance and its boundary points,
// cut by the scene's symmetry planes. To add a shape: its variant in body_schema_3d (cases/scene_schema.cpp) and its
// case in solid_shape (solid_shape.cpp): a closed outward surface (mass properties, Bullet's hull, the draft), a signed
// distance (where water may stand) and boundary points in layers with normals (the particles that carry it).
#include <yaml-cpp/yaml.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "fluid/mirror_plane.hpp"
#include "fluid/vec.hpp"
#include "fluid/walls.hpp"
#include "rigid/polyhedron.hpp"

namespace slide::cases {

// A tank face that is a plane of symmetry (walls[].symmetry): the scene models the side n . x <= offset of it, n the
// face's outward normal (out of the water). A body it cuts is modelled by its part on that side.
struct SymmetryPlane {
  Vec<3> normal;
  double offset = 0.0;
  std::string key;  // walls[w].symmetry, for messages
  bool keeps(const Vec<3>& p) const { return normal.dot(p) < offset; }
  // Whether p lies on the plane, within `tolerance`.
  bool holds(const Vec<3>& p, double tolerance) const { return std::abs(normal.dot(p) - offset) <= tolerance; }
  // The plane as the solver's ghosts know it (fluid/mirror_plane.hpp).
  MirrorPlane mirror() const;
};

// The symmetry planes of the scene's tanks, from the resolved scene.
std::vector<SymmetryPlane> symmetry_planes(const YAML::Node& resolved);

struct SolidShape {
  rigid::TriangleSurface surface;        // closed, outward, world frame at placement, cut by the symmetry planes
  double whole_volume = 0.0;             // m^3, before the cut: a body's mass key states the whole body's
  rigid::Mat3 axes = rigid::Mat3::Identity();  // the body frame's axes at placement
  std::function<double(const Vec<3>&)> signed_distance;  // m from the whole shape's surface, < 0 inside
  std::vector<BoundaryPointOf<3>> points;  // wall layer and dummies within the kept side (empty when layers is 0)
  bool convex = true;                      // false: a concave mesh (Bullet collides it as its convex pieces)
  // The same shape, cut the same way, moved in by `margin` (m) all round: the hulls Bullet collides with, adding its
  // margin back (rigid::SolidSpec::hull_inset); one for a convex shape, a concave mesh's convex pieces
  // (mesh/convex_decomposition.hpp). Throws SceneError where nothing is left.
  std::function<std::vector<rigid::TriangleSurface>(double margin)> inset;
  bool cut() const;                        // whether a symmetry plane cuts it
};

// The shape of bodies[k] (`shape` its shape node, `path` its key path), its boundary points in `layers` layers at the
// spacing dp; a mesh file is looked up from `scene_dir`. Throws SceneError naming the key for a degenerate shape.
SolidShape solid_shape(const YAML::Node& shape, const std::string& path, const std::vector<SymmetryPlane>& planes,
                       double dp, int layers, const std::filesystem::path& scene_dir);

// A water region's shape (fluid.regions[k] of type shape, `path` its key path): the whole shape, not cut by the planes
// of symmetry (the fill keeps the scene's side of them), without boundary points; a mesh may be concave.
SolidShape region_solid_shape(const YAML::Node& shape, const std::string& path, double dp,
                              const std::filesystem::path& scene_dir);

// The key of a shape that says where it is: `center`, or a mesh's `position` (where the file's origin goes).
const char* placement_key(const YAML::Node& shape);

}  // namespace slide::cases
