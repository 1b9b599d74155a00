// Steps: a terrain's boundary particles as a lattice laid along it (cases/terrain_layers.hpp).
#include "cases/terrain_layers.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

namespace slide::cases {
namespace {

// The layers' spacing: (111) planes of the fcc lattice, or the square lattice's dp.
double layer_spacing(LatticeKind kind, double dp) {
  return kind == LatticeKind::fcc ? nearest_spacing(kind, dp) * std::sqrt(2.0 / 3.0) : dp;
}

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

// A lattice coordinate inside [lo, hi], or on an edge that it misses by rounding (a millionth of a spacing): the
// rows that end on an edge lost their last point where (columns) a / columns came out an ulp beyond it, and water ran
// down under a flat terrain through the gap (stop 44).
std::optional<double> onto_edge(double v, double lo, double hi, double spacing) {
  const double tolerance = 1e-6 * spacing;
  if (v < lo - tolerance || v > hi + tolerance) return std::nullopt;
  return std::clamp(v, lo, hi);
}

}  // namespace

double terrain_clearance(LatticeKind kind, double dp) { return 0.5 * layer_spacing(kind, dp); }

std::vector<BoundaryPointOf<3>> terrain_layers(const HeightGrid& g, const rigid::TriangleSurface& s,
                                               const mesh::MeshDistance& distance, LatticeKind kind, double dp,
                                               int layers) {
  double area = 0.0, projected = 0.0;
  for (const auto& t : s.triangles) {
    const rigid::Vec3 n = (s.vertices[t[1]] - s.vertices[t[0]]).cross(s.vertices[t[2]] - s.vertices[t[0]]);
    area += 0.5 * n.norm();
    projected += 0.5 * std::abs(n[2]);
  }
  const bool hexagonal = kind == LatticeKind::fcc;
  const double h = layer_spacing(kind, dp), spacing = nearest_spacing(kind, dp) * std::sqrt(projected / area);
  // Whole numbers of columns and rows across the grid, so that the first and last lie half a spacing in from its edges
  // (where a tank's side takes over, its own wall layer half a spacing beyond): no strip along a side without
  // particles, through which water would run down under the terrain.
  const double width = g.x.back() - g.x.front(), length = g.y.back() - g.y.front();
  const long columns = std::max(1L, std::lround(width / spacing));
  const long rows = std::max(1L, std::lround(length / (hexagonal ? 0.5 * std::sqrt(3.0) * spacing : spacing)));
  const double a = width / double(columns), row = length / double(rows);
  std::vector<BoundaryPointOf<3>> out;
  for (int k = 0; k < layers; ++k) {
    const double depth = (k + 0.5) * h;
    // A, B, C: each layer's lattice shifted to the centres of the one above's triangles.
    // (C's shift along x is a whole spacing less, so that its odd rows start on the grid's edge like A's.)
    const double shift_x = hexagonal ? 0.5 * a * double(k % 3 == 1) : 0.0, shift_y = hexagonal ? row / 3.0 * double(k % 3) : 0.0;
    for (long j = -1; j <= rows; ++j)
      for (long i = -1; i <= columns; ++i) {
        const auto x = onto_edge(g.x.front() + (double(i) + 0.5 + (hexagonal && (j % 2 != 0) ? 0.5 : 0.0)) * a + shift_x,
                                 g.x.front(), g.x.back(), a);
        const auto y = onto_edge(g.y.front() + (double(j) + 0.5) * row + shift_y, g.y.front(), g.y.back(), row);
        if (!x || !y) continue;
        const Vec<3> on(*x, *y, terrain_height(g, *x, *y));
        Vec<3> p = on - depth * terrain_normal(g, *x, *y);
        // A point of an edge's row moved down a slope's normal leaves the grid by up to the depth times the slope: it
        // is moved back onto the edge (its depth changes by that times the slope's sine), where dropping it left a
        // row's spacing free beside the tank's side (stop 44).
        p[0] = std::clamp(p[0], g.x.front(), g.x.back());
        p[1] = std::clamp(p[1], g.y.front(), g.y.back());
        if (!(p[2] < terrain_height(g, p[0], p[1]))) continue;
        const double d = distance.distance(p);
        if (d < depth - 0.25 * h || d > depth + 0.25 * h) continue;
        out.push_back({p, Vec<3>((distance.nearest_point(p) - p).normalized()), d, k});
      }
  }
  return out;
}

}  // namespace slide::cases
