#pragma once
// Writers of mesh files for the tests (binary and ASCII STL, OBJ), so that each test makes the file it reads.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "rigid/polyhedron.hpp"

namespace slide::testing {

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
