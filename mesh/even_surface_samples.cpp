// Steps: even points on a surface (mesh/even_surface_samples.hpp) by weighted sample elimination.
#include "mesh/even_surface_samples.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <queue>
#include <random>
#include <unordered_map>

namespace slide::mesh {
namespace {

using rigid::Vec3;

// Uniform in [0, 1) from the generator's 53 high bits: std::uniform_real_distribution's output is not fixed by the
// standard, std::mt19937_64's sequence is.
double unit(std::mt19937_64& rng) { return double(rng() >> 11) * 0x1.0p-53; }

// `count` points spread uniformly by area over the triangles: triangle t gets the whole points of its share of the
// cumulative area (stratified, so that each triangle has its expected number to within one), each at a uniform place
// in it (a = 1 - sqrt(r1), b = sqrt(r1) (1 - r2), c = sqrt(r1) r2).
std::vector<SurfaceSample> candidates(const rigid::TriangleSurface& s, const std::vector<double>& areas, double total,
                                      long count, unsigned long seed) {
  std::mt19937_64 rng(seed);
  std::vector<SurfaceSample> out;
  out.reserve(std::size_t(count) + s.triangles.size());
  double before = 0.0;
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const long from = std::lround(std::floor(count * before / total));
    before += areas[t];
    const long to = std::lround(std::floor(count * before / total));
    const Vec3 &a = s.vertices[s.triangles[t][0]], &b = s.vertices[s.triangles[t][1]], &c = s.vertices[s.triangles[t][2]];
    for (long k = from; k < to; ++k) {
      const double r1 = std::sqrt(unit(rng)), r2 = unit(rng);
      out.push_back({(1.0 - r1) * a + (r1 * (1.0 - r2)) * b + (r1 * r2) * c, int(t)});
    }
  }
  return out;
}

// The pairs of points closer than `radius`, each point's list in index order (a hash grid of cells `radius` wide).
std::vector<std::vector<std::pair<int, double>>> close_pairs(const std::vector<SurfaceSample>& p, double radius) {
  using Key = std::array<long, 3>;
  const auto key_of = [radius](const Vec3& x) {
    return Key{long(std::floor(x[0] / radius)), long(std::floor(x[1] / radius)), long(std::floor(x[2] / radius))};
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      return std::size_t(k[0] * 73856093L) ^ std::size_t(k[1] * 19349663L) ^ std::size_t(k[2] * 83492791L);
    }
  };
  std::unordered_map<Key, std::vector<int>, Hash> cells;
  for (std::size_t i = 0; i < p.size(); ++i) cells[key_of(p[i].point)].push_back(int(i));
  std::vector<std::vector<std::pair<int, double>>> out(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Key k = key_of(p[i].point);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const auto it = cells.find(Key{k[0] + dx, k[1] + dy, k[2] + dz});
          if (it == cells.end()) continue;
          for (const int j : it->second) {
            const double d = (p[j].point - p[i].point).norm();
            if (j != int(i) && d < radius) out[i].emplace_back(j, d);
          }
        }
    std::sort(out[i].begin(), out[i].end());
  }
  return out;
}

}  // namespace

// Yuksel (2015): with N points wanted on area A out of M candidates, r_max = sqrt(A / (2 sqrt(3) N)) (half the spacing
// of N points in a hexagonal packing); each pair closer than 2 r_max weighs w = (1 - d' / (2 r_max))^8 with
// d' = max(d, r_min), r_min = r_max (1 - (N / M)^1.5) 0.65; the candidate with the largest total weight goes, its
// weight leaves its neighbours' totals, until N are left. Ties go to the lower index, so the result is fixed.
std::vector<SurfaceSample> even_surface_samples(const rigid::TriangleSurface& s, double spacing, unsigned long seed) {
  std::vector<double> areas;
  double total = 0.0;
  for (const auto& t : s.triangles) {
    areas.push_back(0.5 * (s.vertices[t[1]] - s.vertices[t[0]]).cross(s.vertices[t[2]] - s.vertices[t[0]]).norm());
    total += areas.back();
  }
  if (!(total > 0.0) || !(spacing > 0.0)) return {};
  const long wanted = std::max(1L, std::lround(total / (spacing * spacing)));
  const long oversampling = 8;
  const std::vector<SurfaceSample> p = candidates(s, areas, total, oversampling * wanted, seed);
  if (long(p.size()) <= wanted) return p;
  const double r_max = std::sqrt(total / (2.0 * std::sqrt(3.0) * double(wanted)));
  const double r_min = r_max * (1.0 - std::pow(double(wanted) / double(p.size()), 1.5)) * 0.65;
  const auto pairs = close_pairs(p, 2.0 * r_max);
  const auto weight = [&](double d) { return std::pow(1.0 - std::max(d, r_min) / (2.0 * r_max), 8); };
  std::vector<double> total_weight(p.size(), 0.0);
  for (std::size_t i = 0; i < p.size(); ++i)
    for (const auto& [j, d] : pairs[i]) total_weight[i] += weight(d);
  // A max-heap of (weight, -index) with stale entries skipped: a weight only falls, and each fall pushes a fresh entry.
  std::priority_queue<std::pair<double, long>> heap;
  for (std::size_t i = 0; i < p.size(); ++i) heap.emplace(total_weight[i], -long(i));
  std::vector<char> gone(p.size(), 0);
  long left = long(p.size());
  while (left > wanted) {
    const auto [w, minus_i] = heap.top();
    heap.pop();
    const std::size_t i = std::size_t(-minus_i);
    if (gone[i] || w != total_weight[i]) continue;
    gone[i] = 1;
    --left;
    for (const auto& [j, d] : pairs[i]) {
      if (gone[std::size_t(j)]) continue;
      total_weight[std::size_t(j)] -= weight(d);
      heap.emplace(total_weight[std::size_t(j)], -long(j));
    }
  }
  std::vector<SurfaceSample> out;
  out.reserve(std::size_t(wanted));
  for (std::size_t i = 0; i < p.size(); ++i)
    if (!gone[i]) out.push_back(p[i]);
  return out;
}

}  // namespace slide::mesh
