// Steps: the shapes of 3-D bodies (cases/solid_shape.hpp): box, sphere, cylinder, prism and mesh, cut by the tanks'
// symmetry planes.
#include "cases/solid_shape.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "cases/scene_geometry.hpp"
#include "cases/schema.hpp"
#include "cases/surface_layers.hpp"
#include "mesh/closed_mesh.hpp"
#include "mesh/convex_decomposition.hpp"
#include "mesh/convex_inset.hpp"
#include "mesh/mesh_distance.hpp"
#include "rigid/polygon.hpp"

namespace slide::cases {
namespace {

// R = Rz(yaw) Ry(pitch) Rx(roll), from shape.angles = [roll, pitch, yaw] in degrees (bodies.csv's convention).
rigid::Mat3 axes_of(const YAML::Node& shape) {
  const Vec<3> a = vec_of<3>(shape["angles"]) * (M_PI / 180.0);
  return rigid::Mat3(Eigen::AngleAxisd(a[2], Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(a[1], Eigen::Vector3d::UnitY()) *
                     Eigen::AngleAxisd(a[0], Eigen::Vector3d::UnitX()));
}

// Boundary points of a box body in its own frame: the points (i + 1/2) h_a along each axis (h_a = its edge over
// round(edge / dp), so the wall layer lies h_a / 2 inside each face) within `layers` grid layers of its surface. A
// point's layer is its least layer index over the axes; behind one face (one axis at that index) its normal is that
// face's outward normal and its depth the distance to it; in the same layer behind two or three faces (along an edge
// or at a corner of the layer) its normal points to that edge or corner and its depth is the distance to it, so that
// its mirror image lies in the fluid's corner, as the tanks' walls do (fluid/box_walls.hpp) and the mitred corners of
// 2-D outlines.
std::vector<BoundaryPointOf<3>> box_points(const Vec<3>& size, const rigid::Mat3& axes, const Vec<3>& centre,
                                           double dp, int layers) {
  std::array<long, 3> n{};
  Vec<3> h;
  for (int a = 0; a < 3; ++a) {
    n[a] = std::max(1L, std::lround(size[a] / dp));
    h[a] = size[a] / double(n[a]);
  }
  std::vector<BoundaryPointOf<3>> out;
  for (long i = 0; i < n[0]; ++i)
    for (long j = 0; j < n[1]; ++j)
      for (long k = 0; k < n[2]; ++k) {
        const Vec<3> local((i + 0.5) * h[0] - 0.5 * size[0], (j + 0.5) * h[1] - 0.5 * size[1],
                           (k + 0.5) * h[2] - 0.5 * size[2]);
        Vec<3> to_face;  // per axis: the distance to the nearer face, signed by its side
        std::array<long, 3> index{};  // per axis: the grid layer, 0 next to the face
        for (int a = 0; a < 3; ++a) {
          const long cell = a == 0 ? i : a == 1 ? j : k;
          to_face[a] = std::copysign(0.5 * size[a] - std::abs(local[a]), local[a]);
          index[a] = std::min(cell, n[a] - 1 - cell);
        }
        const long layer = std::min({index[0], index[1], index[2]});
        if (layer >= layers) continue;
        Vec<3> out_dir = Vec<3>::Zero();
        for (int a = 0; a < 3; ++a)
          if (index[a] == layer) out_dir[a] = to_face[a];
        out.push_back({centre + axes * local, Vec<3>(axes * out_dir.normalized()), out_dir.norm(), int(layer)});
      }
  return out;
}

// Boundary points of a sphere: layer l on the sphere of radius R - (l + 1/2) dp, as N_l = round(4 pi r_l^2 / dp^2)
// points of a Fibonacci lattice (point k at height 1 - (2k + 1) / N, turned by the golden angle pi (3 - sqrt 5) from
// the one before: nearly even spacing, one point per dp^2 of its sphere, as a flat wall has), normal radial, depth
// (l + 1/2) dp.
std::vector<BoundaryPointOf<3>> sphere_points(const Vec<3>& centre, double radius, double dp, int layers) {
  std::vector<BoundaryPointOf<3>> out;
  const double golden = M_PI * (3.0 - std::sqrt(5.0));
  for (int l = 0; l < layers; ++l) {
    const double depth = (l + 0.5) * dp, r = radius - depth;
    if (r <= 0.0) break;
    const long count = std::max(1L, std::lround(4.0 * M_PI * r * r / (dp * dp)));
    for (long k = 0; k < count; ++k) {
      const double z = 1.0 - (2.0 * k + 1.0) / double(count), ring = std::sqrt(std::max(0.0, 1.0 - z * z));
      const Vec<3> normal(ring * std::cos(golden * k), ring * std::sin(golden * k), z);
      out.push_back({centre + r * normal, normal, depth, l});
    }
  }
  return out;
}

// Boundary points of a cylinder about its own z axis: rings of radius R - (i + 1/2) h_r (h_r = R / round(R / dp)),
// each of round(2 pi r / dp) points, at the heights (k + 1/2) h_z - H / 2 (h_z = H / round(H / dp)), every other height
// turned by half a point's spacing. A point's layer is the least of its ring's index and its height's index from the
// nearer cap, as box_points takes it; behind the side its normal is radial, behind a cap axial, and in the same layer
// behind both it points to the rim, with the depth the distance to what it faces.
std::vector<BoundaryPointOf<3>> cylinder_points(const Vec<3>& centre, double radius, double height, const rigid::Mat3& axes,
                                                double dp, int layers) {
  const long rings = std::max(1L, std::lround(radius / dp)), levels = std::max(1L, std::lround(height / dp));
  const double h_r = radius / double(rings), h_z = height / double(levels);
  std::vector<BoundaryPointOf<3>> out;
  for (long k = 0; k < levels; ++k) {
    const double z = (k + 0.5) * h_z - 0.5 * height, to_cap = std::copysign(0.5 * height - std::abs(z), z);
    const long from_cap = std::min(k, levels - 1 - k);
    for (long i = 0; i < rings; ++i) {
      const long layer = std::min(i, from_cap);
      if (layer >= layers) continue;
      const double r = radius - (i + 0.5) * h_r;
      const long count = std::max(1L, std::lround(2.0 * M_PI * r / dp));
      for (long m = 0; m < count; ++m) {
        const double phi = 2.0 * M_PI * (m + 0.5 * double(k % 2)) / double(count);
        const Vec<3> radial(std::cos(phi), std::sin(phi), 0.0);
        Vec<3> out_dir = Vec<3>::Zero();
        if (i == layer) out_dir += (radius - r) * radial;
        if (from_cap == layer) out_dir[2] = to_cap;
        const Vec<3> local(r * radial[0], r * radial[1], z);
        out.push_back({centre + axes * local, Vec<3>(axes * out_dir.normalized()), out_dir.norm(), int(layer)});
      }
    }
  }
  return out;
}

// The exact signed distance to a cylinder (negative inside): from the side d_r = |q_xy| - R and the caps
// d_z = |q_z| - H / 2 in its own frame q, min(max(d_r, d_z), 0) + |(max(d_r, 0), max(d_z, 0))|.
double cylinder_signed_distance(const Vec<3>& p, const Vec<3>& centre, double radius, double height, const rigid::Mat3& axes) {
  const Vec<3> q = axes.transpose() * (p - centre);
  const double d_r = std::hypot(q[0], q[1]) - radius, d_z = std::abs(q[2]) - 0.5 * height;
  return std::min(std::max(d_r, d_z), 0.0) + std::hypot(std::max(d_r, 0.0), std::max(d_z, 0.0));
}

double box_signed_distance(const Vec<3>& p, const Vec<3>& centre, const Vec<3>& size, const rigid::Mat3& axes) {
  const Vec<3> q = (axes.transpose() * (p - centre)).cwiseAbs() - 0.5 * size;
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

// The surface in bodies[k].shape.file, placed: a file point x goes to position + R (scale x). Throws SceneError naming
// the key, the file and its defect.
rigid::TriangleSurface placed_mesh(const YAML::Node& shape, const std::string& path, const std::filesystem::path& scene_dir,
                                   const rigid::Mat3& axes) {
  const std::filesystem::path file = scene_dir / shape["file"].as<std::string>();
  rigid::TriangleSurface m;
  try {
    m = mesh::read_closed_mesh(file);
  } catch (const std::exception& e) {  // a MeshError, or what CGAL's reader throws
    throw SceneError(path + ".shape.file", fmt::format("{}: {}", file.string(), e.what()));
  }
  const double scale = shape["scale"].as<double>();
  const Vec<3> position = vec_of<3>(shape["position"]);
  for (auto& v : m.vertices) v = position + axes * (scale * v);
  return m;
}

}  // namespace

const char* placement_key(const YAML::Node& shape) {
  return shape["type"].as<std::string>() == "mesh" ? "position" : "center";
}

std::vector<SymmetryPlane> symmetry_planes(const YAML::Node& resolved) {
  std::vector<SymmetryPlane> planes;
  const YAML::Node walls = resolved["walls"];
  for (std::size_t w = 0; w < walls.size(); ++w) {
    const YAML::Node faces = walls[w]["symmetry"];
    if (!faces) continue;
    const Vec<3> lo = vec_of<3>(walls[w]["min"]), hi = vec_of<3>(walls[w]["max"]);
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const std::string face = faces[f].as<std::string>();
      const int axis = face[0] == 'x' ? 0 : 1;
      const bool low = face.substr(2) == "min";
      SymmetryPlane s;
      s.normal = Vec<3>::Zero();
      s.normal[axis] = low ? -1.0 : 1.0;
      s.offset = low ? -lo[axis] : hi[axis];
      s.key = fmt::format("walls[{}].symmetry[{}]", w, f);
      planes.push_back(s);
    }
  }
  return planes;
}

MirrorPlane SymmetryPlane::mirror() const {
  MirrorPlane m;
  m.axis = std::abs(normal[0]) > 0.5 ? 0 : std::abs(normal[1]) > 0.5 ? 1 : 2;
  m.keeps_above = normal[m.axis] < 0.0;  // the outward normal of a min face points down the axis
  m.at = offset * normal[m.axis];
  return m;
}

namespace {

// Whether a closed surface is convex; the tolerance allows an STL's float coordinates (6e-8 of its size) on coplanar
// faces.
bool convex(const rigid::TriangleSurface& m) {
  double size = 0.0;
  for (const auto& v : m.vertices) size = std::max(size, (v - m.vertices[0]).norm());
  return rigid::is_convex(m, 1e-6 * size);
}

// The convex pieces of a concave body's surface, each moved in by the margin: Bullet collides a concave moving body as
// their compound. HACD is allowed the margin as concavity; a piece that stands out of the surface by more than half a
// spacing would make contacts where the body is not, and is refused.
std::vector<rigid::TriangleSurface> concave_inset(const rigid::TriangleSurface& whole, const std::string& path,
                                                  double dp, double margin) {
  mesh::ConvexPieces d;
  try {
    d = mesh::convex_decomposition(whole, margin);
  } catch (const std::invalid_argument& e) {
    throw SceneError(path + ".shape.file", e.what());
  }
  if (d.overreach > 0.5 * dp)
    throw SceneError(path + ".shape.file",
                     fmt::format("its convex decomposition ({} pieces) stands {:.3g} m out of its surface, more than "
                                 "half a spacing", d.pieces.size(), d.overreach));
  std::vector<rigid::TriangleSurface> out;
  for (const auto& piece : d.pieces) {
    try {
      out.push_back(mesh::convex_inset(piece, margin));
    } catch (const std::invalid_argument&) {
      // A piece thinner than twice the margin: left out, its neighbours hold the surface there.
    }
  }
  if (out.empty()) throw SceneError(path + ".shape", "too thin for the collision margin");
  return out;
}

// A shape known by its triangles alone (a mesh, a prism): the signed distance from CGAL's tree on them, the boundary
// points sampled evenly on them in layers, Bullet's hull by the convex inset (a concave mesh's: its pieces').
void from_its_surface(SolidShape& s, const std::string& path, double dp, int layers) {
  const auto distance = std::make_shared<const mesh::MeshDistance>(s.surface);
  s.signed_distance = [distance](const Vec<3>& p) { return distance->signed_distance(p); };
  const auto inside = [distance](const Vec<3>& p) { return distance->signed_distance(p) < 0.0; };
  s.points = surface_layers(s.surface, *distance, inside, dp, layers);
  s.convex = convex(s.surface);
  s.inset = [whole = s.surface, path, dp, convex = s.convex](double margin) {
    if (!convex) return concave_inset(whole, path, dp, margin);
    try {
      return std::vector<rigid::TriangleSurface>{mesh::convex_inset(whole, margin)};
    } catch (const std::invalid_argument&) {
      throw SceneError(path + ".shape", "too thin for the collision margin");
    }
  };
}

// bodies[k].shape of type prism: its outline made counter-clockwise, checked convex, swept over its length.
rigid::TriangleSurface prism_of(const YAML::Node& shape, const std::string& path, const Vec<3>& centre,
                                const rigid::Mat3& axes) {
  std::vector<rigid::Vec2> outline;
  for (const auto& p : points_of(shape["outline"])) outline.emplace_back(p[0], p[1]);
  outline = rigid::counter_clockwise(outline);
  if (!rigid::is_convex_ccw(outline))
    throw SceneError(path + ".shape.outline", "must be a convex polygon (a concave body: give it as a mesh)");
  std::vector<std::array<double, 2>> vertices;
  for (const auto& v : outline) vertices.push_back({v[0], v[1]});
  return rigid::prism_surface(vertices, shape["length"].as<double>(), centre, axes);
}

// The whole shape, before any symmetry cut; a mesh may be concave (s.convex says which).
SolidShape whole_shape(const YAML::Node& shape, const std::string& path, double dp, int layers,
                       const std::filesystem::path& scene_dir) {
  SolidShape s;
  const std::string type = shape["type"].as<std::string>();
  const Vec<3> centre = type == "mesh" ? Vec<3>::Zero() : vec_of<3>(shape["center"]);
  if (type == "mesh") {
    s.axes = axes_of(shape);
    s.surface = placed_mesh(shape, path, scene_dir, s.axes);
    from_its_surface(s, path, dp, layers);
  } else if (type == "prism") {
    s.axes = axes_of(shape);
    s.surface = prism_of(shape, path, centre, s.axes);
    from_its_surface(s, path, dp, layers);
  } else if (type == "sphere") {
    const double radius = shape["radius"].as<double>();
    if (!(radius > 0.0)) throw SceneError(path + ".shape.radius", "must be positive");
    s.surface = rigid::sphere_surface(centre, radius);
    s.signed_distance = [centre, radius](const Vec<3>& p) { return (p - centre).norm() - radius; };
    s.points = sphere_points(centre, radius, dp, layers);
    s.inset = [centre, radius, path](double margin) {
      if (!(radius > 1.5 * margin)) throw SceneError(path + ".shape.radius", "too small for the collision margin");
      return std::vector{rigid::sphere_surface(centre, radius - margin)};
    };
  } else if (type == "cylinder") {
    const double radius = shape["radius"].as<double>(), height = shape["height"].as<double>();
    if (!(radius > 0.0)) throw SceneError(path + ".shape.radius", "must be positive");
    if (!(height > 0.0)) throw SceneError(path + ".shape.height", "must be positive");
    s.axes = axes_of(shape);
    s.surface = rigid::cylinder_surface(centre, radius, height, s.axes);
    s.signed_distance = [centre, radius, height, axes = s.axes](const Vec<3>& p) {
      return cylinder_signed_distance(p, centre, radius, height, axes);
    };
    s.points = cylinder_points(centre, radius, height, s.axes, dp, layers);
    s.inset = [centre, radius, height, axes = s.axes, path](double margin) {
      if (!(radius > 1.5 * margin)) throw SceneError(path + ".shape.radius", "too small for the collision margin");
      if (!(height > 3.0 * margin)) throw SceneError(path + ".shape.height", "too small for the collision margin");
      return std::vector{rigid::cylinder_surface(centre, radius - margin, height - 2.0 * margin, axes)};
    };
  } else {
    const Vec<3> size = vec_of<3>(shape["size"]);
    if (!(size.minCoeff() > 0.0)) throw SceneError(path + ".shape.size", "every edge length must be positive");
    s.axes = axes_of(shape);
    s.surface = rigid::box_surface(centre, size, s.axes);
    s.signed_distance = [centre, size, axes = s.axes](const Vec<3>& p) {
      return box_signed_distance(p, centre, size, axes);
    };
    s.points = box_points(size, s.axes, centre, dp, layers);
    s.inset = [centre, size, axes = s.axes, path](double margin) {
      if (!(size.minCoeff() > 3.0 * margin)) throw SceneError(path + ".shape.size", "too small for the collision margin");
      return std::vector{rigid::box_surface(centre, size - Vec<3>::Constant(2.0 * margin), axes)};
    };
  }
  s.whole_volume = rigid::mass_properties(s.surface).volume;
  return s;
}

}  // namespace

bool SolidShape::cut() const { return rigid::mass_properties(surface).volume < whole_volume * (1.0 - 1e-12); }

SolidShape region_solid_shape(const YAML::Node& shape, const std::string& path, double dp,
                              const std::filesystem::path& scene_dir) {
  return whole_shape(shape, path, dp, 0, scene_dir);
}

SolidShape solid_shape(const YAML::Node& shape, const std::string& path, const std::vector<SymmetryPlane>& planes,
                       double dp, int layers, const std::filesystem::path& scene_dir) {
  SolidShape s = whole_shape(shape, path, dp, layers, scene_dir);
  for (const auto& plane : planes) {
    if (!s.convex)  // the cut below is written for convex surfaces
      for (const auto& v : s.surface.vertices)
        if (!plane.keeps(Vec<3>(v)) && !plane.holds(Vec<3>(v), 1e-9 * dp))
          throw SceneError(path + ".shape", fmt::format("the symmetry plane {} cuts this concave shape: only a convex "
                                                        "one may be cut yet", plane.key));
    try {
      s.surface = rigid::clip_convex(s.surface, plane.normal, plane.offset);
    } catch (const std::invalid_argument&) {
      throw SceneError(path + ".shape", fmt::format("lies wholly beyond the symmetry plane {}", plane.key));
    }
    // A point on the plane (a ring's first point, a box's middle row) is its own mirror image: kept, put on it exactly.
    const double on = 1e-9 * dp;
    std::erase_if(s.points, [&](const BoundaryPointOf<3>& p) { return !plane.keeps(p.position) && !plane.holds(p.position, on); });
    for (auto& p : s.points)
      if (plane.holds(p.position, on)) p.position += (plane.offset - plane.normal.dot(p.position)) * plane.normal;
  }
  if (!s.convex) return s;  // not cut (above)
  s.inset = [whole = s.inset, planes, path](double margin) {
    std::vector<rigid::TriangleSurface> hulls = whole(margin);
    for (const auto& plane : planes) {
      try {
        hulls[0] = rigid::clip_convex(hulls[0], plane.normal, plane.offset - margin);
      } catch (const std::invalid_argument&) {
        throw SceneError(path + ".shape", fmt::format("too thin beside the symmetry plane {} for the collision margin",
                                                      plane.key));
      }
    }
    return hulls;
  };
  return s;
}

}  // namespace slide::cases
