#pragma once
// Writers of mesh files for the tests (binary and ASCII STL, OBJ), so that each test makes the file it reads.
#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "rigid/polyhedron.hpp"

namespace slide::testing {

// A right prism over a polygon in the x-z plane (`outline`, any way round, may be concave), from y0 to y1, its caps the
// given triangles of outline indices (a concave outline's triangulation, by hand); every face turned outward.
inline rigid::TriangleSurface prism_along_y(const std::vector<std::array<double, 2>>& outline,
                                            const std::vector<std::array<int, 3>>& caps, double y0, double y1) {
  rigid::TriangleSurface s;
  const int n = int(outline.size());
  for (const double y : {y0, y1})
    for (const auto& p : outline) s.vertices.push_back(rigid::Vec3(p[0], y, p[1]));
  double twice_area = 0.0;  // > 0: counter-clockwise in (x, z)
  for (int i = 0; i < n; ++i) {
    const auto &a = outline[i], &b = outline[(i + 1) % n];
    twice_area += a[0] * b[1] - b[0] * a[1];
  }
  // Each triangle turned to face `out`.
  const auto add = [&](std::array<int, 3> t, const rigid::Vec3& out) {
    const rigid::Vec3 normal = (s.vertices[t[1]] - s.vertices[t[0]]).cross(s.vertices[t[2]] - s.vertices[t[0]]);
    if (normal.dot(out) < 0.0) std::swap(t[1], t[2]);
    s.triangles.push_back(t);
  };
  for (const auto& t : caps) {
    add(t, rigid::Vec3(0, -1, 0));
    add({n + t[0], n + t[1], n + t[2]}, rigid::Vec3(0, 1, 0));
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    const double du = outline[j][0] - outline[i][0], dv = outline[j][1] - outline[i][1];
    const rigid::Vec3 out = twice_area > 0 ? rigid::Vec3(dv, 0, -du) : rigid::Vec3(-dv, 0, du);
    add({i, j, n + j}, out);
    add({i, n + j, n + i}, out);
  }
  return s;
}

inline void write_stl_binary(const std::filesystem::path& file, const rigid::TriangleSurface& s) {
  std::ofstream out(file, std::ios::binary);
  const std::string header(80, ' ');
  out.write(header.data(), 80);
  const std::uint32_t count = std::uint32_t(s.triangles.size());
  out.write(reinterpret_cast<const char*>(&count), 4);
  for (const auto& t : s.triangles) {
    const rigid::Vec3 n = rigid::outward_normal(s, t);
    float f[12] = {float(n[0]), float(n[1]), float(n[2])};
    for (int k = 0; k < 3; ++k)
      for (int a = 0; a < 3; ++a) f[3 + 3 * k + a] = float(s.vertices[t[k]][a]);
    out.write(reinterpret_cast<const char*>(f), sizeof f);
    const std::uint16_t attributes = 0;
    out.write(reinterpret_cast<const char*>(&attributes), 2);
  }
}

inline void write_stl_ascii(const std::filesystem::path& file, const rigid::TriangleSurface& s) {
  std::ofstream out(file);
  out.precision(17);
  out << "solid test\n";
  for (const auto& t : s.triangles) {
    const rigid::Vec3 n = rigid::outward_normal(s, t);
    out << " facet normal " << n[0] << ' ' << n[1] << ' ' << n[2] << "\n  outer loop\n";
    for (const int v : t) out << "   vertex " << s.vertices[v][0] << ' ' << s.vertices[v][1] << ' ' << s.vertices[v][2] << '\n';
    out << "  endloop\n endfacet\n";
  }
  out << "endsolid test\n";
}

inline void write_obj(const std::filesystem::path& file, const rigid::TriangleSurface& s) {
  std::ofstream out(file);
  out.precision(17);
  for (const auto& v : s.vertices) out << "v " << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
  for (const auto& t : s.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
}

}  // namespace slide::testing
