// Steps: a convex surface moved in by a margin (mesh/convex_inset.hpp).
#include "mesh/convex_inset.hpp"

#include <CGAL/Convex_hull_3/dual/halfspace_intersection_3.h>

#include <vector>

#include "mesh/cgal_kernel.hpp"

namespace slide::mesh {

rigid::TriangleSurface convex_inset(const rigid::TriangleSurface& s, double margin) {
  const rigid::Vec3 c = rigid::mass_properties(s).centroid;
  std::vector<Kernel::Plane_3> planes;
  for (const auto& t : s.triangles) {
    const rigid::Vec3 n = rigid::outward_normal(s, t);
    const double offset = n.dot(s.vertices[t[0]]) - margin;  // n . x <= offset inside
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
  return out;
}

}  // namespace slide::mesh
