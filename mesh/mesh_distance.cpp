// Steps: the signed distance to a closed triangle mesh (mesh/mesh_distance.hpp), with CGAL's AABB tree.
#include "mesh/mesh_distance.hpp"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Side_of_triangle_mesh.h>

#include <cmath>
#include <stdexcept>

#include "mesh/cgal_kernel.hpp"

namespace slide::mesh {

using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, CGAL::AABB_face_graph_triangle_primitive<SurfaceMesh>>>;

// The mesh first: the tree's primitives point into it, so it must not move once the tree is built.
struct MeshDistance::Tree {
  SurfaceMesh mesh;
  AabbTree tree;
  std::unique_ptr<CGAL::Side_of_triangle_mesh<SurfaceMesh, Kernel>> side;
};

MeshDistance::MeshDistance(const rigid::TriangleSurface& s, bool closed) : tree_(std::make_unique<Tree>()) {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  to_soup(s, points, faces);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, tree_->mesh);
  const auto faces_of_mesh = CGAL::faces(tree_->mesh);
  tree_->tree.insert(faces_of_mesh.first, faces_of_mesh.second, tree_->mesh);
  tree_->tree.build();
  tree_->tree.accelerate_distance_queries();
  if (closed) tree_->side = std::make_unique<CGAL::Side_of_triangle_mesh<SurfaceMesh, Kernel>>(tree_->tree);
}

MeshDistance::~MeshDistance() = default;
MeshDistance::MeshDistance(MeshDistance&&) noexcept = default;
MeshDistance& MeshDistance::operator=(MeshDistance&&) noexcept = default;

double MeshDistance::distance(const rigid::Vec3& p) const {
  return std::sqrt(CGAL::to_double(tree_->tree.squared_distance(Point(p[0], p[1], p[2]))));
}

double MeshDistance::signed_distance(const rigid::Vec3& p) const {
  if (!tree_->side) throw std::logic_error("the signed distance to an open surface");
  const Point q(p[0], p[1], p[2]);
  const double d = std::sqrt(CGAL::to_double(tree_->tree.squared_distance(q)));
  const CGAL::Bounded_side side = (*tree_->side)(q);
  return side == CGAL::ON_BOUNDED_SIDE ? -d : side == CGAL::ON_BOUNDARY ? 0.0 : d;
}

rigid::Vec3 MeshDistance::nearest_point(const rigid::Vec3& p) const {
  const Point c = tree_->tree.closest_point(Point(p[0], p[1], p[2]));
  return rigid::Vec3(CGAL::to_double(c.x()), CGAL::to_double(c.y()), CGAL::to_double(c.z()));
}

}  // namespace slide::mesh
