#pragma once
// Where a deformable slide is and what shape it has (slide_front.csv, slide_outline.csv): its front, its largest
// thickness and its upper surface, from the particles of its phase.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <vector>

#include "coupling/simulation.hpp"

namespace slide {

struct SlideFront {
  Vec<2> front = Vec<2>::Constant(std::numeric_limits<double>::quiet_NaN());  // m, the particle furthest along
  double thickness_max = 0.0;  // m, largest vertical thickness of a column
  std::size_t particles = 0;
};

// Columns of width `column_width` along x (column k holds x in [k w, (k + 1) w)), each with the lowest and highest
// particle centre of the slide's phase in it.
struct SlideColumns {
  std::map<long, std::pair<double, double>> bottom_top;  // column -> (lowest y, highest y)
  double width = 0.0;
};

inline SlideColumns slide_columns(const Particles<2>& P, std::uint8_t phase, double column_width) {
  SlideColumns c;
  c.width = column_width;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::fluid || P.phase[i] != phase) continue;
    const long k = static_cast<long>(std::floor(P.position[i][0] / column_width));
    auto [it, fresh] = c.bottom_top.try_emplace(k, P.position[i][1], P.position[i][1]);
    if (!fresh) {
      it->second.first = std::min(it->second.first, P.position[i][1]);
      it->second.second = std::max(it->second.second, P.position[i][1]);
    }
  }
  return c;
}

// The front is the particle of the phase furthest along `direction` (a unit vector: down the slope, say), the lowest
// id among equals so the answer does not depend on the particle order. A column's thickness is the vertical extent of
// its particles plus one spacing (each particle stands for dp of height: a block of n rows reads n dp).
inline SlideFront measure_slide_front(const Particles<2>& P, std::uint8_t phase, const Vec<2>& direction, double dp,
                                      double column_width) {
  SlideFront f;
  double best = -std::numeric_limits<double>::infinity();
  std::uint32_t best_id = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
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
// centre plus half a spacing (the top of the material), in increasing x.
inline std::vector<Vec<2>> slide_upper_surface(const Particles<2>& P, std::uint8_t phase, double dp,
                                               double column_width) {
  std::vector<Vec<2>> out;
  for (const auto& [k, bt] : slide_columns(P, phase, column_width).bottom_top)
    out.emplace_back((k + 0.5) * column_width, bt.second + 0.5 * dp);
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
