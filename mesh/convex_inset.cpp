// Steps: a convex surface moved in by a margin (mesh/convex_inset.hpp).
#include "mesh/convex_inset.hpp"

#include <CGAL/Convex_hull_3/dual/halfspace_intersection_3.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>

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
  CGAL::Polygon_mesh_processing::triangulate_faces(m);
  rigid::TriangleSurface out;
  for (const auto v : m.vertices()) {
    const Point& p = m.point(v);
    out.vertices.push_back(rigid::Vec3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
  }
  for (const auto f : m.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (const auto v : CGAL::vertices_around_face(m.halfedge(f), m)) t[std::size_t(k++)] = int(v.idx());
    out.triangles.push_back(t);
  }
  if (rigid::mass_properties(out).volume <= 0.0) throw std::invalid_argument("a body too thin for the collision margin");
  return out;
}

}  // namespace slide::mesh
