#pragma once
// The rigid-body world: Bullet (double precision) behind one small interface, so that nothing outside rigid/
// sees Bullet. Two kinds of body share it:
//  * planar (2-D scenes): convex polygons extruded one metre in z, constrained to the x-y plane (linear factor 1,1,0;
//    angular factor 0,0,1), so mass and inertia are per unit width; static ground is made of segments;
//  * solid (3-D scenes): convex hulls in six degrees of freedom with their inertia tensor; static ground is boxes and
//    triangle meshes (terrains).
#include <Eigen/Geometry>
#include <array>
#include <memory>
#include <vector>

#include "rigid/polygon.hpp"
#include "rigid/polyhedron.hpp"

namespace slide::rigid {

struct PlanarState {
  Vec2 position = Vec2::Zero();  // centre of mass, m
  double angle = 0.0;            // rad, counter-clockwise, 0 at creation, continuous (not wrapped)
  Vec2 velocity = Vec2::Zero();  // of the centre of mass, m/s
  double angular_velocity = 0.0; // rad/s
};

struct BodySpec {
  std::vector<Vec2> outline;  // convex polygon in world coordinates at creation (either orientation)
  double mass = 0.0;          // per unit width, kg/m
  double inertia = 0.0;       // about the centre of mass, per unit width, kg m
  double friction = 0.0;      // Coulomb coefficient against static ground (which has friction 1)
  double restitution = 0.0;
  bool kinematic = false;     // moved from outside (prescribed motion): collides but is not pushed
  std::array<bool, 3> locked{false, false, false};  // x, y, rotation held fixed
};

using Quat = Eigen::Quaternion<double, Eigen::DontAlign>;

// A solid body's pose and motion. The orientation is the rotation since the body was made (identity then), the
// angular velocity is in world axes.
struct SpatialState {
  Vec3 position = Vec3::Zero();  // centre of mass, m
  Quat orientation = Quat::Identity();
  Vec3 velocity = Vec3::Zero();          // of the centre of mass, m/s
  Vec3 angular_velocity = Vec3::Zero();  // rad/s
};

struct SolidSpec {
  // The body's convex surface, or a concave body's convex pieces (mesh/convex_decomposition.hpp): outward, world
  // coordinates at creation, m.
  std::vector<TriangleSurface> hulls;
  Vec3 centre_of_mass = Vec3::Zero();   // m
  Mat3 inertia = Mat3::Identity();      // about the centre of mass, in world axes at creation, kg m^2
  double mass = 0.0;                    // kg
  double friction = 0.0;                // Coulomb coefficient against static ground (which has friction 1)
  double restitution = 0.0;
  std::array<bool, 6> locked{};         // x, y, z, then rotation about x, y, z held fixed
  bool kinematic = false;               // moved from outside (prescribed motion): collides but is not pushed
  // true: `hulls` are already the body's surface moved in by the collision margin (its maker built it so: a sphere's
  // of radius R - margin), taken as it is; false: add_solid moves it in (inset_convex).
  bool hull_inset = false;
};

class RigidWorld {
 public:
  // margin: Bullet's collision margin, m (kept inside the outlines, see polygon.hpp inset, and the hulls).
  RigidWorld(const Vec2& gravity, double margin);
  RigidWorld(const Vec3& gravity, double margin);
  ~RigidWorld();
  RigidWorld(const RigidWorld&) = delete;
  RigidWorld& operator=(const RigidWorld&) = delete;

  // Returns the body's index. Its centre of mass is the outline's centroid.
  int add_body(const BodySpec& spec);
  // Static ground: the segment a-b with solid material on the side `into_solid` (unit), `thickness` deep.
  void add_static_segment(const Vec2& a, const Vec2& b, const Vec2& into_solid, double thickness,
                          double friction, double restitution);

  // A solid body (3-D scenes). Returns its index. Throws std::invalid_argument for a mass or inertia that is not
  // positive, or a hull too small for the collision margin.
  int add_solid(const SolidSpec& spec);
  // Static ground in 3-D: the box [lo, hi] (axis-aligned).
  void add_static_box(const Vec3& lo, const Vec3& hi, double friction, double restitution);
  // Static ground in 3-D: a triangle surface, open or closed (a terrain), as Bullet's btBvhTriangleMeshShape (for
  // bodies that do not move: DESIGN.md).
  void add_static_mesh(const TriangleSurface& surface, double friction, double restitution);

  std::size_t size() const;
  PlanarState state(int body) const;
  SpatialState spatial_state(int body) const;
  double mass(int body) const;
  double inertia(int body) const;

  // Held bodies do not move (release_time); a held body keeps its pose and has zero velocity.
  void set_held(int body, bool held);
  // Kinematic bodies: the pose and velocity for the coming step, from a prescribed law.
  void set_kinematic_state(int body, const PlanarState& s);
  void set_kinematic_state(int body, const SpatialState& s);
  // Moves a body by delta without changing anything else (set-up only).
  void translate(int body, const Vec2& delta);
  // Sets a dynamic body's velocity (initial conditions).
  void set_velocity(int body, const Vec2& velocity, double angular_velocity);
  void set_velocity(int body, const Vec3& velocity, const Vec3& angular_velocity);
  void translate(int body, const Vec3& delta);
  // Force through the centre of mass and torque about it, applied during the next step only.
  void apply_force(int body, const Vec2& force, double torque);
  void apply_force(int body, const Vec3& force, const Vec3& torque);

  // Advances exactly dt (no sub-stepping, no interpolation).
  void step(double dt);

  // What Bullet's contacts and constraints did to the body in the last step, as a mean force:
  // m (v_new - v_old) / dt - m g - applied force. Zero for kinematic bodies.
  Vec2 contact_force(int body) const;
  Vec3 contact_force_3d(int body) const;

  // Every call that changed the world since it was made, in order with its arguments. Replaying it into a fresh
  // world of the same gravity and margin gives the same world bit for bit, Bullet's contact caches included (Bullet
  // is deterministic for the same calls): a checkpoint stores this rather than Bullet's internals.
  const std::vector<double>& journal() const;
  // Empties the world and makes the calls of `journal` again. Throws std::runtime_error on a malformed journal.
  void replay(const std::vector<double>& journal);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// sizeof(btScalar) as compiled into the library: 8 when the double-precision build is used consistently.
std::size_t bullet_scalar_size();

}  // namespace slide::rigid
