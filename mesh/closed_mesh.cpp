// Steps: reading and checking closed triangle meshes (mesh/closed_mesh.hpp), with CGAL.
#include "mesh/closed_mesh.hpp"

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <fmt/format.h>

#include <map>
#include <utility>

#include "mesh/cgal_kernel.hpp"

namespace slide::mesh {
namespace {


std::string corner_text(const rigid::Vec3& p) { return fmt::format("({:.6g}, {:.6g}, {:.6g})", p[0], p[1], p[2]); }

// A body is one closed surface: its faces joined through their shared edges (union-find) form one piece.
void check_one_piece(const rigid::TriangleSurface& s) {
  std::vector<std::size_t> parent(s.triangles.size());
  for (std::size_t t = 0; t < parent.size(); ++t) parent[t] = t;
  const auto root = [&parent](std::size_t t) {
    while (parent[t] != t) t = parent[t] = parent[parent[t]];
    return t;
  };
  std::map<std::pair<int, int>, std::size_t> face_of;  // undirected edge (smaller corner first) -> a face on it
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = s.triangles[t][k], b = s.triangles[t][(k + 1) % 3];
      const auto [it, added] = face_of.emplace(std::pair{std::min(a, b), std::max(a, b)}, t);
      if (!added) parent[root(t)] = root(it->second);
    }
  std::size_t pieces = 0;
  for (std::size_t t = 0; t < parent.size(); ++t) pieces += root(t) == t;
  if (pieces > 1)
    throw MeshError(fmt::format("it is {} separate closed surfaces: a body's mesh must be one", pieces));
}

// Every edge must border exactly two faces, once in each direction (a closed surface whose faces agree on their
// orientation); the first that does not is named by its corners.
void check_edges(const rigid::TriangleSurface& s) {
  std::map<std::pair<int, int>, int> directed;
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const auto& tri = s.triangles[t];
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
      throw MeshError(fmt::format("face {} has two equal corners (it has no area)", t));
    for (int k = 0; k < 3; ++k) ++directed[{tri[k], tri[(k + 1) % 3]}];
  }
  const auto edge_text = [&](int a, int b) {
    return fmt::format("the edge from {} to {}", corner_text(s.vertices[a]), corner_text(s.vertices[b]));
  };
  for (const auto& [edge, count] : directed) {
    const auto back = directed.find({edge.second, edge.first});
    const int faces = count + (back == directed.end() ? 0 : back->second);
    if (faces == 1) throw MeshError(fmt::format("it is not closed: {} borders one face only (a hole)", edge_text(edge.first, edge.second)));
    if (faces > 2)
      throw MeshError(fmt::format("it is not a manifold: {} borders {} faces", edge_text(edge.first, edge.second), faces));
    if (count != 1)
      throw MeshError(fmt::format("its faces are not consistently oriented: the two faces at {} run along it the same "
                                  "way (one of them is flipped)", edge_text(edge.first, edge.second)));
  }
}

// The signed volume the faces enclose (positive when they point outward), about the corners' mean.
double enclosed_volume(const rigid::TriangleSurface& s) {
  rigid::Vec3 origin = rigid::Vec3::Zero();
  for (const auto& v : s.vertices) origin += v;
  origin /= double(s.vertices.size());
  double volume = 0.0;
  for (const auto& t : s.triangles) {
    const rigid::Vec3 a = s.vertices[t[0]] - origin, b = s.vertices[t[1]] - origin, c = s.vertices[t[2]] - origin;
    volume += a.dot(b.cross(c)) / 6.0;
  }
  return volume;
}

SurfaceMesh to_cgal(const rigid::TriangleSurface& s) {
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  to_soup(s, points, faces);
  if (!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(faces))
    throw MeshError("it is not a manifold: separate sheets of it meet at a corner");
  SurfaceMesh m;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, m);
  return m;
}

}  // namespace

void check_closed_mesh(const rigid::TriangleSurface& s) {
  if (s.triangles.empty()) throw MeshError("it has no faces");
  for (const auto& t : s.triangles)
    for (const int v : t)
      if (v < 0 || std::size_t(v) >= s.vertices.size()) throw MeshError("a face names a corner that is not there");
  check_edges(s);
  double size = 0.0;
  for (const auto& v : s.vertices) size = std::max(size, (v - s.vertices[0]).norm());
  const double volume = enclosed_volume(s);
  if (!(std::abs(volume) > 1e-12 * size * size * size))
    throw MeshError("it encloses no volume (its faces lie in one plane or fold onto each other)");
  if (volume < 0.0)
    throw MeshError(fmt::format("its faces point inward (they enclose {:.6g} m^3 turned inside out): flip them",
                                -volume));
  const SurfaceMesh m = to_cgal(s);
  if (CGAL::Polygon_mesh_processing::does_self_intersect(m)) throw MeshError("it intersects itself (two of its faces cut each other)");
  check_one_piece(s);
}

rigid::TriangleSurface read_closed_mesh(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) throw MeshError("no such file");
  std::string ext = file.extension().string();
  for (auto& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".stl" && ext != ".obj") throw MeshError("a mesh file must be .stl (binary or ASCII) or .obj");
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> faces;
  bool read = false;
  try {
    read = CGAL::IO::read_polygon_soup(file.string(), points, faces);
  } catch (const std::exception& e) {
    throw MeshError(fmt::format("it could not be read as {}: {}", ext.substr(1), e.what()));
  }
  if (!read || faces.empty()) throw MeshError(fmt::format("it could not be read as {} (or holds no faces)", ext.substr(1)));
  rigid::TriangleSurface s;
  for (const auto& p : points) s.vertices.push_back(rigid::Vec3(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
  // A polygon of more than three corners (OBJ allows them) as a fan from its first corner: exact for a flat convex
  // one; any other shows up as a self-intersection or a fold below.
  for (const auto& f : faces) {
    if (f.size() < 3) throw MeshError("a face has fewer than three corners");
    for (std::size_t k = 1; k + 1 < f.size(); ++k) s.triangles.push_back({int(f[0]), int(f[k]), int(f[k + 1])});
  }
  check_closed_mesh(s);
  return s;
}

}  // namespace slide::mesh
