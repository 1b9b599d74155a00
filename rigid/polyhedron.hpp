#pragma once
// Closed triangle surfaces (a solid body's boundary in 3-D): volume, centre of mass and inertia tensor of the solid they
// enclose, by the divergence theorem over the triangles (each triangle with the origin makes a signed tetrahedron;
// the sums of the tetrahedra's integrals are the solid's: Tonon, "Explicit exact formulas for the 3-D tetrahedron
// inertia tensor in terms of its vertex coordinates", J. Math. Stat. 1 (2005) 8-11). Triangles run counter-clockwise
// seen from outside (normals outward); the solid's volume is then positive.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

namespace slide::rigid {

using Vec3 = Eigen::Matrix<double, 3, 1, Eigen::DontAlign>;
using Mat3 = Eigen::Matrix<double, 3, 3, Eigen::DontAlign>;

struct TriangleSurface {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;  // counter-clockwise seen from outside
};

struct MassProperties {
  double volume = 0.0;            // m^3
  Vec3 centroid = Vec3::Zero();   // m
  Mat3 inertia = Mat3::Zero();    // about the centroid, per unit density (m^5): multiply by the density for kg m^2
};

// For a tetrahedron (0, a, b, c) of signed volume V = a . (b x c) / 6, the integrals over it are
//   int x_i x_j dV = V/20 (sum_k p_k,i p_k,j + (sum_k p_k,i)(sum_k p_k,j)) over its vertices p_k (the origin adds 0),
// and the inertia about the origin I = tr(S) 1 - S with S_ij = int x_i x_j dV. Summed over the surface's triangles,
// then moved to the centroid by the parallel-axis theorem: I_c = I_o - V (|c|^2 1 - c c^T).
// The sums are taken about the vertices' mean rather than the origin: far from the origin they would cancel.
inline MassProperties mass_properties(const TriangleSurface& s) {
  MassProperties m;
  Vec3 origin = Vec3::Zero();
  for (const Vec3& v : s.vertices) origin += v;
  origin /= double(std::max<std::size_t>(1, s.vertices.size()));
  Mat3 second = Mat3::Zero();  // S about the origin
  Vec3 first = Vec3::Zero();   // int x dV
  for (const auto& t : s.triangles) {
    const Vec3 a = s.vertices[t[0]] - origin, b = s.vertices[t[1]] - origin, c = s.vertices[t[2]] - origin;
    const double v = a.dot(b.cross(c)) / 6.0;
    m.volume += v;
    const Vec3 sum = a + b + c;
    first += v * sum / 4.0;
    second += (v / 20.0) * (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose());
  }
  if (!(m.volume > 0.0)) throw std::invalid_argument("a closed surface with no positive volume (inward normals?)");
  m.centroid = first / m.volume;
  const Mat3 about_origin = second.trace() * Mat3::Identity() - second;
  const Vec3& c = m.centroid;
  m.inertia = about_origin - m.volume * (c.squaredNorm() * Mat3::Identity() - c * c.transpose());
  m.centroid += origin;
  return m;
}

inline Vec3 outward_normal(const TriangleSurface& s, const std::array<int, 3>& t) {
  return Vec3((s.vertices[t[1]] - s.vertices[t[0]]).cross(s.vertices[t[2]] - s.vertices[t[0]]).normalized());
}

// A convex surface's vertices moved inwards by `margin`: each vertex by the smallest displacement d with n . d =
// -margin for the outward normal n of every face it touches (exact where three faces meet; the least-squares
// compromise where more do, lengthened where it falls short of the margin behind one of them). Bullet adds its collision margin around a convex hull, so this hull with the margin
// collides at the true surface, its edges rounded. Throws std::invalid_argument where an inset vertex lies less than
// half the margin inside some face (the body is too thin for the margin: under 1.5 margins across). Not the whole
// margin: a vertex near a face it does not touch (a sphere's, near a plane that cuts it) may stand a little closer.
inline std::vector<Vec3> inset_convex(const TriangleSurface& s, double margin) {
  std::vector<std::vector<Vec3>> normals(s.vertices.size());
  for (const auto& t : s.triangles) {
    const Vec3 n = outward_normal(s, t);
    for (const int v : t) {
      bool known = false;
      for (const Vec3& m : normals[v]) known = known || m.dot(n) > 1.0 - 1e-9;
      if (!known) normals[v].push_back(n);
    }
  }
  std::vector<Vec3> out;
  for (std::size_t v = 0; v < s.vertices.size(); ++v) {
    if (normals[v].empty()) continue;
    Eigen::MatrixXd A(normals[v].size(), 3);
    for (std::size_t k = 0; k < normals[v].size(); ++k) A.row(Eigen::Index(k)) = normals[v][k].transpose();
    const Eigen::VectorXd rhs = Eigen::VectorXd::Constant(A.rows(), -margin);
    Vec3 d = A.jacobiSvd(Eigen::ComputeThinU | Eigen::ComputeThinV).solve(rhs);
    // Where the compromise leaves it short of `margin` behind one of its faces, lengthened until it is not.
    double stretch = 1.0;
    for (const Vec3& n : normals[v])
      if (n.dot(d) < 0.0) stretch = std::max(stretch, -margin / n.dot(d));
    out.push_back(s.vertices[v] + stretch * d);
  }
  for (const auto& t : s.triangles) {
    const Vec3 n = outward_normal(s, t);
    for (const Vec3& p : out)
      if (n.dot(p - s.vertices[t[0]]) > -0.5 * margin)
        throw std::invalid_argument("a body too thin for the collision margin");
  }
  return out;
}

// The volume of the solid below the plane z = level: its surface clipped to z <= level, the tetrahedra taken from a
// point on the plane (the cap the plane cuts lies in it and adds nothing), so the sum is exact for any closed surface.
inline double volume_below(const TriangleSurface& s, double level) {
  double v = 0.0;
  const Vec3 o(0.0, 0.0, level);
  for (const auto& t : s.triangles) {
    // Sutherland-Hodgman against the one plane.
    Vec3 kept[4];
    int n = 0;
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = s.vertices[t[k]] - o, b = s.vertices[t[(k + 1) % 3]] - o;
      if (a[2] <= 0.0) kept[n++] = a;
      if ((a[2] < 0.0 && b[2] > 0.0) || (a[2] > 0.0 && b[2] < 0.0)) kept[n++] = a + (a[2] / (a[2] - b[2])) * (b - a);
    }
    for (int k = 1; k + 1 < n; ++k) v += kept[0].dot(kept[k].cross(kept[k + 1])) / 6.0;
  }
  return v;
}

// The point of triangle (a, b, c) nearest to p, by its Voronoi regions (Ericson, Real-Time Collision Detection, 5.1.5).
inline Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + (d1 / (d1 - d3)) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + (d2 / (d2 - d6)) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// Distance from p to the surface (to its nearest triangle), m.
inline double distance_to_surface(const TriangleSurface& s, const Vec3& p) {
  double best = INFINITY;
  for (const auto& t : s.triangles)
    best = std::min(best, (closest_point_on_triangle(p, s.vertices[t[0]], s.vertices[t[1]], s.vertices[t[2]]) - p).norm());
  return best;
}

// Whether a closed, consistently outward surface is convex: at every edge, the far corner of each of its two faces lies
// on or behind the other face's plane (within `tolerance`, m). Convex at every edge and closed without
// self-intersection is convex as a whole.
inline bool is_convex(const TriangleSurface& s, double tolerance) {
  std::map<std::pair<int, int>, std::size_t> face_of;  // directed edge -> the face it runs along
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) face_of[{s.triangles[t][k], s.triangles[t][(k + 1) % 3]}] = t;
  for (std::size_t t = 0; t < s.triangles.size(); ++t) {
    const auto& tri = s.triangles[t];
    const Vec3 n = outward_normal(s, tri);
    for (int k = 0; k < 3; ++k) {
      const auto other = face_of.find({tri[(k + 1) % 3], tri[k]});
      if (other == face_of.end()) continue;
      for (const int v : s.triangles[other->second])
        if (n.dot(s.vertices[v] - s.vertices[tri[0]]) > tolerance) return false;
    }
  }
  return true;
}

// Whether p lies inside (or on) a convex surface: behind every triangle's plane.
inline bool inside_convex(const TriangleSurface& s, const Vec3& p) {
  for (const auto& t : s.triangles)
    if (outward_normal(s, t).dot(p - s.vertices[t[0]]) > 0.0) return false;
  return true;
}

// A box of the given edge lengths centred at `centre`, its edges along the columns of `axes` (a rotation), as twelve
// outward triangles.
inline TriangleSurface box_surface(const Vec3& centre, const Vec3& size, const Mat3& axes = Mat3::Identity()) {
  TriangleSurface s;
  for (int k = 0; k < 8; ++k) {
    const Vec3 corner((k & 1 ? 0.5 : -0.5) * size[0], (k & 2 ? 0.5 : -0.5) * size[1], (k & 4 ? 0.5 : -0.5) * size[2]);
    s.vertices.push_back(centre + axes * corner);
  }
  // Corner k has bit 0 for +x, bit 1 for +y, bit 2 for +z; each face as two triangles, counter-clockwise from outside.
  s.triangles = {{0, 2, 3}, {0, 3, 1},   // -z
                 {4, 5, 7}, {4, 7, 6},   // +z
                 {0, 1, 5}, {0, 5, 4},   // -y
                 {2, 6, 7}, {2, 7, 3},   // +y
                 {0, 4, 6}, {0, 6, 2},   // -x
                 {1, 3, 7}, {1, 7, 5}};  // +x
  return s;
}

// The part of a convex surface on the side n . x <= offset of a plane (n a unit vector), closed by the cap the plane
// cuts: each triangle clipped (Sutherland-Hodgman against the one plane) and fanned, the cap the convex polygon of the
// cut points ordered by angle about their mean, fanned with its normal n. Slivers of no area are dropped. The surface
// unchanged where it lies wholly on the kept side; throws std::invalid_argument where nothing of it is kept.
inline TriangleSurface clip_convex(const TriangleSurface& s, const Vec3& n, double offset) {
  TriangleSurface out;
  std::vector<Vec3> cut;
  // Triangles share their corners (inset_convex moves a corner by all the faces it touches): points within a
  // billionth of the surface's size are one.
  double size = 0.0;
  for (const auto& v : s.vertices) size = std::max(size, (v - s.vertices[0]).norm());
  const double merge = 1e-9 * std::max(size, 1e-300);
  std::map<std::array<long long, 3>, int> index;
  const auto vertex = [&](const Vec3& p) {
    const std::array<long long, 3> key{std::llround(p[0] / merge), std::llround(p[1] / merge), std::llround(p[2] / merge)};
    const auto [it, added] = index.emplace(key, static_cast<int>(out.vertices.size()));
    if (added) out.vertices.push_back(p);
    return it->second;
  };
  const auto add_triangle = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
    if ((b - a).cross(c - a).norm() <= 1e-14 * std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), 1e-300})) return;
    const std::array<int, 3> t{vertex(a), vertex(b), vertex(c)};
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) out.triangles.push_back(t);
  };
  for (const auto& t : s.triangles) {
    Vec3 kept[4];
    int m = 0;
    for (int k = 0; k < 3; ++k) {
      const Vec3& a = s.vertices[t[k]];
      const Vec3& b = s.vertices[t[(k + 1) % 3]];
      // A corner within `merge` of the plane lies on it: no sliver between it and the cut.
      const auto side = [&](const Vec3& p) { const double d = n.dot(p) - offset; return std::abs(d) <= merge ? 0.0 : d; };
      const double da = side(a), db = side(b);
      if (da <= 0.0) kept[m++] = a;
      if (da == 0.0) cut.push_back(a);
      if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) {
        kept[m++] = a + (da / (da - db)) * (b - a);
        cut.push_back(kept[m - 1]);
      }
    }
    for (int k = 1; k + 1 < m; ++k) add_triangle(kept[0], kept[k], kept[k + 1]);
  }
  if (out.triangles.empty()) throw std::invalid_argument("the plane leaves nothing of the surface");
  if (cut.size() < 3) return out;
  Vec3 mean = Vec3::Zero();
  for (const auto& c : cut) mean += c;
  mean /= double(cut.size());
  // In-plane axes u, v with u x v = n, so that counter-clockwise by angle is counter-clockwise seen along n.
  const Vec3 u = (std::abs(n[0]) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(n).normalized(), v = n.cross(u);
  std::vector<std::pair<double, Vec3>> ring;
  for (const auto& c : cut) ring.emplace_back(std::atan2((c - mean).dot(v), (c - mean).dot(u)), c);
  std::sort(ring.begin(), ring.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t k = 0; k < ring.size(); ++k)
    add_triangle(mean, ring[k].second, ring[(k + 1) % ring.size()].second);
  return out;
}

// A sphere as a latitude-longitude surface of `rings` bands (even) and 2 rings meridians, so that it is symmetric
// about the planes through its centre normal to x, y and z (a sphere cut by them keeps its share of the volume
// exactly). Its vertices lie on the sphere of radius radius (V / V_polyhedron)^(1/3), which gives the polyhedron the
// sphere's volume exactly; its inertia is then within 1.2e-3 of 2/5 m R^2 at 48 rings (tests/test_rigid_solid.cpp).
inline TriangleSurface sphere_surface(const Vec3& centre, double radius, int rings = 48) {
  if (rings < 4 || rings % 2) throw std::invalid_argument("a sphere needs an even number of rings, at least 4");
  const int meridians = 2 * rings;
  TriangleSurface s;
  s.vertices.push_back(Vec3(0.0, 0.0, -1.0));
  for (int i = 1; i < rings; ++i) {
    const double theta = M_PI * i / rings;  // from the south pole
    for (int j = 0; j < meridians; ++j) {
      const double phi = 2.0 * M_PI * j / meridians;
      s.vertices.push_back(Vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), -std::cos(theta)));
    }
  }
  s.vertices.push_back(Vec3(0.0, 0.0, 1.0));
  const int north = static_cast<int>(s.vertices.size()) - 1;
  const auto at = [&](int ring, int j) { return 1 + (ring - 1) * meridians + (j % meridians); };
  for (int j = 0; j < meridians; ++j) {
    s.triangles.push_back({0, at(1, j + 1), at(1, j)});
    s.triangles.push_back({north, at(rings - 1, j), at(rings - 1, j + 1)});
    for (int i = 1; i + 1 < rings; ++i) {
      s.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
      s.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
    }
  }
  const double scale = radius * std::cbrt((4.0 / 3.0) * M_PI / mass_properties(s).volume);
  for (auto& v : s.vertices) v = centre + scale * v;
  return s;
}

// A right prism: the convex polygon `outline` (counter-clockwise in the prism's own x-y plane, about its axis) swept
// along its own z over `height`, centred on z = 0, then turned by `axes` and moved to `centre`. Caps as fans from the
// first vertex (hence convex), sides as two triangles an edge, all outward.
inline TriangleSurface prism_surface(const std::vector<std::array<double, 2>>& outline, double height, const Vec3& centre,
                                     const Mat3& axes = Mat3::Identity()) {
  const int n = static_cast<int>(outline.size());
  if (n < 3) throw std::invalid_argument("a prism needs an outline of at least 3 vertices");
  TriangleSurface s;
  for (const double z : {-0.5 * height, 0.5 * height})
    for (const auto& v : outline) s.vertices.push_back(centre + axes * Vec3(v[0], v[1], z));
  const auto bottom = [](int i) { return i; };
  const auto top = [n](int i) { return n + i; };
  for (int i = 1; i + 1 < n; ++i) {
    s.triangles.push_back({bottom(0), bottom(i + 1), bottom(i)});
    s.triangles.push_back({top(0), top(i), top(i + 1)});
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    s.triangles.push_back({bottom(i), bottom(j), top(j)});
    s.triangles.push_back({bottom(i), top(j), top(i)});
  }
  return s;
}

// A circular cylinder of `radius` and `height` about its own z axis (turned by `axes`, centred on `centre`): a prism on
// a regular polygon of `sides`, its circumradius raised so that the polygon's area is pi radius^2 (the volume exact).
inline TriangleSurface cylinder_surface(const Vec3& centre, double radius, double height, const Mat3& axes = Mat3::Identity(),
                                        int sides = 64) {
  if (sides < 3) throw std::invalid_argument("a cylinder needs at least 3 sides");
  const double step = 2.0 * M_PI / sides;
  // A regular polygon of circumradius c has area (sides / 2) c^2 sin(step).
  const double c = radius * std::sqrt(2.0 * M_PI / (sides * std::sin(step)));
  std::vector<std::array<double, 2>> outline;
  for (int k = 0; k < sides; ++k) outline.push_back({c * std::cos(k * step), c * std::sin(k * step)});
  return prism_surface(outline, height, centre, axes);
}

}  // namespace slide::rigid
