#pragma once
// The distance to a triangle surface and its nearest point (CGAL's AABB tree of the triangles), and for a closed one
// the signed distance, negative inside (CGAL's ray-parity test on exact predicates, Side_of_triangle_mesh, for the
// side). Built once; queries are const and may run on several threads.
#include <memory>

#include "rigid/polyhedron.hpp"

namespace slide::mesh {

class MeshDistance {
 public:
  // With `closed`, `surface` must be closed and outward (check_closed_mesh); an open one (a terrain) has no inside.
  explicit MeshDistance(const rigid::TriangleSurface& surface, bool closed = true);
  ~MeshDistance();
  MeshDistance(MeshDistance&&) noexcept;
  MeshDistance& operator=(MeshDistance&&) noexcept;

  // m from the surface.
  double distance(const rigid::Vec3& p) const;
  // m from the surface, < 0 inside, 0 on it (closed surfaces only: std::logic_error otherwise).
  double signed_distance(const rigid::Vec3& p) const;
  // The point of the surface nearest to p.
  rigid::Vec3 nearest_point(const rigid::Vec3& p) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace slide::mesh
