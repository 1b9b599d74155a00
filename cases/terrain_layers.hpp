#pragma once
// A terrain's wall and dummy particles as a lattice laid along it, as 2-D lays rows along a slope (fluid/walls.hpp,
// lattice_boundary): on the fcc lattice, layers of the fcc's close-packed (111) planes, hexagonal with the fluid's
// nearest spacing a = 1.1225 dp, stacked A, B, C at (k + 1/2) h below the surface (h = a sqrt(2/3) = 0.9165 dp); on
// the square lattice, square layers of spacing dp at (k + 1/2) dp. One point per dp^3, as the water's lattice.
// Each layer is the 2-D lattice in (x, y), every point lifted onto the surface and moved down its normal by the
// layer's depth; its spacing in (x, y) is a sqrt(cos), cos the ratio of the surface's projected area to its area, so
// that a plane of any slope holds one point per a^2 sqrt(3)/2 of its own area (along the slope the points stand 1/cos
// further apart than across it: 3.5 % on a 15 degree slope), rounded to whole numbers of columns and rows across the
// grid, the first and last half a spacing in from its edges. Why not points spread at random (mesh/even_surface_
// samples.hpp): their gaps let water through (stop 43: still water over a random-sampled 15 degree terrain started from
// the lattice reached 2.8 m/s and 48 particles passed under the surface in 0.4 s; the tank's floor, 0.13 m/s and none).
// A point is kept where its distance to the surface is within a quarter spacing of its layer's depth (behind a kink
// the two sides' points meet near the bisector), its normal towards the surface's nearest point, its depth the
// distance to it.
#include <vector>

#include "cases/height_grid.hpp"
#include "fluid/lattice.hpp"
#include "fluid/walls.hpp"
#include "mesh/mesh_distance.hpp"

namespace slide::cases {

std::vector<BoundaryPointOf<3>> terrain_layers(const HeightGrid& grid, const rigid::TriangleSurface& surface,
                                               const mesh::MeshDistance& distance, LatticeKind kind, double dp,
                                               int layers);

// How far the water's first lattice points stay from the surface: half the layers' spacing, so that the wall layer,
// as far below, is one layer spacing from the water.
double terrain_clearance(LatticeKind kind, double dp);

}  // namespace slide::cases
