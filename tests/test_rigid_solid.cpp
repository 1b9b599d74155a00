// rigid/: solid bodies in six degrees of freedom (3-D scenes) and closed surfaces' mass properties, against closed
// forms.
#include <gtest/gtest.h>

#include <cmath>

#include "mesh/convex_decomposition.hpp"
#include "rigid/polyhedron.hpp"
#include "rigid/rigid_world.hpp"
#include "tests/mesh_files.hpp"
#include "tests/solid_box.hpp"

namespace slide::rigid {
namespace {

Mat3 rotation_about(const Vec3& axis, double angle) {
  return Mat3(Eigen::AngleAxisd(angle, Eigen::Vector3d(axis).normalized()).toRotationMatrix());
}

SolidSpec box_solid(const Vec3& centre, const Vec3& size, double density, const Mat3& axes = Mat3::Identity()) {
  return testing::solid_box(centre, size, density, axes);
}

TEST(SolidBody, BoxMassPropertiesMatchClosedForms) {
  const Vec3 size(0.4, 0.2, 0.1);
  const MassProperties m = mass_properties(box_surface(Vec3(1.0, -2.0, 0.5), size));
  EXPECT_NEAR(m.volume, 0.008, 1e-16);
  EXPECT_NEAR((m.centroid - Vec3(1.0, -2.0, 0.5)).norm(), 0.0, 1e-14);
  // I_xx = V (b^2 + c^2) / 12, and so on; no products of inertia along the box's axes.
  // (to rounding: 1e-12 of the largest moment, 1.3e-4 m^5)
  EXPECT_NEAR(m.inertia(0, 0), 0.008 * (0.04 + 0.01) / 12.0, 1e-16);
  EXPECT_NEAR(m.inertia(1, 1), 0.008 * (0.16 + 0.01) / 12.0, 1e-16);
  EXPECT_NEAR(m.inertia(2, 2), 0.008 * (0.16 + 0.04) / 12.0, 1e-16);
  EXPECT_NEAR(m.inertia(0, 1), 0.0, 1e-16);
  EXPECT_NEAR(m.inertia(1, 2), 0.0, 1e-16);
  // Turned, the tensor turns with it: R I R^T.
  const Mat3 R = rotation_about(Vec3(1.0, 2.0, 3.0), 0.7);
  const MassProperties turned = mass_properties(box_surface(Vec3::Zero(), size, R));
  EXPECT_NEAR((turned.inertia - R * m.inertia * R.transpose()).norm(), 0.0, 1e-16);
  EXPECT_NEAR(turned.volume, 0.008, 1e-16);
}

// The tetrahedron (0, e_x, e_y, e_z): V = 1/6, centroid (1/4, 1/4, 1/4); int x^2 dV = 1/60, int x y dV = 1/120, so
// about the centroid I_xx = 1/30 - V (1/16 + 1/16) = 1/80 and I_xy = -1/120 + V / 16 = 1/480.
TEST(SolidBody, TetrahedronMassPropertiesMatchClosedForms) {
  TriangleSurface t;
  t.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  t.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  const MassProperties m = mass_properties(t);
  EXPECT_NEAR(m.volume, 1.0 / 6.0, 1e-15);
  EXPECT_NEAR((m.centroid - Vec3(0.25, 0.25, 0.25)).norm(), 0.0, 1e-15);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(m.inertia(i, i), 1.0 / 80.0, 1e-15);
    EXPECT_NEAR(m.inertia(i, (i + 1) % 3), 1.0 / 480.0, 1e-15);
  }
  // Inward triangles are refused.
  for (auto& tri : t.triangles) std::swap(tri[1], tri[2]);
  EXPECT_THROW(mass_properties(t), std::invalid_argument);
}

TEST(SolidBody, VolumeBelowALevelMatchesClosedForms) {
  const TriangleSurface box = box_surface(Vec3(0.3, 0.2, 1.0), Vec3(0.2, 0.1, 0.4));
  EXPECT_NEAR(volume_below(box, 0.5), 0.0, 1e-18);
  EXPECT_NEAR(volume_below(box, 0.9), 0.2 * 0.1 * 0.1, 1e-15);
  EXPECT_NEAR(volume_below(box, 1.0), 0.2 * 0.1 * 0.2, 1e-15);
  EXPECT_NEAR(volume_below(box, 2.0), 0.2 * 0.1 * 0.4, 1e-15);
  // A cube on its edge (turned 45 degrees about x), edge 1, centre at 0: below z = 0 half of it; below z = -h with
  // h < sqrt(2)/2 a prism of triangular section (sqrt(2)/2 - h)^2.
  const TriangleSurface edge = box_surface(Vec3::Zero(), Vec3(1.0, 1.0, 1.0), rotation_about(Vec3(1, 0, 0), M_PI / 4));
  EXPECT_NEAR(volume_below(edge, 0.0), 0.5, 1e-14);
  const double h = 0.3, w = std::sqrt(0.5) - h;
  EXPECT_NEAR(volume_below(edge, -h), w * w, 1e-14);
}

// A box cut by a plane through it, closed by its cap: the half boxes' volumes and centroids, exactly; cut by a tilted
// plane through its centre, half the volume about the centre's mirror; wholly on the kept side, unchanged.
TEST(SolidBody, ClippedBoxIsClosedByItsCap) {
  const TriangleSurface box = box_surface(Vec3(1.0, 2.0, 3.0), Vec3(0.4, 0.2, 0.1));
  const MassProperties lower = mass_properties(clip_convex(box, Vec3(1, 0, 0), 0.9));  // keeps x <= 0.9
  EXPECT_NEAR(lower.volume, 0.1 * 0.2 * 0.1, 1e-15);
  EXPECT_NEAR((lower.centroid - Vec3(0.85, 2.0, 3.0)).norm(), 0.0, 1e-14);
  // Its inertia about its own centroid: a box 0.1 x 0.2 x 0.1.
  EXPECT_NEAR(lower.inertia(0, 0), 0.002 * (0.04 + 0.01) / 12.0, 1e-17);
  EXPECT_NEAR(lower.inertia(1, 1), 0.002 * (0.01 + 0.01) / 12.0, 1e-17);
  const Vec3 n = Vec3(1.0, -2.0, 0.5).normalized();
  const MassProperties half = mass_properties(clip_convex(box, n, n.dot(Vec3(1.0, 2.0, 3.0))));
  const MassProperties other = mass_properties(clip_convex(box, -n, -n.dot(Vec3(1.0, 2.0, 3.0))));
  EXPECT_NEAR(half.volume, 0.004, 1e-15);
  EXPECT_NEAR(other.volume, 0.004, 1e-15);
  EXPECT_NEAR((half.centroid + other.centroid - 2.0 * Vec3(1.0, 2.0, 3.0)).norm(), 0.0, 1e-14);
  EXPECT_LT(n.dot(half.centroid - Vec3(1.0, 2.0, 3.0)), 0.0);
  EXPECT_NEAR(mass_properties(clip_convex(box, Vec3(0, 0, 1), 10.0)).volume, 0.008, 1e-15);
  EXPECT_THROW(clip_convex(box, Vec3(0, 0, 1), 0.0), std::invalid_argument);
}

// The sphere's surface holds its volume exactly; its inertia is that of a solid sphere, 2/5 V R^2 per unit density,
// within 1.2e-3. Cut through its centre it keeps exactly a half and a quarter of it. The hemisphere's centroid lies
// 3R/8 from the cut, and the quarter ball's 3R/8 from each cut plane (int x dV over it = pi R^4 / 16, over its
// volume pi R^3 / 3), within 1e-3 R.
TEST(SolidBody, SphereAndItsHalvesMatchClosedForms) {
  const double R = 0.15, V = 4.0 / 3.0 * M_PI * R * R * R;
  const Vec3 c(0.3, -0.2, 0.9);
  const TriangleSurface sphere = sphere_surface(c, R);
  const MassProperties m = mass_properties(sphere);
  EXPECT_NEAR(m.volume, V, 1e-12 * V);  // rounding over 9,000 triangles
  EXPECT_NEAR((m.centroid - c).norm(), 0.0, 1e-14);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(m.inertia(i, i), 0.4 * V * R * R, 1.2e-3 * 0.4 * V * R * R) << i;
  EXPECT_NEAR(m.inertia(0, 1), 0.0, 1e-12 * V * R * R);
  const MassProperties upper = mass_properties(clip_convex(sphere, Vec3(0, 0, -1), -c[2]));  // z >= c_z
  EXPECT_NEAR(upper.volume, V / 2.0, 1e-12 * V);
  EXPECT_NEAR((upper.centroid - (c + Vec3(0.0, 0.0, 3.0 * R / 8.0))).norm(), 0.0, 1e-3 * R);
  const MassProperties quarter =
      mass_properties(clip_convex(clip_convex(sphere, Vec3(-1, 0, 0), -c[0]), Vec3(0, -1, 0), -c[1]));
  EXPECT_NEAR(quarter.volume, V / 4.0, 1e-12 * V);
  EXPECT_NEAR((quarter.centroid - (c + Vec3(3.0 * R / 8.0, 3.0 * R / 8.0, 0.0))).norm(), 0.0, 1e-3 * R);
  // About the vertical axis through the centre, a quarter ball has a quarter of the ball's moment.
  const double about_axis = quarter.inertia(2, 2) + quarter.volume * (std::pow(quarter.centroid[0] - c[0], 2) +
                                                                      std::pow(quarter.centroid[1] - c[1], 2));
  EXPECT_NEAR(about_axis, 0.1 * V * R * R, 1.2e-3 * 0.1 * V * R * R);
  EXPECT_THROW(sphere_surface(c, R, 7), std::invalid_argument);
}

// A prism on a triangle (the Heinrich wedge's kind): volume, centroid and the moment about its axis exactly; a
// cylinder, on its 64-sided prism of the same area: volume exactly, moments within the polygon's 1e-3.
TEST(SolidBody, PrismAndCylinderMatchClosedForms) {
  const double b = 0.4, h = 0.3, L = 0.2;  // a right triangle of legs b (x) and h (y), swept over L
  const Vec3 c(1.0, 2.0, 3.0);
  const MassProperties prism = mass_properties(prism_surface({{0.0, 0.0}, {b, 0.0}, {0.0, h}}, L, c));
  EXPECT_NEAR(prism.volume, 0.5 * b * h * L, 1e-14);
  EXPECT_NEAR((prism.centroid - (c + Vec3(b / 3.0, h / 3.0, 0.0))).norm(), 0.0, 1e-14);
  // About the axis through the centroid along z: the triangle's polar moment (b h / 36)(b^2 + h^2) times L.
  EXPECT_NEAR(prism.inertia(2, 2), b * h / 36.0 * (b * b + h * h) * L, 1e-14);
  EXPECT_THROW(prism_surface({{0.0, 0.0}, {1.0, 0.0}}, 1.0, c), std::invalid_argument);

  const double R = 0.1, H = 0.25, V = M_PI * R * R * H;
  const Mat3 axes(Eigen::AngleAxisd(0.5 * M_PI, Vec3::UnitX()));  // lying: its axis along -y
  const MassProperties cyl = mass_properties(cylinder_surface(c, R, H, axes));
  EXPECT_NEAR(cyl.volume, V, 1e-12 * V);
  EXPECT_NEAR((cyl.centroid - c).norm(), 0.0, 1e-14);
  const double about_axis = 0.5 * V * R * R, across = V * (3.0 * R * R + H * H) / 12.0;
  EXPECT_NEAR(cyl.inertia(1, 1), about_axis, 1e-3 * about_axis);
  EXPECT_NEAR(cyl.inertia(0, 0), across, 1e-3 * across);
  EXPECT_NEAR(cyl.inertia(2, 2), across, 1e-3 * across);
}

TEST(SolidBody, FreeFlightKeepsVelocityAndSpinAboutAPrincipalAxis) {
  RigidWorld w(Vec3(0.0, 0.0, 0.0), 1e-3);
  const int b = w.add_solid(box_solid(Vec3(0.1, 0.2, 0.3), Vec3(0.2, 0.1, 0.05), 800.0));
  w.set_velocity(b, Vec3(1.5, -0.5, 0.25), Vec3(0.0, 0.0, 2.0));
  const double dt = 1e-3;
  const int steps = 1000;
  for (int k = 0; k < steps; ++k) w.step(dt);
  const SpatialState s = w.spatial_state(b);
  const double t = steps * dt;
  EXPECT_NEAR((s.position - (Vec3(0.1, 0.2, 0.3) + t * Vec3(1.5, -0.5, 0.25))).norm(), 0.0, 1e-9);
  EXPECT_NEAR((s.velocity - Vec3(1.5, -0.5, 0.25)).norm(), 0.0, 1e-12);
  const Eigen::AngleAxisd turned{Eigen::Quaterniond(s.orientation)};
  EXPECT_NEAR(turned.angle(), 2.0 * t, 1e-9);
  EXPECT_NEAR(std::abs(turned.axis()[2]), 1.0, 1e-9);
}

// Torque-free motion about a non-principal axis: the angular momentum R I_0 R^T omega is conserved in world axes
// (Bullet's implicit gyroscopic term), and the kinetic energy with it to the integrator's accuracy.
TEST(SolidBody, TorqueFreeTumblingConservesAngularMomentum) {
  RigidWorld w(Vec3(0.0, 0.0, 0.0), 1e-3);
  const SolidSpec spec = box_solid(Vec3::Zero(), Vec3(0.3, 0.2, 0.1), 1000.0);
  const int b = w.add_solid(spec);
  const Vec3 omega0(0.5, 3.0, 0.2);  // near the intermediate axis: it tumbles
  w.set_velocity(b, Vec3::Zero(), omega0);
  const Vec3 L0 = spec.inertia * omega0;
  const double E0 = 0.5 * omega0.dot(spec.inertia * omega0);
  double worst_L = 0.0, worst_E = 0.0;
  for (int k = 0; k < 4000; ++k) {
    w.step(1e-4);
    const SpatialState s = w.spatial_state(b);
    const Mat3 R = Eigen::Quaterniond(s.orientation).toRotationMatrix();
    const Mat3 I = R * spec.inertia * R.transpose();
    worst_L = std::max(worst_L, (I * s.angular_velocity - L0).norm() / L0.norm());
    worst_E = std::max(worst_E, std::abs(0.5 * s.angular_velocity.dot(I * s.angular_velocity) - E0) / E0);
  }
  EXPECT_LT(worst_L, 2e-3);
  EXPECT_LT(worst_E, 2e-3);
}

TEST(SolidBody, AppliedForceAndTorqueGiveTheirAccelerations) {
  RigidWorld w(Vec3(0.0, 0.0, -9.81), 1e-3);
  const SolidSpec spec = box_solid(Vec3::Zero(), Vec3(0.2, 0.2, 0.2), 500.0);  // m = 4 kg, I = m a^2 / 6
  const int b = w.add_solid(spec);
  const double dt = 1e-3, I = spec.mass * 0.04 / 6.0;
  const Vec3 force(2.0, 0.0, spec.mass * 9.81 + 1.0), torque(0.0, 0.0, 0.3);
  for (int k = 0; k < 500; ++k) {
    w.apply_force(b, force, torque);
    w.step(dt);
  }
  const SpatialState s = w.spatial_state(b);
  const double t = 500 * dt;
  EXPECT_NEAR(s.velocity[0], 2.0 / spec.mass * t, 1e-12);
  EXPECT_NEAR(s.velocity[2], 1.0 / spec.mass * t, 1e-11);
  EXPECT_NEAR(s.angular_velocity[2], 0.3 / I * t, 1e-10);
  // No contact: what Bullet did beyond gravity and the applied force is nothing.
  EXPECT_NEAR(w.contact_force_3d(b).norm(), 0.0, 1e-9);
}

TEST(SolidBody, BoxSettlesOnTheFloorAndTheContactHoldsItsWeight) {
  RigidWorld w(Vec3(0.0, 0.0, -9.81), 1e-3);
  w.add_static_box(Vec3(-1.0, -1.0, -0.1), Vec3(1.0, 1.0, 0.0), 1.0, 0.0);
  SolidSpec spec = box_solid(Vec3(0.0, 0.0, 0.06), Vec3(0.2, 0.1, 0.1), 500.0);
  spec.friction = 0.5;
  const int b = w.add_solid(spec);
  for (int k = 0; k < 1000; ++k) w.step(1e-3);
  const SpatialState s = w.spatial_state(b);
  EXPECT_NEAR(s.position[2], 0.05, 2e-4);  // on the floor, within a fifth of the margin's scale
  EXPECT_LT(s.velocity.norm(), 1e-3);
  EXPECT_NEAR(w.contact_force_3d(b)[2], spec.mass * 9.81, 1e-3 * spec.mass * 9.81);
}

// A box on a static triangle mesh (a terrain: a 30 degree plane as a grid of 4 x 3 cells, 24 triangles) slides down it
// at g (sin - mu cos) with Coulomb friction mu = 0.2 (the mesh's friction 1, so the pair's is the body's), and one on
// a plane less steep than atan(mu) stays.
TEST(SolidBody, BoxSlidesDownATriangleMeshSlopeWithCoulombFriction) {
  for (const double degrees : {30.0, 8.0}) {
    const double theta = degrees * M_PI / 180.0, mu = 0.2, g = 9.81;
    RigidWorld w(Vec3(0.0, 0.0, -g), 1e-3);
    TriangleSurface terrain;
    for (int j = 0; j <= 3; ++j)
      for (int i = 0; i <= 4; ++i) terrain.vertices.push_back(Vec3(-1.0 + 0.5 * i, -0.75 + 0.5 * j, -std::tan(theta) * (-1.0 + 0.5 * i)));
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) {
        const int a = j * 5 + i;
        terrain.triangles.push_back({a, a + 1, a + 6});
        terrain.triangles.push_back({a, a + 6, a + 5});
      }
    w.add_static_mesh(terrain, 1.0, 0.0);
    // The box resting on the plane at x = 0 (its base centre there), turned with it.
    const Mat3 R = rotation_about(Vec3::UnitY(), theta);
    const Vec3 normal = R * Vec3::UnitZ(), down = R * Vec3::UnitX();
    SolidSpec spec = box_solid(Vec3(0.05 * normal), Vec3(0.2, 0.2, 0.1), 1000.0, R);
    spec.friction = mu;
    const int b = w.add_solid(spec);
    // The acceleration from the speed down the slope at 0.1 s and 0.3 s: over the first steps, before the contact
    // holds (Bullet's margin), the box gains a little more (measured: 3.94 m/s^2 over the first 0.05 s at 30 degrees).
    const double dt = 1e-3;
    double v_early = 0.0;
    for (int k = 1; k <= 300; ++k) {
      w.step(dt);
      if (k == 100) v_early = w.spatial_state(b).velocity.dot(down);
    }
    const SpatialState st = w.spatial_state(b);
    const double a = g * (std::sin(theta) - mu * std::cos(theta));
    if (a > 0.0) {
      EXPECT_NEAR((st.velocity.dot(down) - v_early) / 0.2, a, 0.02 * a) << degrees;
      EXPECT_NEAR(st.velocity.dot(normal), 0.0, 0.01 * st.velocity.norm()) << degrees;  // it stays on the plane
    } else {
      EXPECT_LT(st.velocity.norm(), 1e-3) << degrees;
    }
  }
}

TEST(SolidBody, LockedComponentsStayPut) {
  RigidWorld w(Vec3(0.0, 0.0, -9.81), 1e-3);
  SolidSpec spec = box_solid(Vec3::Zero(), Vec3(0.2, 0.2, 0.2), 500.0);
  spec.locked = {true, true, false, true, true, true};  // heave only
  const int b = w.add_solid(spec);
  for (int k = 0; k < 100; ++k) {
    w.apply_force(b, Vec3(5.0, -3.0, 0.0), Vec3(0.2, 0.1, 0.3));
    w.step(1e-3);
  }
  const SpatialState s = w.spatial_state(b);
  EXPECT_EQ(s.position[0], 0.0);
  EXPECT_EQ(s.position[1], 0.0);
  EXPECT_NEAR(s.position[2], -0.5 * 9.81 * 0.1 * 0.1, 1e-3);
  EXPECT_NEAR(s.orientation.angularDistance(Quat::Identity()), 0.0, 1e-15);
}

// A body whose inertia is not diagonal in world axes runs in Bullet on its principal axes; its reported orientation
// is still the rotation since creation.
TEST(SolidBody, OrientationCountsFromCreationForATurnedBody) {
  RigidWorld w(Vec3(0.0, 0.0, 0.0), 1e-3);
  const Mat3 R = rotation_about(Vec3(1.0, 1.0, 0.0), 0.4);
  const int b = w.add_solid(box_solid(Vec3(0.5, 0.5, 0.5), Vec3(0.3, 0.2, 0.1), 700.0, R));
  EXPECT_NEAR(w.spatial_state(b).orientation.angularDistance(Quat::Identity()), 0.0, 1e-12);
  EXPECT_NEAR((w.spatial_state(b).position - Vec3(0.5, 0.5, 0.5)).norm(), 0.0, 1e-14);
  EXPECT_THROW(w.state(b), std::logic_error);  // a solid body has no planar state
  // Set spinning about world z (not a principal axis of the turned box, so only one short step, over which the
  // rotation stays about z to first order): the orientation counted from creation is a turn of w dt about z.
  w.set_velocity(b, Vec3::Zero(), Vec3(0.0, 0.0, 1.0));
  w.step(1e-4);
  const Eigen::AngleAxisd turned{Eigen::Quaterniond(w.spatial_state(b).orientation)};
  EXPECT_NEAR(turned.angle(), 1e-4, 1e-9);
  EXPECT_NEAR(std::abs(turned.axis()[2]), 1.0, 1e-4);
  // Single rotation locks are refused (the inertia couples the axes).
  SolidSpec one_lock = box_solid(Vec3(0.5, 0.5, 0.5), Vec3(0.3, 0.2, 0.1), 700.0);
  one_lock.locked = {false, false, false, false, true, false};
  EXPECT_THROW(w.add_solid(one_lock), std::invalid_argument);
}

// An arch (a prism 0.06 wide, 0.04 high and 0.04 deep whose notch, 0.02 x 0.02, opens downward), as its convex pieces:
// the decomposition (HACD) gives pieces whose union is the arch, none standing out of it.
SolidSpec arch_solid(const Vec3& at, double density, std::size_t* pieces = nullptr) {
  const std::vector<std::array<double, 2>> outline{{0, 0},       {0.02, 0},    {0.02, 0.02}, {0.04, 0.02},
                                                   {0.04, 0},    {0.06, 0},    {0.06, 0.04}, {0, 0.04}};
  const std::vector<std::array<int, 3>> caps{{0, 1, 2}, {0, 2, 7}, {2, 3, 7}, {3, 6, 7}, {3, 4, 5}, {3, 5, 6}};
  TriangleSurface s = testing::prism_along_y(outline, caps, -0.02, 0.02);
  for (auto& v : s.vertices) v += at;
  const mesh::ConvexPieces d = mesh::convex_decomposition(s, 1e-4);
  EXPECT_LT(d.overreach, 1e-12);
  double volume = 0.0;
  for (const auto& piece : d.pieces) volume += mass_properties(piece).volume;
  EXPECT_NEAR(volume, 0.002 * 0.04, 1e-15);
  if (pieces) *pieces = d.pieces.size();
  const MassProperties m = mass_properties(s);
  SolidSpec spec;
  spec.hulls = d.pieces;
  spec.centre_of_mass = m.centroid;
  spec.mass = density * m.volume;
  spec.inertia = density * m.inertia;
  return spec;
}

// A concave body collides as its convex pieces (a compound): the arch let down over a post 0.01 wide and 0.015 high
// stands on its legs on the floor, the post in its notch (its centre of mass 0.022 above the floor: the bar's
// 0.0012 m^2 at 0.03, the legs' 0.0008 at 0.01); as one convex hull it would sit on the post, 0.015 higher.
TEST(SolidBody, ConcaveBodyCollidesAsItsConvexPieces) {
  for (const bool whole : {false, true}) {
    RigidWorld w(Vec3(0.0, 0.0, -9.81), 1e-4);
    w.add_static_box(Vec3(-1.0, -1.0, -0.1), Vec3(1.0, 1.0, 0.0), 1.0, 0.0);
    w.add_static_box(Vec3(-0.005, -0.1, 0.0), Vec3(0.005, 0.1, 0.015), 1.0, 0.0);
    std::size_t pieces = 0;
    SolidSpec spec = arch_solid(Vec3(-0.03, 0.0, 0.02), 500.0, &pieces);
    EXPECT_GE(pieces, 2u);
    if (whole) spec.hulls = {box_surface(Vec3(0.0, 0.0, 0.04), Vec3(0.06, 0.04, 0.04))};  // its one convex hull
    const int b = w.add_solid(spec);
    for (int k = 0; k < 1500; ++k) w.step(1e-3);
    const SpatialState s = w.spatial_state(b);
    EXPECT_NEAR(s.position[2], whole ? 0.037 : 0.022, 3e-4) << (whole ? "one hull" : "its pieces");
    EXPECT_NEAR(s.position[0], 0.0, 1e-6);
    EXPECT_LT(s.velocity.norm(), 1e-3);
  }
}

// A restart rebuilds the world from its journal: a box, and an arch of convex pieces (a compound), tumbling onto the
// floor, go on to the same bits.
TEST(SolidBody, JournalReplaysToTheSameBits) {
  for (const bool arch : {false, true}) {
    RigidWorld w(Vec3(0.0, 0.0, -9.81), 1e-3);
    w.add_static_box(Vec3(-1.0, -1.0, -0.1), Vec3(1.0, 1.0, 0.0), 1.0, 0.0);
    const Mat3 tilted = rotation_about(Vec3(0, 1, 1), 0.3);
    SolidSpec spec = arch ? arch_solid(Vec3(0.0, 0.0, 0.2), 500.0)
                          : box_solid(Vec3(0.0, 0.0, 0.2), Vec3(0.2, 0.1, 0.1), 500.0, tilted);
    spec.friction = 0.4;
    const int b = w.add_solid(spec);
    w.set_velocity(b, Vec3(0.3, 0.1, 0.0), Vec3(1.0, -2.0, 0.5));
    for (int k = 0; k < 300; ++k) {
      w.apply_force(b, Vec3(0.1 * k, 0.0, 0.0), Vec3(0.0, 0.01, 0.0));
      if (k == 100) w.translate(b, Vec3(0.0, 0.0, 0.01));
      w.step(1e-3);
    }
    RigidWorld copy(Vec3(0.0, 0.0, -9.81), 1e-3);
    copy.replay(w.journal());
    for (int k = 0; k < 200; ++k) {
      w.step(1e-3);
      copy.step(1e-3);
    }
    const SpatialState a = w.spatial_state(b), c = copy.spatial_state(b);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(a.position[k], c.position[k]);
      EXPECT_EQ(a.angular_velocity[k], c.angular_velocity[k]);
    }
    EXPECT_EQ(a.orientation.w(), c.orientation.w());
    EXPECT_EQ(a.orientation.x(), c.orientation.x());
    EXPECT_GT(a.angular_velocity.norm(), 0.0) << arch;
  }
}

TEST(SolidBody, BadSolidsAreRefused) {
  RigidWorld w(Vec3(0.0, 0.0, -9.81), 1e-2);
  SolidSpec spec = box_solid(Vec3::Zero(), Vec3(0.2, 0.2, 0.2), 500.0);
  spec.mass = 0.0;
  EXPECT_THROW(w.add_solid(spec), std::invalid_argument);
  EXPECT_THROW(w.add_solid(box_solid(Vec3::Zero(), Vec3(0.015, 0.2, 0.2), 500.0)), std::invalid_argument);  // < 2 margins
  // The inset hull of a box is the box smaller by the margin on every side.
  const auto inset = inset_convex(box_surface(Vec3(1.0, 2.0, 3.0), Vec3(0.2, 0.1, 0.3)), 0.01);
  ASSERT_EQ(inset.size(), 8u);
  for (const Vec3& p : inset) {
    EXPECT_NEAR(std::abs(p[0] - 1.0), 0.09, 1e-14);
    EXPECT_NEAR(std::abs(p[1] - 2.0), 0.04, 1e-14);
    EXPECT_NEAR(std::abs(p[2] - 3.0), 0.14, 1e-14);
  }
}

}  // namespace
}  // namespace slide::rigid
