#pragma once
// A closed surface as convex pieces whose union stands for it: what Bullet needs to collide a concave moving body (a
// btCompoundShape of convex hulls). HACD (Mamou & Ghorbel, "A simple and efficient approach for 3D mesh approximate
// convex decomposition", ICIP 2009; Debian's libbullet-extras-dev) merges the surface's triangles into clusters while
// each cluster's concavity (how far its surface lies inside its convex hull) stays small; each piece is the convex
// hull of a cluster (CGAL's convex_hull_3, outward). A convex surface is one piece.
#include <vector>

#include "rigid/polyhedron.hpp"

namespace slide::mesh {

struct ConvexPieces {
  std::vector<rigid::TriangleSurface> pieces;  // convex, closed, outward
  double overreach = 0.0;  // m: the furthest a piece's surface (its corners and face centres) stands outside the whole
};

// `surface` closed and outward; `concavity` (m) the concavity HACD allows a cluster. Throws std::invalid_argument where
// HACD fails.
ConvexPieces convex_decomposition(const rigid::TriangleSurface& surface, double concavity);

}  // namespace slide::mesh
