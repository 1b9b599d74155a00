#pragma once
// The CGAL types mesh/*.cpp share (private to this folder): exact predicates, double constructions, a halfedge mesh.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include "rigid/polyhedron.hpp"

namespace slide::mesh {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;

// The surface as CGAL's points and faces (a polygon soup).
inline void to_soup(const rigid::TriangleSurface& s, std::vector<Point>& points, std::vector<std::vector<std::size_t>>& faces) {
  for (const auto& v : s.vertices) points.emplace_back(v[0], v[1], v[2]);
  for (const auto& t : s.triangles) faces.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
}

}  // namespace slide::mesh
