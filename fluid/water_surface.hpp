#pragma once
// The height of the water's free surface above any point: the pore water's hydrostatic head in a sediment
// (fluid/pore_pressure.hpp) and the water's pressure on the faces of a body resting on a wall (coupling/).
//
// Heights are measured along up = -g / |g| (a scene may tilt gravity to make a slope of a flat floor). The space
// across up is cut into columns of one spacing (a line of columns in 2-D, a grid of them in 3-D); a column's surface
// is its highest water particle's centre plus dp / 2 (the particle stands for dp of height, as the free-surface row
// lies half a spacing inside the true surface). A point's surface is the highest of its own column's and the
// neighbouring ones' (the 3 or 3 x 3 around it), so that a column the lattice happens to leave without a particle
// near the surface, or a thin column beside a slide, does not read a hole. A column with no water within one column
// of it has no surface (-infinity): a point there is dry.
// What it leaves out: the surface is the highest water above a point, not the nearest; a drop flying above a slide
// wets the column under it while it flies (its head is the drop's height). Waves enter through the surface's height,
// not through their dynamic pressure.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "fluid/communicator.hpp"
#include "fluid/particles.hpp"

namespace slide {

template <int D>
class WaterSurface {
 public:
  // From the real fluid particles for which is_water(i) holds; `gravity` non-zero. On several processes (comm), from
  // every process's: the columns' extent and their highest water are maxima across them, the same on each.
  template <class IsWater>
  void build(const Particles<D>& P, const Vec<D>& gravity, double dp, IsWater&& is_water,
             const Communicator* comm = nullptr) {
    set_axes(gravity);
    width_ = dp;
    const std::size_t n = P.real_count();
    std::array<long, D - 1> lo, hi;
    lo.fill(std::numeric_limits<long>::max());
    hi.fill(std::numeric_limits<long>::min());
    bool any = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (P.kind[i] != Kind::fluid || !is_water(i)) continue;
      const auto c = column(P.position[i]);
      for (int k = 0; k < D - 1; ++k) lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
      any = true;
    }
    if (comm) {
      std::array<std::int64_t, 2 * (D - 1) + 1> v;
      for (int k = 0; k < D - 1; ++k) v[k] = -lo[k], v[D - 1 + k] = hi[k];
      v[2 * (D - 1)] = any ? 1 : 0;
      comm->max(v.data(), v.size());
      for (int k = 0; k < D - 1; ++k) lo[k] = -v[k], hi[k] = v[D - 1 + k];
      any = v[2 * (D - 1)] != 0;
    }
    top_.clear();
    if (!any) return;
    // One column of margin on every side, so that a point beside the water reads its neighbours' surface.
    for (int k = 0; k < D - 1; ++k) origin_[k] = lo[k] - 1, extent_[k] = hi[k] - lo[k] + 3;
    std::size_t cells = 1;
    for (int k = 0; k < D - 1; ++k) cells *= static_cast<std::size_t>(extent_[k]);
    const double none = -std::numeric_limits<double>::infinity();
    std::vector<double> own(cells, none);
    for (std::size_t i = 0; i < n; ++i) {
      if (P.kind[i] != Kind::fluid || !is_water(i)) continue;
      double& t = own[index(column(P.position[i]))];
      t = std::max(t, height(P.position[i]) + 0.5 * dp);
    }
    if (comm) comm->max(own.data(), own.size());
    top_.assign(cells, none);
    for (std::size_t c = 0; c < cells; ++c) {
      const auto at = unindex(c);
      for_each_neighbour(at, [&](std::size_t m) { top_[c] = std::max(top_[c], own[m]); });
    }
  }

  // Height of the point x along up, m.
  double height(const Vec<D>& x) const { return x.dot(up_); }

  // The water's surface height above x, m (-infinity where there is no water above it, or before any build).
  double surface_above(const Vec<D>& x) const {
    if (top_.empty()) return -std::numeric_limits<double>::infinity();
    auto c = column(x);
    for (int k = 0; k < D - 1; ++k) {
      c[k] -= origin_[k];
      if (c[k] < 0 || c[k] >= extent_[k]) return -std::numeric_limits<double>::infinity();
      c[k] += origin_[k];
    }
    return top_[index(c)];
  }

  // How deep x lies below the water's surface, m (0 where it is dry: above the surface or without water above).
  double depth_below_surface(const Vec<D>& x) const { return std::max(0.0, surface_above(x) - height(x)); }

  const Vec<D>& up() const { return up_; }

 private:
  void set_axes(const Vec<D>& gravity) {
    up_ = -gravity.normalized();
    if constexpr (D == 2) {
      across_[0] = Vec<D>(up_[1], -up_[0]);
    } else {
      // Any unit vector not along up, made normal to it; the third axis completes the frame.
      Vec<D> a = std::abs(up_[0]) < 0.9 ? Vec<D>(1.0, 0.0, 0.0) : Vec<D>(0.0, 1.0, 0.0);
      across_[0] = (a - a.dot(up_) * up_).normalized();
      const Vec<D>& u = up_;
      const Vec<D>& v = across_[0];
      across_[1] = Vec<D>(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
    }
  }

  std::array<long, D - 1> column(const Vec<D>& x) const {
    std::array<long, D - 1> c;
    for (int k = 0; k < D - 1; ++k) c[k] = static_cast<long>(std::floor(x.dot(across_[k]) / width_));
    return c;
  }

  std::size_t index(const std::array<long, D - 1>& c) const {
    std::size_t m = 0;
    for (int k = D - 2; k >= 0; --k) m = m * static_cast<std::size_t>(extent_[k]) + static_cast<std::size_t>(c[k] - origin_[k]);
    return m;
  }

  std::array<long, D - 1> unindex(std::size_t m) const {
    std::array<long, D - 1> c;
    for (int k = 0; k < D - 1; ++k) {
      c[k] = origin_[k] + static_cast<long>(m % static_cast<std::size_t>(extent_[k]));
      m /= static_cast<std::size_t>(extent_[k]);
    }
    return c;
  }

  // The column c and those beside it (inside the table), by index.
  template <class F>
  void for_each_neighbour(const std::array<long, D - 1>& c, F&& f) const {
    if constexpr (D == 2) {
      for (long a = c[0] - 1; a <= c[0] + 1; ++a)
        if (a >= origin_[0] && a < origin_[0] + extent_[0]) f(index({a}));
    } else {
      for (long a = c[0] - 1; a <= c[0] + 1; ++a)
        for (long b = c[1] - 1; b <= c[1] + 1; ++b)
          if (a >= origin_[0] && a < origin_[0] + extent_[0] && b >= origin_[1] && b < origin_[1] + extent_[1])
            f(index({a, b}));
    }
  }

  Vec<D> up_ = Vec<D>::Zero();
  std::array<Vec<D>, D - 1> across_{};
  double width_ = 1.0;
  std::array<long, D - 1> origin_{}, extent_{};
  std::vector<double> top_;  // surface height of each column, m
};

}  // namespace slide
