#pragma once
// Which fixed wall a fluid particle passed through in a step. A wall's particles fill a band `thickness` deep behind
// its face (fluid/walls.hpp: layers at (k + 1/2) dp; fluid/box_walls.hpp and cases/terrain_layers.hpp in 3-D). A move
// that crosses the back of that band, from the fluid's side and where the back lies behind the face, went through the
// wall: an instability. A particle that leaves the domain without such a crossing left through an open side (a splash
// over the top, a jet past a wall's end) and is taken out of the run (coupling/simulation.hpp). A face is a segment in
// 2-D and a triangle in 3-D; rigid bodies are not walls here.
//
// The faces are binned on a grid of cells at least as large as any step's move, each face in every cell within one
// cell of its band, so a move is tested against the faces of the cell where it ends.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "fluid/vec.hpp"

namespace slide {

template <int D>
struct WallFace {
  std::array<Vec<D>, D> corner;  // the segment's ends (2-D) or the triangle's corners (3-D), m
  Vec<D> inward;                 // unit normal from the face into the fluid
  double thickness = 0.0;        // m: how deep behind the face the wall's particles reach
};

// Whether p, a point of the face's plane (line in 2-D), lies on the face: within the segment, or within the triangle
// by its barycentric coordinates (Ericson, Real-Time Collision Detection, 3.4).
template <int D>
bool on_face(const WallFace<D>& f, const Vec<D>& p) {
  const Vec<D> e0 = f.corner[1] - f.corner[0], v = p - f.corner[0];
  if constexpr (D == 2) {
    const double t = v.dot(e0) / e0.squaredNorm();
    return t >= 0.0 && t <= 1.0;
  } else {
    const Vec<D> e1 = f.corner[2] - f.corner[0];
    const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1), d20 = v.dot(e0), d21 = v.dot(e1);
    const double det = d00 * d11 - d01 * d01;
    const double u = (d11 * d20 - d01 * d21) / det, w = (d00 * d21 - d01 * d20) / det;
    return u >= 0.0 && w >= 0.0 && u + w <= 1.0;
  }
}

template <int D>
class WallCrossing {
 public:
  WallCrossing() = default;
  // [lo, hi]: the grid's extent, cell: its size.
  WallCrossing(std::vector<WallFace<D>> faces, const Vec<D>& lo, const Vec<D>& hi, double cell)
      : faces_(std::move(faces)), lo_(lo), cell_(cell) {
    std::size_t cells = 1;
    for (int k = 0; k < D; ++k) {
      n_[k] = std::max(1, static_cast<int>(std::ceil((hi[k] - lo[k]) / cell)));
      cells *= static_cast<std::size_t>(n_[k]);
    }
    std::vector<std::vector<std::uint32_t>> bins(cells);
    for (std::uint32_t k = 0; k < faces_.size(); ++k) {
      const WallFace<D>& f = faces_[k];
      const Vec<D> back = -f.thickness * f.inward;
      Vec<D> lo_face = f.corner[0], hi_face = f.corner[0];
      for (const Vec<D>& c : f.corner) {
        lo_face = lo_face.cwiseMin(c).cwiseMin(c + back);
        hi_face = hi_face.cwiseMax(c).cwiseMax(c + back);
      }
      const auto first = cell_of(lo_face), last = cell_of(hi_face);
      std::array<int, D> from{}, to{};
      for (int d = 0; d < D; ++d) {
        from[d] = std::max(0, first[d] - 1);
        to[d] = std::min(n_[d] - 1, last[d] + 1);
      }
      for_each_cell(from, to, [&](std::size_t c) { bins[c].push_back(k); });
    }
    start_.assign(bins.size() + 1, 0);
    for (std::size_t c = 0; c < bins.size(); ++c) start_[c + 1] = start_[c] + bins[c].size();
    for (const auto& bin : bins) list_.insert(list_.end(), bin.begin(), bin.end());
  }

  bool empty() const { return faces_.empty(); }
  const WallFace<D>& face(int k) const { return faces_[static_cast<std::size_t>(k)]; }

  // The lowest index of a face whose back the move from -> to crossed from the fluid's side, or -1. With d(p) the
  // signed distance of p from the back (positive towards the fluid), a crossing has d(from) >= 0 > d(to) and meets
  // the back at a point behind the face.
  int crossed(const Vec<D>& from, const Vec<D>& to) const {
    if (faces_.empty()) return -1;
    const auto at = cell_of(to);
    std::size_t c = 0;
    for (int d = D - 1; d >= 0; --d) c = c * n_[d] + static_cast<std::size_t>(std::clamp(at[d], 0, n_[d] - 1));
    for (std::size_t e = start_[c]; e < start_[c + 1]; ++e) {
      const WallFace<D>& f = faces_[list_[e]];
      const double d_from = (from - f.corner[0]).dot(f.inward) + f.thickness;
      const double d_to = (to - f.corner[0]).dot(f.inward) + f.thickness;
      if (!(d_from >= 0.0 && d_to < 0.0)) continue;
      const Vec<D> meet = from + (d_from / (d_from - d_to)) * (to - from);
      if (on_face(f, Vec<D>(meet + f.thickness * f.inward))) return static_cast<int>(list_[e]);
    }
    return -1;
  }

 private:
  // The cell of p, clamped to one cell beyond the grid either way (NaN to the first): the cast stays defined for any
  // coordinate, a blown-up one included.
  std::array<int, D> cell_of(const Vec<D>& p) const {
    std::array<int, D> at{};
    for (int d = 0; d < D; ++d) {
      const double c = std::floor((p[d] - lo_[d]) / cell_);
      at[d] = c >= -1.0 ? (c <= double(n_[d]) ? static_cast<int>(c) : n_[d]) : -1;
    }
    return at;
  }

  // Calls f(cell index) for the cells from..to (inclusive) in every axis; x varies fastest.
  template <class F>
  void for_each_cell(const std::array<int, D>& from, const std::array<int, D>& to, F&& f) const {
    std::array<int, D> at = from;
    for (int d = 0; d < D; ++d)
      if (from[d] > to[d]) return;
    while (true) {
      std::size_t c = 0;
      for (int d = D - 1; d >= 0; --d) c = c * n_[d] + static_cast<std::size_t>(at[d]);
      f(c);
      int d = 0;
      while (d < D && ++at[d] > to[d]) at[d] = from[d], ++d;
      if (d == D) return;
    }
  }

  std::vector<WallFace<D>> faces_;
  Vec<D> lo_ = Vec<D>::Zero();
  double cell_ = 1.0;
  std::array<int, D> n_{};
  std::vector<std::size_t> start_;   // faces of cell c: list_[start_[c] .. start_[c + 1])
  std::vector<std::uint32_t> list_;  // in increasing face index within each cell
};

}  // namespace slide
