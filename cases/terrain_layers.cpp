// Steps: a terrain's boundary particles, the water's own lattice below its surface (cases/terrain_layers.hpp).
#include "cases/terrain_layers.hpp"

#include <algorithm>
#include <cmath>

namespace slide::cases {
namespace {

// The upward unit normal of the grid's triangle under (x, y) (inside the grid).
Vec<3> terrain_normal(const HeightGrid& g, double x, double y) {
  const std::size_t i = std::min<std::size_t>(std::upper_bound(g.x.begin(), g.x.end(), x) - g.x.begin(), g.x.size() - 1) - 1;
  const std::size_t j = std::min<std::size_t>(std::upper_bound(g.y.begin(), g.y.end(), y) - g.y.begin(), g.y.size() - 1) - 1;
  const double dx = g.x[i + 1] - g.x[i], dy = g.y[j + 1] - g.y[j];
  const double u = (x - g.x[i]) / dx, w = (y - g.y[j]) / dy;
  const double z00 = g.at(i, j), z10 = g.at(i + 1, j), z11 = g.at(i + 1, j + 1), z01 = g.at(i, j + 1);
  const double slope_x = u >= w ? (z10 - z00) / dx : (z11 - z01) / dx;
  const double slope_y = u >= w ? (z11 - z10) / dy : (z01 - z00) / dy;
  return Vec<3>(-slope_x, -slope_y, 1.0).normalized();
}

}  // namespace

bool above_terrain(const HeightGrid& grid, const Vec<3>& p, double edge_slack) {
  const double h = terrain_height(grid, p[0], p[1], edge_slack);
  return std::isnan(h) || p[2] > h;
}

std::vector<BoundaryPointOf<3>> terrain_layers(const HeightGrid& g, const mesh::MeshDistance& distance,
                                               LatticeKind kind, double dp, double reach, const Vec<3>& offset) {
  const auto [lowest, highest] = std::minmax_element(g.z.begin(), g.z.end());
  const Vec<3> lo(g.x.front(), g.y.front(), *lowest - reach), hi(g.x.back(), g.y.back(), *highest);
  const double spacing = row_spacing(kind, dp), eps = 1e-9 * dp;
  std::vector<BoundaryPointOf<3>> out;
  const auto visit = [&](const Vec<3>& p) {
    if (above_terrain(g, p, eps) || std::isnan(terrain_height(g, p[0], p[1], eps))) return;
    const Vec<3> nearest = distance.nearest_point(p);
    const double depth = (nearest - p).norm();
    if (depth > reach + eps) return;
    // A point on the surface itself takes the normal of the triangle under it.
    const Vec<3> normal = depth > eps ? Vec<3>((nearest - p) / depth)
                                      : terrain_normal(g, std::clamp(p[0], g.x.front(), g.x.back()),
                                                       std::clamp(p[1], g.y.front(), g.y.back()));
    out.push_back({p, normal, depth, static_cast<int>(std::floor(depth / spacing + 1e-9))});
  };
  for_each_lattice_point(kind, dp, lo, hi, visit, offset);
  return out;
}

}  // namespace slide::cases
