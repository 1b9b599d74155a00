#pragma once
// The lattice that particles start on: square (simple cubic in 3-D), or the close-packed one of the dimension:
// hexagonal in 2-D, face-centred cubic (fcc) in 3-D. All hold one particle per dp^d of space, so a particle's mass is
// rho dp^d on any; n0, lambda and kappa are lattice sums over the chosen one.
//
// Why a hexagonal lattice: under the (p_i + p_j) pressure gradients a compressed square lattice is a saddle (a
// repulsive pair force gives its shear modes negative stiffness), so still water started on it rearranges by itself.
// The hexagonal lattice is the stable packing of repulsive particles; still water started on it stays put in the
// bulk (issue 3's closing note has the measurements).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string_view>

#include "fluid/kernel.hpp"
#include "fluid/name_table.hpp"

namespace slide {

enum class LatticeKind { square, hexagonal, fcc };

inline constexpr auto lattice_kind_names = make_name_table<LatticeKind>(std::pair{LatticeKind::square, "square"},
                                                                      std::pair{LatticeKind::hexagonal, "hexagonal"},
                                                                      std::pair{LatticeKind::fcc, "fcc"});

// The face-centred cubic lattice with one point per dp^3 is the simple cubic lattice of spacing s = 2^(-1/3) dp with
// i + j + k even (half its points, so 1 / (2 s^3) = 1 / dp^3): its planes across each axis are s apart, and its
// nearest spacing is s sqrt(2) = 2^(1/6) dp = 1.1225 dp.
inline double fcc_plane_spacing(double dp) { return dp * std::pow(2.0, -1.0 / 3.0); }

inline std::string_view to_string(LatticeKind k) { return lattice_kind_names.name(k); }

// Nearest-neighbour distance of a lattice with one particle per dp^2: dp on the square lattice, and on the
// hexagonal lattice a with a * (sqrt(3) / 2) a = dp^2, i.e. a = dp sqrt(2 / sqrt(3)) = 1.0746 dp.
// On the fcc lattice: 2^(1/6) dp = 1.1225 dp.
inline double nearest_spacing(LatticeKind k, double dp) {
  if (k == LatticeKind::fcc) return std::sqrt(2.0) * fcc_plane_spacing(dp);
  return k == LatticeKind::square ? dp : dp * std::sqrt(2.0 / std::sqrt(3.0));
}

// Distance between the lattice's horizontal rows: dp, or (sqrt(3) / 2) a = 0.9306 dp on the hexagonal lattice.
// On the fcc lattice, the distance between its horizontal planes: 2^(-1/3) dp = 0.7937 dp.
inline double row_spacing(LatticeKind k, double dp) {
  if (k == LatticeKind::fcc) return fcc_plane_spacing(dp);
  return k == LatticeKind::square ? dp : 0.5 * std::sqrt(3.0) * nearest_spacing(k, dp);
}

// Lattice point (i, j) in 2-D, anchored so that the square lattice's cells tile the plane from the origin:
// square: ((i + 1/2) dp, (j + 1/2) dp); hexagonal: rows at (j + 1/2) h, odd rows shifted by half a spacing,
// x = (i + 1/2 + (j mod 2) / 2) a. The whole lattice is then moved by `offset` (cases/build_walls.cpp moves the rows to
// meet a body's bottom, row_offset_to_meet below).
inline Vec<2> lattice_point(LatticeKind k, double dp, long i, long j, const Vec<2>& offset = Vec<2>::Zero()) {
  if (k == LatticeKind::square) return Vec<2>((i + 0.5) * dp, (j + 0.5) * dp) + offset;
  const double a = nearest_spacing(k, dp), h = row_spacing(k, dp);
  const long odd = ((j % 2) + 2) % 2;
  return Vec<2>((i + 0.5 + 0.5 * odd) * a, (j + 0.5) * h) + offset;
}

// Calls f(point) for every 2-D lattice point in the box [lo, hi] (and a few beyond it; callers test membership).
template <class F>
void for_each_lattice_point(LatticeKind k, double dp, const Vec<2>& lo, const Vec<2>& hi, F&& f,
                            const Vec<2>& offset = Vec<2>::Zero()) {
  const double a = nearest_spacing(k, dp), h = row_spacing(k, dp);
  const Vec<2> l = lo - offset, u = hi - offset;
  const long i0 = static_cast<long>(std::floor(l[0] / a)) - 2, i1 = static_cast<long>(std::ceil(u[0] / a)) + 1;
  const long j0 = static_cast<long>(std::floor(l[1] / h)) - 1, j1 = static_cast<long>(std::ceil(u[1] / h)) + 1;
  for (long j = j0; j <= j1; ++j)
    for (long i = i0; i <= i1; ++i) f(lattice_point(k, dp, i, j, offset));
}

// Calls f(point) for every point of a 3-D lattice in the box [lo, hi] (and a few beyond it; callers test membership),
// z slowest, x fastest: square (simple cubic), ((i + 1/2) dp, (j + 1/2) dp, (k + 1/2) dp); fcc, the same with the
// plane spacing s (fcc_plane_spacing) for i + j + k even. Then moved by offset.
template <class F>
void for_each_lattice_point(LatticeKind kind, double dp, const Vec<3>& lo, const Vec<3>& hi, F&& f,
                            const Vec<3>& offset = Vec<3>::Zero()) {
  if (kind == LatticeKind::hexagonal) throw std::invalid_argument("the hexagonal lattice is 2-D only (3-D: fcc)");
  const bool fcc = kind == LatticeKind::fcc;
  const double s = fcc ? fcc_plane_spacing(dp) : dp;
  std::array<long, 3> first{}, last{};
  for (int a = 0; a < 3; ++a) {
    first[a] = static_cast<long>(std::floor((lo[a] - offset[a]) / s)) - 1;
    last[a] = static_cast<long>(std::ceil((hi[a] - offset[a]) / s)) + 1;
  }
  for (long k = first[2]; k <= last[2]; ++k)
    for (long j = first[1]; j <= last[1]; ++j)
      for (long i = first[0]; i <= last[0]; ++i)
        if (!fcc || ((i + j + k) % 2 + 2) % 2 == 0) f(Vec<3>((i + 0.5) * s, (j + 0.5) * s, (k + 0.5) * s) + offset);
}

// The lattice laid along a face (fluid/walls.hpp; a slide resting on it, cases/build_fluid_regions.cpp): rows
// parallel to the face at (k + 1/2) h on the side `out` points to (k < 0: behind it), points a apart along each row
// from `origin`, odd rows shifted by a / 2 on the hexagonal lattice. Rows k = -1 and k = 0 are a row spacing apart
// across the face, so a wall's rows (k < 0) and a slide's (k >= 0) form one unbroken lattice.
inline Vec<2> face_lattice_point(LatticeKind kind, double dp, const Vec<2>& origin, const Vec<2>& along,
                                 const Vec<2>& out, long i, long k) {
  const double a = nearest_spacing(kind, dp), h = row_spacing(kind, dp);
  const double shift = kind == LatticeKind::hexagonal ? 0.5 * static_cast<double>(((k % 2) + 2) % 2) : 0.0;
  return origin + ((i + shift) * a) * along + ((k + 0.5) * h) * out;
}

// Calls f(point) for every point of that lattice in the box [lo, hi] (and a few beyond it; callers test membership).
template <class F>
void for_each_face_lattice_point(LatticeKind kind, double dp, const Vec<2>& origin, const Vec<2>& along,
                                 const Vec<2>& out, const Vec<2>& lo, const Vec<2>& hi, F&& f) {
  const double a = nearest_spacing(kind, dp), h = row_spacing(kind, dp);
  double s_lo = std::numeric_limits<double>::infinity(), s_hi = -s_lo, n_lo = s_lo, n_hi = -s_lo;
  for (const Vec<2>& c : {lo, hi, Vec<2>(lo[0], hi[1]), Vec<2>(hi[0], lo[1])}) {
    s_lo = std::min(s_lo, (c - origin).dot(along)), s_hi = std::max(s_hi, (c - origin).dot(along));
    n_lo = std::min(n_lo, (c - origin).dot(out)), n_hi = std::max(n_hi, (c - origin).dot(out));
  }
  const long k0 = static_cast<long>(std::floor(n_lo / h)) - 1, k1 = static_cast<long>(std::ceil(n_hi / h)) + 1;
  const long i0 = static_cast<long>(std::floor(s_lo / a)) - 1, i1 = static_cast<long>(std::ceil(s_hi / a)) + 1;
  for (long k = k0; k <= k1; ++k)
    for (long i = i0; i <= i1; ++i) f(face_lattice_point(kind, dp, origin, along, out, i, k));
}

// The vertical offset, in (-h/2, h/2], that puts a row of the lattice at height y.
inline double row_offset_to_meet(LatticeKind k, double dp, double y) {
  const double h = row_spacing(k, dp);
  const double unshifted = (std::round(y / h - 0.5) + 0.5) * h;  // the nearest row of the unmoved lattice
  return y - unshifted;
}

// n0, lambda and kappa (fluid/kernel.hpp) on the hexagonal lattice of nearest spacing a:
// points a (i + j / 2, j sqrt(3) / 2) for integers i, j, all within re except the origin.
inline LatticeConstants hexagonal_lattice_constants(double a, double re) {
  const int m = static_cast<int>(std::ceil(2.0 * re / (std::sqrt(3.0) * a))) + 1;  // rows within re
  double sum_w = 0.0, sum_wr2 = 0.0, sum_dwr = 0.0;
  for (int j = -m; j <= m; ++j)
    for (int i = -2 * m - 2; i <= 2 * m + 2; ++i) {
      if (i == 0 && j == 0) continue;
      const double x = a * (i + 0.5 * j), y = a * 0.5 * std::sqrt(3.0) * j;
      const double r = std::sqrt(x * x + y * y);
      const double w = kernel_weight(r, re);
      sum_w += w;
      sum_wr2 += w * r * r;
      sum_dwr += -kernel_derivative(r, re) * r;
    }
  return {sum_w, sum_wr2 / sum_w, sum_dwr / (2.0 * sum_w)};
}

// n0, lambda and kappa on the fcc lattice of one point per dp^3: the points s (i, j, k), i + j + k even, of the
// simple cubic lattice of spacing s = fcc_plane_spacing(dp), all within re except the origin.
inline LatticeConstants fcc_lattice_constants(double dp, double re) {
  const double s = fcc_plane_spacing(dp);
  const int m = static_cast<int>(std::ceil(re / s)) + 1;
  double sum_w = 0.0, sum_wr2 = 0.0, sum_dwr = 0.0;
  for (int i = -m; i <= m; ++i)
    for (int j = -m; j <= m; ++j)
      for (int k = -m; k <= m; ++k) {
        if ((i == 0 && j == 0 && k == 0) || ((i + j + k) % 2 + 2) % 2 != 0) continue;
        const double r = s * std::sqrt(double(i) * i + double(j) * j + double(k) * k);
        const double w = kernel_weight(r, re);
        sum_w += w;
        sum_wr2 += w * r * r;
        sum_dwr += -kernel_derivative(r, re) * r;
      }
  return {sum_w, sum_wr2 / sum_w, sum_dwr / (3.0 * sum_w)};
}

// The lattice constants of the lattice the particles start on.
template <int D>
LatticeConstants lattice_constants(double dp, double re, LatticeKind k) {
  if (k == LatticeKind::square) return lattice_constants<D>(dp, re);
  if constexpr (D == 2) {
    if (k == LatticeKind::fcc) throw std::invalid_argument("the fcc lattice is 3-D only (2-D: hexagonal)");
    return hexagonal_lattice_constants(nearest_spacing(k, dp), re);
  } else {
    if (k == LatticeKind::hexagonal) throw std::invalid_argument("the hexagonal lattice is 2-D only (3-D: fcc)");
    return fcc_lattice_constants(dp, re);
  }
}

}  // namespace slide
