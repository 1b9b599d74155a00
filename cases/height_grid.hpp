#pragma once
// A terrain as a grid of elevations (walls[].type: terrain, 3-D), the way a user brings a bathymetry or a DEM: a CSV
// grid or an ESRI ASCII grid. The surface is the grid's cells, each split into two triangles along its diagonal from
// (x_i, y_j) to (x_i+1, y_j+1), so that its height is exact on planar pieces (a slope, a flat floor) whatever the
// grid's spacing.
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "rigid/polyhedron.hpp"

namespace slide::cases {

struct HeightGrid {
  std::vector<double> x, y;  // m, strictly increasing
  std::vector<double> z;     // m, z[j * x.size() + i] at (x[i], y[j])
  double at(std::size_t i, std::size_t j) const { return z[j * x.size() + i]; }
};

// Reads `file` by its extension:
// * .csv: a header `y\x,x_0,x_1,...` (its first cell any label), then one row per y: `y_j,z_0j,z_1j,...`;
// * .asc (ESRI ASCII grid): ncols, nrows, xllcorner or xllcenter, yllcorner or yllcenter, cellsize, an optional
//   NODATA_value, then nrows rows of ncols elevations, the northernmost (largest y) first; corner keys put the values
//   at the cells' centres.
// Throws std::runtime_error saying what is wrong and where (a row, a cell, a no-data value).
HeightGrid read_height_grid(const std::filesystem::path& file);

// The grid's surface, its triangles facing up (out of the ground).
rigid::TriangleSurface terrain_surface(const HeightGrid& g);

// The surface's height at (x, y) on its triangles; NaN outside the grid. A point outside it by at most `edge_slack` (m)
// takes the edge's height: a lattice point on a symmetry plane along the grid's edge, its coordinates rounded, lies
// on the edge (without the slack a slide there, 1e-14 m beside a grid whose edge the scene rounded, had no terrain
// under it and fell through while it settled).
double terrain_height(const HeightGrid& g, double x, double y, double edge_slack = 0.0);

}  // namespace slide::cases
