// Closed meshes from files (mesh/closed_mesh.hpp), their signed distance (mesh/mesh_distance.hpp) and even points on
// surfaces (mesh/even_surface_samples.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mesh/closed_mesh.hpp"
#include "mesh/convex_inset.hpp"
#include "mesh/even_surface_samples.hpp"
#include "mesh/mesh_distance.hpp"
#include "rigid/polyhedron.hpp"
#include "tests/cli_helpers.hpp"
#include "tests/mesh_files.hpp"

namespace slide {
namespace {

using rigid::Vec3;

// The defect check_closed_mesh names for `s`, or "" for none.
std::string defect_of(const rigid::TriangleSurface& s) {
  try {
    mesh::check_closed_mesh(s);
  } catch (const mesh::MeshError& e) {
    return e.what();
  }
  return "";
}

TEST(ClosedMesh, ReadsTheSameCubeFromBinaryAsciiStlAndObj) {
  const auto dir = testing::fresh_directory("closed_mesh");
  const rigid::TriangleSurface cube = rigid::box_surface(Vec3(0.5, 0.25, 2.0), Vec3(1.0, 0.5, 2.0));
  testing::write_stl_binary(dir / "cube_binary.stl", cube);
  testing::write_stl_ascii(dir / "cube_ascii.STL", cube);
  testing::write_obj(dir / "cube.obj", cube);
  // A quad face in OBJ comes as two triangles.
  testing::write_file(dir / "quads.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                         "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  for (const char* name : {"cube_binary.stl", "cube_ascii.STL", "cube.obj"}) {
    const rigid::TriangleSurface s = mesh::read_closed_mesh(dir / name);
    EXPECT_EQ(s.vertices.size(), 8u) << name;  // an STL's repeated corners merged
    EXPECT_EQ(s.triangles.size(), 12u) << name;
    const rigid::MassProperties m = rigid::mass_properties(s);
    EXPECT_NEAR(m.volume, 1.0, 1e-12) << name;
    EXPECT_NEAR((m.centroid - Vec3(0.5, 0.25, 2.0)).norm(), 0.0, 1e-12) << name;
  }
  const rigid::TriangleSurface q = mesh::read_closed_mesh(dir / "quads.obj");
  EXPECT_EQ(q.triangles.size(), 12u);
  EXPECT_NEAR(rigid::mass_properties(q).volume, 1.0, 1e-15);
}

TEST(ClosedMesh, RefusesEachDefectByName) {
  const rigid::TriangleSurface cube = rigid::box_surface(Vec3::Zero(), Vec3::Ones());
  EXPECT_EQ(defect_of(cube), "");
  rigid::TriangleSurface hole = cube;
  hole.triangles.pop_back();
  EXPECT_NE(defect_of(hole).find("not closed"), std::string::npos) << defect_of(hole);
  rigid::TriangleSurface flipped = cube;
  std::swap(flipped.triangles[3][1], flipped.triangles[3][2]);
  EXPECT_NE(defect_of(flipped).find("not consistently oriented"), std::string::npos) << defect_of(flipped);
  rigid::TriangleSurface inward = cube;
  for (auto& t : inward.triangles) std::swap(t[1], t[2]);
  EXPECT_NE(defect_of(inward).find("point inward"), std::string::npos) << defect_of(inward);
  rigid::TriangleSurface flat;  // two triangles back to back: closed, no volume
  flat.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  flat.triangles = {{0, 1, 2}, {0, 2, 1}};
  EXPECT_NE(defect_of(flat).find("no volume"), std::string::npos) << defect_of(flat);
  // Two cubes overlapping by half, written as one surface: closed and outward, but its faces cut each other.
  rigid::TriangleSurface two = cube;
  const rigid::TriangleSurface other = rigid::box_surface(Vec3(0.5, 0.5, 0.5), Vec3::Ones());
  for (const auto& v : other.vertices) two.vertices.push_back(v);
  for (const auto& t : other.triangles) two.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
  EXPECT_NE(defect_of(two).find("intersects itself"), std::string::npos) << defect_of(two);
  // Two cubes sharing one corner: every edge is fine, the corner is not a manifold's.
  rigid::TriangleSurface touching = cube;
  const rigid::TriangleSurface beyond = rigid::box_surface(Vec3::Ones(), Vec3::Ones());
  for (int k = 0; k < 8; ++k) touching.vertices.push_back(beyond.vertices[k]);
  for (const auto& t : beyond.triangles) {
    std::array<int, 3> u{};
    for (int k = 0; k < 3; ++k) u[k] = t[k] == 0 ? 7 : t[k] + 8;  // its corner 0 is the first cube's corner 7
    touching.triangles.push_back(u);
  }
  EXPECT_NE(defect_of(touching).find("not a manifold"), std::string::npos) << defect_of(touching);
  // Two cubes apart: each closed, together not one body.
  rigid::TriangleSurface apart = cube;
  const rigid::TriangleSurface far = rigid::box_surface(Vec3(3.0, 0.0, 0.0), Vec3::Ones());
  for (const auto& v : far.vertices) apart.vertices.push_back(v);
  for (const auto& t : far.triangles) apart.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
  EXPECT_NE(defect_of(apart).find("2 separate closed surfaces"), std::string::npos) << defect_of(apart);
}

TEST(ClosedMesh, RefusesFilesItCannotRead) {
  const auto dir = testing::fresh_directory("closed_mesh_bad");
  const auto what = [](const std::filesystem::path& p) {
    try {
      mesh::read_closed_mesh(p);
    } catch (const mesh::MeshError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(what(dir / "missing.stl"), "no such file");
  testing::write_file(dir / "cube.ply", "ply\n");
  EXPECT_NE(what(dir / "cube.ply").find(".stl"), std::string::npos);
  testing::write_file(dir / "garbage.obj", "this is not a mesh\n");
  EXPECT_NE(what(dir / "garbage.obj").find("could not be read"), std::string::npos) << what(dir / "garbage.obj");
  testing::write_file(dir / "open.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_NE(what(dir / "open.obj").find("not closed"), std::string::npos) << what(dir / "open.obj");
}

// The exact signed distance to a box, as a check on the mesh's.
double box_distance(const Vec3& p, const Vec3& half) {
  const Vec3 q = p.cwiseAbs() - half;
  return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

TEST(MeshDistance, IsTheBoxsExactSignedDistance) {
  const Vec3 size(1.0, 0.6, 0.4);
  const mesh::MeshDistance d(rigid::box_surface(Vec3::Zero(), size));
  long inside = 0;
  for (int i = -7; i <= 7; ++i)
    for (int j = -7; j <= 7; ++j)
      for (int k = -7; k <= 7; ++k) {
        const Vec3 p(0.1031 * i, 0.0577 * j, 0.0413 * k);
        const double exact = box_distance(p, 0.5 * size);
        ASSERT_NEAR(d.signed_distance(p), exact, 1e-12) << p.transpose();
        inside += exact < 0.0;
        if (exact > 0.0) {
          ASSERT_NEAR((d.nearest_point(p) - p).norm(), exact, 1e-12);
        }
      }
  EXPECT_GT(inside, 100);
  EXPECT_EQ(d.signed_distance(Vec3(0.5, 0.0, 0.0)), 0.0);  // on a face
}

// On a sphere of radius 1 and spacing 0.1: the number of points is its area over the spacing squared, each lies on
// its triangle, and no two are close. Measured (8 candidates a point): nearest neighbours at least 0.630 and on
// average 0.746 of a hexagonal packing's spacing (16 candidates a point: 0.617 and 0.749); the bounds keep that.
TEST(EvenSurfaceSamples, SpreadOnePointPerSpacingSquaredEvenly) {
  const rigid::TriangleSurface sphere = rigid::sphere_surface(Vec3::Zero(), 1.0, 64);
  double area = 0.0;
  for (const auto& t : sphere.triangles)
    area += 0.5 * (sphere.vertices[t[1]] - sphere.vertices[t[0]]).cross(sphere.vertices[t[2]] - sphere.vertices[t[0]]).norm();
  const double s = 0.1;
  const auto p = mesh::even_surface_samples(sphere, s);
  ASSERT_EQ(long(p.size()), std::lround(area / (s * s)));
  double least = INFINITY, mean = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    ASSERT_LT(rigid::distance_to_surface(sphere, p[i].point), 1e-12);
    const auto& t = sphere.triangles[std::size_t(p[i].triangle)];
    ASSERT_NEAR(rigid::outward_normal(sphere, t).dot(p[i].point - sphere.vertices[t[0]]), 0.0, 1e-12);
    double nearest = INFINITY;
    for (std::size_t j = 0; j < p.size(); ++j)
      if (j != i) nearest = std::min(nearest, (p[j].point - p[i].point).norm());
    least = std::min(least, nearest);
    mean += nearest / double(p.size());
  }
  const double hexagonal = std::sqrt(2.0 / std::sqrt(3.0)) * s;  // one point per s^2 in a hexagonal packing
  RecordProperty("least_over_hexagonal", std::to_string(least / hexagonal));
  RecordProperty("mean_over_hexagonal", std::to_string(mean / hexagonal));
  std::printf("nearest neighbour: least %.3f, mean %.3f of the hexagonal spacing\n", least / hexagonal, mean / hexagonal);
  EXPECT_GT(least, 0.6 * hexagonal);
  EXPECT_GT(mean, 0.72 * hexagonal);
  EXPECT_EQ(mesh::even_surface_samples(sphere, s), p);  // the same points every time
}

// The shipped Enet & Grilli slide (cases/meshes/make_enet_grilli_slide.py): closed, convex, 0.395 m x 0.680 m x 0.082 m,
// its volume that of the Gaussian formula (7.726e-3 m^3) less what its facets cut off the curved dome.
TEST(ClosedMesh, ShippedEnetGrilliSlideIsTheirGaussianSlide) {
  const rigid::TriangleSurface s =
      mesh::read_closed_mesh(std::filesystem::path(SLIDE_SOURCE_DIR) / "cases/meshes/enet_grilli_slide.stl");
  EXPECT_TRUE(rigid::is_convex(s, 1e-9));
  Vec3 lo = s.vertices[0], hi = s.vertices[0];
  for (const auto& v : s.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  EXPECT_NEAR(hi[0] - lo[0], 0.395, 1e-6);
  EXPECT_NEAR(hi[1] - lo[1], 0.680, 1e-6);
  EXPECT_NEAR(hi[2], 0.082, 1e-6);
  EXPECT_EQ(lo[2], 0.0);
  const double volume = rigid::mass_properties(s).volume;
  EXPECT_LT(volume, 7.726e-3);
  EXPECT_GT(volume, 7.726e-3 * 0.998);
}

// The exact inset of a box is the box less the margin all round; the shipped slide's, at the margins of dp 0.02 to 0.04
// (its thin rim closes), lies inside it by the margin: every corner at least the margin from the slide's surface.
TEST(ConvexInset, IsTheShapeMovedInByTheMargin) {
  const rigid::TriangleSurface box = rigid::box_surface(Vec3(0.1, 0.2, 0.3), Vec3(0.4, 0.3, 0.2));
  const rigid::TriangleSurface in = mesh::convex_inset(box, 0.01);
  EXPECT_NEAR(rigid::mass_properties(in).volume, 0.38 * 0.28 * 0.18, 1e-12);
  for (const auto& v : in.vertices) EXPECT_NEAR(rigid::distance_to_surface(box, v), 0.01, 1e-12);
  EXPECT_THROW(mesh::convex_inset(box, 0.1), std::invalid_argument);  // the box is 0.2 thick
  const rigid::TriangleSurface slide =
      mesh::read_closed_mesh(std::filesystem::path(SLIDE_SOURCE_DIR) / "cases/meshes/enet_grilli_slide.stl");
  for (const double margin : {0.002, 0.003, 0.004}) {
    const rigid::TriangleSurface inset = mesh::convex_inset(slide, margin);
    for (const auto& v : inset.vertices) {
      ASSERT_TRUE(rigid::inside_convex(slide, v));
      ASSERT_GT(rigid::distance_to_surface(slide, v), margin * (1.0 - 1e-6));
    }
    EXPECT_LT(rigid::mass_properties(inset).volume, rigid::mass_properties(slide).volume);
  }
}

}  // namespace
}  // namespace slide
