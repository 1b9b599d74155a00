// Steps: a convex surface moved in by a margin (mesh/convex_inset.hpp).
#include "mesh/convex_inset.hpp"

#include <CGAL/Convex_hull_3/dual/halfspace_intersection_3.h>

#include <algorithm>
#include <utility>
#include <vector>

#include "mesh/cgal_kernel.hpp"

namespace slide::mesh {

rigid::TriangleSurface convex_inset(const rigid::TriangleSurface& s, double margin) {
  const rigid::Vec3 c = rigid::mass_properties(s).centroid;
  // One plane per face direction: the triangles of a flat face give planes equal to rounding, and three nearly equal
  // planes make a corner of the intersection ill-conditioned. Sorted by normal, neighbours within 1e-12 are one (the
  // innermost kept).
  std::vector<std::pair<rigid::Vec3, double>> faces;  // outward normal, offset: n . x <= offset inside
  for (const auto& t : s.triangles) {
    const rigid::Vec3 n = rigid::outward_normal(s, t);
    faces.emplace_back(n, n.dot(s.vertices[t[0]]) - margin);
  }
  std::sort(faces.begin(), faces.end(), [](const auto& a, const auto& b) {
    return std::lexicographical_compare(a.first.data(), a.first.data() + 3, b.first.data(), b.first.data() + 3);
  });
  std::vector<std::pair<rigid::Vec3, double>> distinct;
  for (const auto& f : faces) {
    if (!distinct.empty() && (distinct.back().first - f.first).norm() < 1e-12)
      distinct.back().second = std::min(distinct.back().second, f.second);
    else
      distinct.push_back(f);
  }
  std::vector<Kernel::Plane_3> planes;
  for (const auto& [n, offset] : distinct) {
    if (!(n.dot(c) < offset)) throw std::invalid_argument("a body too thin for the collision margin");
    planes.emplace_back(n[0], n[1], n[2], -offset);  // negative side: n . x - offset < 0
  }
  SurfaceMesh m;
  CGAL::halfspace_intersection_3(planes.begin(), planes.end(), m, Point(c[0], c[1], c[2]));
  rigid::TriangleSurface out;
  for (const auto v : m.vertices()) {
    const Point& p = m.point(v);
    out.vertices.push_back(rigid::Vec3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
  }
  // Each face is a convex polygon: a fan from its first corner. (CGAL's triangulate_faces, a constrained
  // triangulation, did not return on the Enet & Grilli slide's inset at dp 0.04, whose faces near the rim are slivers.)
  for (const auto f : m.faces()) {
    std::vector<int> corners;
    for (const auto v : CGAL::vertices_around_face(m.halfedge(f), m)) corners.push_back(int(v.idx()));
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) out.triangles.push_back({corners[0], corners[k], corners[k + 1]});
  }
  if (rigid::mass_properties(out).volume <= 0.0) throw std::invalid_argument("a body too thin for the collision margin");
  // Every corner inside every moved face (within a billionth of the body's size): a corner CGAL could not place well
  // would show here.
  double size = 0.0;
  for (const auto& v : s.vertices) size = std::max(size, (v - s.vertices[0]).norm());
  for (const auto& v : out.vertices)
    for (const auto& [n, offset] : distinct)
      if (n.dot(v) > offset + 1e-9 * size) throw std::invalid_argument("the collision hull could not be built");
  return out;
}

}  // namespace slide::mesh
