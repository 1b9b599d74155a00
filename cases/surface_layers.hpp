#pragma once
// Boundary particles along a mesh body's surface, which is not on the lattice (a terrain's particles are the lattice's:
// cases/terrain_layers.hpp): layer l is the surface spread evenly with one point per dp^2
// (mesh/even_surface_samples.hpp, each layer its own set, so that the gaps of one do not line up with the next's),
// moved by (l + 1/2) dp along their face's normal into the solid. Near an edge a point so moved may come nearer
// another face: it is kept while its depth (its distance to the surface, on the solid's side) is within dp/4 of its
// layer's (at a convex edge the two faces' points so meet near the bisector; a thin part keeps the layers it has room
// for). Its normal points to the surface's nearest point and its depth is its distance to it, as at a box's edges.
#include <functional>
#include <vector>

#include "fluid/vec.hpp"
#include "fluid/walls.hpp"
#include "mesh/mesh_distance.hpp"
#include "rigid/polyhedron.hpp"

namespace slide::cases {

// The triangles face out of the solid (a body's outward, a terrain's up into the water); `solid_side(p)`: whether p
// lies in the solid (inside the body, below the terrain).
std::vector<BoundaryPointOf<3>> surface_layers(const rigid::TriangleSurface& surface, const mesh::MeshDistance& distance,
                                               const std::function<bool(const Vec<3>&)>& solid_side, double dp,
                                               int layers);

}  // namespace slide::cases
