#pragma once
// Where a deformable slide is and what shape it has (slide_front.csv, slide_outline.csv): its front, its largest
// thickness and its upper surface, from the particles of its phase.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <type_traits>
#include <vector>

#include "coupling/simulation.hpp"

namespace slide {

// D: 2 (columns along x, thickness along y) or 3 (columns on an (x, y) grid, thickness along z).
template <int D>
struct SlideFrontOf {
  Vec<D> front = Vec<D>::Constant(std::numeric_limits<double>::quiet_NaN());  // m, the particle furthest along
  double thickness_max = 0.0;  // m, largest vertical thickness of a column
  std::size_t particles = 0;
};
using SlideFront = SlideFrontOf<2>;

// Columns of width `column_width` across the horizontal axes (in 2-D column k holds x in [k w, (k + 1) w); in 3-D
// column (k, l) also y in [l w, (l + 1) w)), each with the lowest and highest particle centre of the slide's phase in
// it, along the vertical axis (the last).
template <int D>
struct SlideColumnsOf {
  using Column = std::array<long, D - 1>;
  std::map<Column, std::pair<double, double>> bottom_top;  // column -> (lowest, highest)
  double width = 0.0;
};

template <int D>
SlideColumnsOf<D> slide_columns(const Particles<D>& P, std::uint8_t phase, double column_width) {
  SlideColumnsOf<D> c;
  c.width = column_width;
  for (std::size_t i = 0; i < P.real_count(); ++i) {  // real particles: not their images
    if (P.kind[i] != Kind::fluid || P.phase[i] != phase) continue;
    typename SlideColumnsOf<D>::Column k;
    for (int a = 0; a + 1 < D; ++a) k[a] = static_cast<long>(std::floor(P.position[i][a] / column_width));
    const double up = P.position[i][D - 1];
    auto [it, fresh] = c.bottom_top.try_emplace(k, up, up);
    if (!fresh) {
      it->second.first = std::min(it->second.first, up);
      it->second.second = std::max(it->second.second, up);
    }
  }
  return c;
}

// The front is the particle of the phase furthest along `direction` (a unit vector: down the slope, say), the lowest
// id among equals so the answer does not depend on the particle order. A column's thickness is the vertical extent of
// its particles plus one spacing (each particle stands for dp of height: a block of n rows reads n dp).
template <int D>
SlideFrontOf<D> measure_slide_front(const Particles<D>& P, std::uint8_t phase,
                                    const std::type_identity_t<Vec<D>>& direction, double dp,
                                    double column_width) {
  SlideFrontOf<D> f;
  double best = -std::numeric_limits<double>::infinity();
  ParticleId best_id = 0;
  for (std::size_t i = 0; i < P.real_count(); ++i) {  // real particles: not their images
    if (P.kind[i] != Kind::fluid || P.phase[i] != phase) continue;
    ++f.particles;
    const double s = direction.dot(P.position[i]);
    if (s > best || (s == best && P.id[i] < best_id)) {
      best = s;
      best_id = P.id[i];
      f.front = P.position[i];
    }
  }
  for (const auto& [k, bt] : slide_columns(P, phase, column_width).bottom_top)
    f.thickness_max = std::max(f.thickness_max, bt.second - bt.first + dp);
  return f;
}

// The slide's upper surface: for every column holding its particles, the column's centre and its highest particle
// centre plus half a spacing (the top of the material), in increasing x (then y).
template <int D>
std::vector<Vec<D>> slide_upper_surface(const Particles<D>& P, std::uint8_t phase, double dp, double column_width) {
  std::vector<Vec<D>> out;
  for (const auto& [k, bt] : slide_columns(P, phase, column_width).bottom_top) {
    Vec<D> top;
    for (int a = 0; a + 1 < D; ++a) top[a] = (k[a] + 0.5) * column_width;
    top[D - 1] = bt.second + 0.5 * dp;
    out.push_back(top);
  }
  return out;
}

// A rigid body's upper surface from its boundary particles: for every column holding its wall particles (the layer
// half a spacing inside its surface), the column's centre and its highest wall particle plus half a spacing, in
// increasing x (then y).
template <int D>
std::vector<Vec<D>> body_upper_surface(const Particles<D>& P, int body, double dp, double column_width) {
  std::map<std::array<long, D - 1>, double> highest;
  for (std::size_t i = 0; i < P.real_count(); ++i) {
    if (P.kind[i] != Kind::wall || P.body_of(i) != body) continue;
    std::array<long, D - 1> k;
    for (int a = 0; a + 1 < D; ++a) k[a] = static_cast<long>(std::floor(P.position[i][a] / column_width));
    auto [it, fresh] = highest.try_emplace(k, P.position[i][D - 1]);
    if (!fresh) it->second = std::max(it->second, P.position[i][D - 1]);
  }
  std::vector<Vec<D>> out;
  for (const auto& [k, up] : highest) {
    Vec<D> top;
    for (int a = 0; a + 1 < D; ++a) top[a] = (k[a] + 0.5) * column_width;
    top[D - 1] = up + 0.5 * dp;
    out.push_back(top);
  }
  return out;
}

// A polygon's upper surface (a rigid slide's outline, any orientation): for every column of width `column_width` whose
// centre lies within the polygon's x range, the centre and the highest point of the outline above it, in increasing x.
inline std::vector<Vec<2>> polygon_upper_surface(const std::vector<Vec<2>>& outline, double column_width) {
  std::vector<Vec<2>> out;
  if (outline.size() < 3) return out;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& v : outline) lo = std::min(lo, v[0]), hi = std::max(hi, v[0]);
  for (long k = static_cast<long>(std::floor(lo / column_width)); (k + 0.5) * column_width <= hi; ++k) {
    const double x = (k + 0.5) * column_width;
    if (x < lo) continue;
    double top = -std::numeric_limits<double>::infinity();
    for (std::size_t m = 0; m < outline.size(); ++m) {
      const Vec<2>& a = outline[m];
      const Vec<2>& b = outline[(m + 1) % outline.size()];
      if ((x < std::min(a[0], b[0])) || (x > std::max(a[0], b[0]))) continue;
      const double y = a[0] == b[0] ? std::max(a[1], b[1]) : a[1] + (x - a[0]) / (b[0] - a[0]) * (b[1] - a[1]);
      top = std::max(top, y);
    }
    out.emplace_back(x, top);
  }
  return out;
}

}  // namespace slide
