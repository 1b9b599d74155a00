#pragma once
// Which fixed wall a fluid particle passed through in a step. A wall's particles fill a band `thickness` deep behind
// its face (fluid/walls.hpp: layers at (k + 1/2) dp). A move that crosses the back of that band, from the fluid's
// side and within the face segment's length, went through the wall: an instability. A particle that leaves the
// domain without such a crossing left through an open side (a splash over the top, a jet past a wall's end) and is
// taken out of the run (coupling/simulation.hpp). Faces are 2-D polylines; rigid bodies are not walls here.
//
// The faces are binned on a grid of cells at least as large as any step's move, each face in every cell within one
// cell of its band, so a move is tested against the faces of the cell where it ends.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "fluid/vec.hpp"

namespace slide {

struct WallFace {
  Vec<2> a, b;     // the face segment, m
  Vec<2> inward;   // unit normal from the face into the fluid
};

class WallCrossing {
 public:
  WallCrossing() = default;
  // thickness: how deep behind the face the wall's particles reach, m; [lo, hi]: the grid's extent, cell: its size.
  WallCrossing(std::vector<WallFace> faces, double thickness, const Vec<2>& lo, const Vec<2>& hi, double cell)
      : faces_(std::move(faces)), thickness_(thickness), lo_(lo), cell_(cell) {
    nx_ = std::max(1, static_cast<int>(std::ceil((hi[0] - lo[0]) / cell)));
    ny_ = std::max(1, static_cast<int>(std::ceil((hi[1] - lo[1]) / cell)));
    std::vector<std::vector<std::uint32_t>> bins(static_cast<std::size_t>(nx_) * ny_);
    for (std::uint32_t k = 0; k < faces_.size(); ++k) {
      const WallFace& f = faces_[k];
      const Vec<2> back = -thickness * f.inward;
      const Vec<2> lo_face = f.a.cwiseMin(f.b).cwiseMin(f.a + back).cwiseMin(f.b + back);
      const Vec<2> hi_face = f.a.cwiseMax(f.b).cwiseMax(f.a + back).cwiseMax(f.b + back);
      const auto [i0, j0] = cell_of(lo_face);
      const auto [i1, j1] = cell_of(hi_face);
      for (int j = std::max(0, j0 - 1); j <= std::min(ny_ - 1, j1 + 1); ++j)
        for (int i = std::max(0, i0 - 1); i <= std::min(nx_ - 1, i1 + 1); ++i)
          bins[static_cast<std::size_t>(j) * nx_ + i].push_back(k);
    }
    start_.assign(bins.size() + 1, 0);
    for (std::size_t c = 0; c < bins.size(); ++c) start_[c + 1] = start_[c] + bins[c].size();
    for (const auto& bin : bins) list_.insert(list_.end(), bin.begin(), bin.end());
  }

  bool empty() const { return faces_.empty(); }
  const WallFace& face(int k) const { return faces_[static_cast<std::size_t>(k)]; }

  // The lowest index of a face whose back the move from -> to crossed from the fluid's side, or -1. With d(p) the
  // signed distance of p from the back line (positive towards the fluid), a crossing has d(from) >= 0 > d(to) and
  // meets the line at a point whose projection falls on the face segment.
  int crossed(const Vec<2>& from, const Vec<2>& to) const {
    if (faces_.empty()) return -1;
    const auto [i, j] = cell_of(to);
    const std::size_t c = static_cast<std::size_t>(std::clamp(j, 0, ny_ - 1)) * nx_ + std::clamp(i, 0, nx_ - 1);
    for (std::size_t e = start_[c]; e < start_[c + 1]; ++e) {
      const WallFace& f = faces_[list_[e]];
      const double d_from = (from - f.a).dot(f.inward) + thickness_;
      const double d_to = (to - f.a).dot(f.inward) + thickness_;
      if (!(d_from >= 0.0 && d_to < 0.0)) continue;
      const Vec<2> meet = from + (d_from / (d_from - d_to)) * (to - from);
      const Vec<2> along = f.b - f.a;
      const double t = (meet - f.a).dot(along) / along.squaredNorm();
      if (t >= 0.0 && t <= 1.0) return static_cast<int>(list_[e]);
    }
    return -1;
  }

 private:
  // The cell of p, clamped to one cell beyond the grid either way (NaN to the first): the cast stays defined for any
  // coordinate, a blown-up one included.
  std::pair<int, int> cell_of(const Vec<2>& p) const {
    auto index = [&](double x, double lo, int n) {
      const double c = std::floor((x - lo) / cell_);
      return c >= -1.0 ? (c <= double(n) ? static_cast<int>(c) : n) : -1;
    };
    return {index(p[0], lo_[0], nx_), index(p[1], lo_[1], ny_)};
  }

  std::vector<WallFace> faces_;
  double thickness_ = 0.0;
  Vec<2> lo_ = Vec<2>::Zero();
  double cell_ = 1.0;
  int nx_ = 1, ny_ = 1;
  std::vector<std::size_t> start_;   // faces of cell c: list_[start_[c] .. start_[c + 1])
  std::vector<std::uint32_t> list_;  // in increasing face index within each cell
};

}  // namespace slide
