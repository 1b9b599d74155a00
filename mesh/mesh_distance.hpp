#pragma once
// The signed distance to a closed triangle mesh (negative inside) and its nearest point: CGAL's AABB tree of the
// triangles for the distance, and its ray-parity test on exact predicates (Side_of_triangle_mesh) for the side. Both
// are built once; queries are const and may run on several threads.
#include <memory>

#include "rigid/polyhedron.hpp"

namespace slide::mesh {

class MeshDistance {
 public:
  // `surface` must be closed and outward (check_closed_mesh).
  explicit MeshDistance(const rigid::TriangleSurface& surface);
  ~MeshDistance();
  MeshDistance(MeshDistance&&) noexcept;
  MeshDistance& operator=(MeshDistance&&) noexcept;

  // m from the surface, < 0 inside, 0 on it.
  double signed_distance(const rigid::Vec3& p) const;
  // The point of the surface nearest to p.
  rigid::Vec3 nearest_point(const rigid::Vec3& p) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
};

}  // namespace slide::mesh
