// Steps: a closed surface as convex pieces (mesh/convex_decomposition.hpp).
#include "mesh/convex_decomposition.hpp"

#include <HACD/hacdHACD.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <stdexcept>

#include "mesh/cgal_kernel.hpp"
#include "mesh/mesh_distance.hpp"

namespace slide::mesh {
namespace {

// The convex hull of `points`, triangulated, outward.
rigid::TriangleSurface hull_of(const std::vector<Point>& points) {
  SurfaceMesh m;
  CGAL::convex_hull_3(points.begin(), points.end(), m);
  rigid::TriangleSurface out;
  for (const auto v : m.vertices()) {
    const Point& p = m.point(v);
    out.vertices.push_back(rigid::Vec3(p.x(), p.y(), p.z()));
  }
  for (const auto f : m.faces()) {
    std::vector<int> corners;
    for (const auto v : CGAL::vertices_around_face(m.halfedge(f), m)) corners.push_back(int(v.idx()));
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) out.triangles.push_back({corners[0], corners[k], corners[k + 1]});
  }
  return out;
}

// HACD's parameters. Its own example's compacity weight (0.1) and no volume weight; its concavity is measured after it
// scales the mesh into a box 1000 across, hence the factor. The faces' and the extra distance points let it see the
// concavity of a coarse mesh: without them it merged an L-shaped prism of 12 triangles into one cluster.
std::vector<std::vector<Point>> hacd_clusters(const rigid::TriangleSurface& s, double concavity) {
  std::vector<HACD::Vec3<HACD::Real>> points;
  for (const auto& v : s.vertices) points.emplace_back(v[0], v[1], v[2]);
  std::vector<HACD::Vec3<long>> triangles;
  for (const auto& t : s.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  rigid::Vec3 lo = s.vertices[0], hi = lo;
  for (const auto& v : s.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  HACD::HACD hacd;
  hacd.SetPoints(points.data());
  hacd.SetNPoints(points.size());
  hacd.SetTriangles(triangles.data());
  hacd.SetNTriangles(triangles.size());
  hacd.SetCompacityWeight(0.1);
  hacd.SetVolumeWeight(0.0);
  hacd.SetNClusters(1);
  hacd.SetNVerticesPerCH(100);
  hacd.SetConcavity(concavity * 1000.0 / (hi - lo).maxCoeff());
  hacd.SetAddExtraDistPoints(true);
  hacd.SetAddNeighboursDistPoints(false);
  hacd.SetAddFacesPoints(true);
  if (!hacd.Compute()) throw std::invalid_argument("the convex decomposition (HACD) failed");
  std::vector<std::vector<Point>> clusters;
  for (std::size_t c = 0; c < hacd.GetNClusters(); ++c) {
    std::vector<HACD::Vec3<HACD::Real>> corners(hacd.GetNPointsCH(c));
    std::vector<HACD::Vec3<long>> faces(hacd.GetNTrianglesCH(c));
    hacd.GetCH(c, corners.data(), faces.data());
    clusters.emplace_back();
    for (const auto& p : corners) clusters.back().emplace_back(p.X(), p.Y(), p.Z());
  }
  return clusters;
}

}  // namespace

ConvexPieces convex_decomposition(const rigid::TriangleSurface& surface, double concavity) {
  ConvexPieces out;
  const MeshDistance whole(surface);
  for (const auto& cluster : hacd_clusters(surface, concavity)) {
    if (cluster.size() < 4) continue;  // a flat sliver holds no volume
    rigid::TriangleSurface piece = hull_of(cluster);
    if (!(rigid::mass_properties(piece).volume > 0.0)) continue;
    for (const auto& v : piece.vertices) out.overreach = std::max(out.overreach, whole.signed_distance(v));
    for (const auto& t : piece.triangles) {
      const rigid::Vec3 centre = (piece.vertices[t[0]] + piece.vertices[t[1]] + piece.vertices[t[2]]) / 3.0;
      out.overreach = std::max(out.overreach, whole.signed_distance(centre));
    }
    out.pieces.push_back(std::move(piece));
  }
  if (out.pieces.empty()) throw std::invalid_argument("the convex decomposition (HACD) gave no piece with a volume");
  return out;
}

}  // namespace slide::mesh
