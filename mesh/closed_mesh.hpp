#pragma once
// Closed triangle meshes read from files (a body's or a wall's shape from CAD or a survey): STL, binary or ASCII, and
// OBJ, read and checked with CGAL (Debian's libcgal-dev, header-only: its readers, its polygon-soup to mesh
// conversion and its self-intersection test on exact predicates, rather than code of ours for each). Only this
// folder's .cpp files include CGAL, so that its long compile stays in one library; the rest of slide sees
// rigid::TriangleSurface.
#include <filesystem>
#include <stdexcept>
#include <string>

#include "rigid/polyhedron.hpp"

namespace slide::mesh {

// What is wrong with a mesh, in words a user can act on (the caller adds the file and the key).
struct MeshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The closed surface in `file` (.stl binary or ASCII, .obj; by the extension), its corners merged where they coincide
// exactly (an STL file repeats them per facet). Throws MeshError where the file cannot be read or the surface is not
// a closed, consistently and outward oriented, non-self-intersecting triangle mesh with positive volume
// (check_closed_mesh).
rigid::TriangleSurface read_closed_mesh(const std::filesystem::path& file);

// Throws MeshError naming the first defect found: not triangles, an edge of a single face (a hole) or of more than
// two (non-manifold), faces turned against their neighbours, faces pointing inward, no volume, faces that cut one
// another, separate closed surfaces.
void check_closed_mesh(const rigid::TriangleSurface& surface);

}  // namespace slide::mesh
