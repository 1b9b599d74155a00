#pragma once
// A terrain's wall and dummy particles: the water's own lattice below its surface, to the kernel's reach, as a tank's
// floor and sides are cut from it (fluid/box_walls.hpp). Each point's depth is its distance to the surface and its
// normal points to the surface's nearest point; its layer is that depth in the lattice's plane spacings (layer 0: a
// wall particle, the rest dummies). The water takes the lattice's points above the surface, so that water and terrain
// are one lattice: still water over a flat terrain is the tank's floor's still water, and over a slope the water meets
// a staircase of the lattice's planes, its particles' depths and normals those of the true surface.
// Why (stop 44): the terrain's layers were laid along its surface as fcc (111) planes (hexagonal, 0.9165 dp apart) with
// the water half a layer clear, as 2-D lays rows along a slope. Still water settled over them was not at rest, even
// over a flat terrain: a 0.3 m x 0.1 m tank, dp 0.01, 0.2 m deep, settled 3 s, over a flat terrain at 0.0238 m reached
// 5.2 % of sqrt(g H) at 0.2 s and its mean speed grew from 0.007 to 0.011 m/s by 0.6 s; the same terrain's particles on
// the water's lattice: 0.099 % at 1 s, mean 0.0002 m/s, as the tank's floor alone (0.11 %). The price: on a slope
// the water's first rows stand on the lattice's steps (the slide work's smooth slope, laid along the face, is 2-D's).
// Earlier still (stop 43), layers from random even samples let water through (48-240 particles in 0.4 s).
#include <vector>

#include "cases/height_grid.hpp"
#include "fluid/lattice.hpp"
#include "fluid/walls.hpp"
#include "mesh/mesh_distance.hpp"

namespace slide::cases {

// Whether p stands above the terrain (or beside it: outside its grid by more than `edge_slack`, m).
bool above_terrain(const HeightGrid& grid, const Vec<3>& p, double edge_slack);

// The lattice's points (moved by `offset`, as the water's) under the grid's surface within `reach` of it (m; the
// kernel's radius), inside its grid.
std::vector<BoundaryPointOf<3>> terrain_layers(const HeightGrid& grid, const mesh::MeshDistance& distance,
                                               LatticeKind kind, double dp, double reach,
                                               const Vec<3>& offset = Vec<3>::Zero());

}  // namespace slide::cases
