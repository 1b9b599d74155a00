#pragma once
// A convex surface moved in by a margin, exactly: the intersection of its faces' half-spaces each moved in by the
// margin (CGAL's halfspace_intersection_3, the dual of a convex hull). Faces that the margin closes (a thin rim) drop
// out, where moving the corners (rigid::inset_convex) folds them over. Bullet adds its collision margin around a
// body's hull, so this hull collides at the body's surface.
#include <stdexcept>

#include "rigid/polyhedron.hpp"

namespace slide::mesh {

// `surface` closed, outward and convex. Throws std::invalid_argument where the centroid does not lie more than the
// margin inside every face (the body is too thin for it).
rigid::TriangleSurface convex_inset(const rigid::TriangleSurface& surface, double margin);

}  // namespace slide::mesh
