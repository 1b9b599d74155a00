#pragma once
// The exchange between the MPS fluid and rigid bodies (DESIGN.md step 5). Each body's boundary particles carry
// their offsets in the body frame; every step their world positions, velocities and normals are set from the
// body's pose (x = X + R r0, v = V + omega x (R r0)), never integrated. The fluid force on a body is the sum, over
// its boundary particles, of exactly the opposite of the pair terms those particles contributed to their fluid
// neighbours' pressure gradient, viscous term and collisions, so what the body gets the fluid gives.
// Only coupling/ knows both fluid/ and rigid/. In 2-D scenes bodies are planar (a scalar angle and torque, per unit
// width), in 3-D solid in six degrees of freedom (a quaternion, torque vectors); the exchange is the same.
#include <optional>
#include <type_traits>
#include <string>
#include <vector>

#include "fluid/domain.hpp"
#include "fluid/gradient.hpp"
#include "fluid/name_table.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"
#include "fluid/pore_pressure.hpp"
#include "fluid/state_stream.hpp"
#include "fluid/viscosity.hpp"
#include "rigid/prescribed_motion.hpp"
#include "rigid/rail_motion.hpp"
#include "rigid/spatial_prescribed_motion.hpp"
#include "rigid/rigid_world.hpp"

namespace slide {

// A torque: about z in 2-D (N m per unit width), a vector in 3-D (N m).
template <int D>
using Torque = std::conditional_t<D == 2, double, Vec<3>>;
template <int D>
Torque<D> zero_torque() {
  if constexpr (D == 2) return 0.0;
  else return Vec<3>::Zero();
}
// The torque of force f at arm r: r x f.
inline double torque_of(const Vec<2>& r, const Vec<2>& f) { return r[0] * f[1] - r[1] * f[0]; }
inline Vec<3> torque_of(const Vec<3>& r, const Vec<3>& f) { return r.cross(f); }

// A body's pose and motion as the rigid world states it.
template <int D>
using BodyState = std::conditional_t<D == 2, rigid::PlanarState, rigid::SpatialState>;
// What a body is made from: a convex outline (2-D), a convex surface with its inertia tensor (3-D).
template <int D>
using BodySpecOf = std::conditional_t<D == 2, rigid::BodySpec, rigid::SolidSpec>;
// The orientation the scene placed a body at: an angle (rad) in 2-D, a rotation in 3-D.
template <int D>
using Placement = std::conditional_t<D == 2, double, rigid::Quat>;

// Mean fluid force of the last step on a body, and its torque about the centre of mass.
template <int D>
struct BodyFluidForce {
  Vec<D> pressure = Vec<D>::Zero();  // pressure gradient and collision impulses
  Vec<D> viscous = Vec<D>::Zero();
  Torque<D> pressure_torque = zero_torque<D>();
  Torque<D> viscous_torque = zero_torque<D>();
  Vec<D> total() const { return pressure + viscous; }
  Torque<D> total_torque() const { return pressure_torque + viscous_torque; }
};

struct BodyMotion {
  enum class Mode { free, prescribed, rail } mode = Mode::free;
  static constexpr auto mode_names = make_name_table<Mode>(std::pair{Mode::free, "free"},
                                                           std::pair{Mode::prescribed, "prescribed"},
                                                           std::pair{Mode::rail, "rail"});
  double release_time = 0.0;                        // free and rail bodies are held until then
  bool free_while_settling = false;                 // floats with the water during a settled start (free bodies)
  std::optional<rigid::PrescribedMotion> prescribed;  // for Mode::prescribed, 2-D
  std::optional<rigid::SpatialPrescribedMotion> prescribed_3d;  // for Mode::prescribed, 3-D
  std::optional<rigid::Rail> rail;                              // for Mode::rail (3-D), held until release_time
};

template <int D>
class RigidBodies {
 public:
  RigidBodies(const Vec<D>& gravity, double margin) : world(world_vector(gravity), margin), gravity_(gravity) {}

  rigid::RigidWorld world;
  std::vector<std::string> names;
  std::vector<BodyMotion> motion;
  std::vector<BodyFluidForce<D>> force;  // of the last step
  std::vector<double> density;           // kg/m^3 (informative; in 2-D mass is per unit width)
  // The orientation the scene placed the body at (2-D: a box's shape.angle, 0 for an outline given by its points;
  // 3-D: the rotation its shape states). Bullet counts rotations from creation; bodies.csv and prescribed series state
  // the placement composed with that.
  std::vector<Placement<D>> placed;

  int add(const std::string& name, const BodySpecOf<D>& spec, const BodyMotion& m, double body_density,
          const Placement<D>& placed_at = unturned());
  std::size_t size() const { return names.size(); }

  // Body b's outline where it is now, counter-clockwise, m (2-D).
  std::vector<Vec<2>> outline_now(int b) const requires(D == 2);
  // Pose and velocity of body b now.
  BodyState<D> state(int b) const {
    if constexpr (D == 2) return world.state(b);
    else return world.spatial_state(b);
  }
  // Its angle as the scene states orientations: the placement + the rotation since creation, rad (2-D).
  double absolute_angle(int b) const requires(D == 2) {
    return placed[static_cast<std::size_t>(b)] + state(b).angle;
  }
  // Its orientation as the scene states orientations: the rotation since creation after the placement (3-D).
  rigid::Quat absolute_orientation(int b) const requires(D == 3) {
    return rigid::Quat(state(b).orientation * placed[static_cast<std::size_t>(b)]);
  }

  // Applies the poses at `time` (prescribed bodies) and sets every body particle's position, velocity, normal and
  // acceleration from its body's pose. The acceleration is the rigid field a = A + alpha x r + w x (w x r) (in 2-D
  // the last term is -omega^2 r), with A
  // and alpha the body's mean accelerations since the previous placement (zero at the first one, or when time
  // went back, as after settling); the boundary pressure needs it (fluid/wall_pressure.hpp: head along g - a).
  void place_particles(Particles<D>& P, double time);

  // The three exchanges, each called where the fluid computes the same pair terms, before the fluid's update.
  void add_viscous_forces(const Domain<D>& domain, const NeighborList& nl, double re, double n0, double lambda,
                          const ViscousWall& wall, double volume);
  void add_pressure_forces(const Domain<D>& domain, const NeighborList& nl, GradientModel model, double re, double n0,
                           double kappa, double volume);
  void add_collision_forces(const Domain<D>& domain, const NeighborList& nl, double distance, double restitution,
                            double volume, double dt);
  // The water's pressure on the faces that rest on a wall under water, where no fluid particle reaches: beside the pair
  // terms above, called with them (coupling/dry_face_pressure.hpp). `grid` bins the domain's particles. 2-D so far: in 3-D a
  // body's faces resting on walls get no such pressure (the faces are polygons there: not written yet).
  void add_dry_face_pressure(const Domain<D>& domain, const NeighborGrid<D>& grid, const PorePressureField<D>& pore,
                             double dp);

  // Mean fluid and contact forces since the last call (time-weighted over the steps in between), for outputs:
  // a single step's force is noisy, the momentum a body received over an interval is not.
  struct MeanForces {
    BodyFluidForce<D> fluid;
    Vec<D> contact = Vec<D>::Zero();
  };
  std::vector<MeanForces> take_mean_forces();

  // A settled start (coupling/relaxation.hpp) runs the step loop before t = 0. While it does, prescribed bodies stay
  // at their pose of t = 0, free bodies are held unless they float with the water (free_while_settling), rail bodies
  // stay where they are put, and no release time passes. Ending it restores the holds of t = 0 and stops every body.
  void set_settling(bool on);
  // Multiplies the velocities of the bodies that float while settling by `factor` (the settling's damping).
  void damp_floating(double factor);

  // Hands the accumulated forces to the rigid world, steps it by dt (time is the time after the step), and starts
  // the next step's accumulation.
  void advance(double time_after, double dt);

  // The state the step needs beyond the particles (tools/checkpoint.hpp): the rigid world (as its journal), the
  // forces being accumulated, the last placement. Restoring expects the same bodies, made as they were.
  void save_state(StateWriter& out) const;
  void restore_state(StateReader& in);

 private:
  static Placement<D> unturned() {
    if constexpr (D == 2) return 0.0;
    else return rigid::Quat::Identity();
  }
  static auto world_vector(const Vec<D>& v) {
    if constexpr (D == 2) return rigid::Vec2(v[0], v[1]);
    else return rigid::Vec3(v[0], v[1], v[2]);
  }
  void accumulate(const Domain<D>& domain, const std::vector<Vec<D>>& per_particle, bool viscous);
  // A rail body's step (rigid/rail_motion.hpp) under the fluid force of the step and gravity: its kinematic pose and
  // velocity at the step's end.
  void move_on_rail(int b, const Vec<D>& fluid_force, double dt);
  template <class PairForce>
  void exchange(const Domain<D>& domain, const NeighborList& nl, bool viscous, const PairForce& pair_force);
  std::vector<BodyFluidForce<D>> pending_;
  std::vector<MeanForces> impulse_;  // force x time since the last take_mean_forces
  double impulse_time_ = 0.0;
  std::vector<Vec<D>> scratch_;
  Vec<D> gravity_;
  std::vector<std::vector<Vec<2>>> outline_;  // 2-D: each body's outline about its centre of mass, as created (ccw)
  std::vector<BodyState<D>> placed_state_;  // at the last placement
  double placed_time_ = 0.0;
  bool settling_ = false;
};

extern template class RigidBodies<2>;
extern template class RigidBodies<3>;

}  // namespace slide
