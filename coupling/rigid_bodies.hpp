#pragma once
// The exchange between the MPS fluid and rigid bodies (DESIGN.md step 5). Each body's boundary particles carry
// their offsets in the body frame; every step their world positions, velocities and normals are set from the
// body's pose (x = X + R r0, v = V + omega x (R r0)), never integrated. The fluid force on a body is the sum, over
// its boundary particles, of exactly the opposite of the pair terms those particles contributed to their fluid
// neighbours' pressure gradient, viscous term and collisions, so what the body gets the fluid gives.
// Only coupling/ knows both fluid/ and rigid/. Bodies are planar (2-D scenes).
#include <optional>
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
#include "rigid/rigid_world.hpp"

namespace slide {

// Mean fluid force of the last step on a body, and its torque about the centre of mass.
struct BodyFluidForce {
  Vec<2> pressure = Vec<2>::Zero();  // pressure gradient and collision impulses
  Vec<2> viscous = Vec<2>::Zero();
  double pressure_torque = 0.0;
  double viscous_torque = 0.0;
  Vec<2> total() const { return pressure + viscous; }
  double total_torque() const { return pressure_torque + viscous_torque; }
};

struct BodyMotion {
  enum class Mode { free, prescribed } mode = Mode::free;
  static constexpr auto mode_names =
      make_name_table<Mode>(std::pair{Mode::free, "free"}, std::pair{Mode::prescribed, "prescribed"});
  double release_time = 0.0;                        // free bodies are held until then
  bool free_while_settling = false;                 // floats with the water during a settled start (free bodies)
  std::optional<rigid::PrescribedMotion> prescribed;  // for Mode::prescribed
};

class RigidBodies {
 public:
  RigidBodies(const Vec<2>& gravity, double margin) : world(rigid::Vec2(gravity[0], gravity[1]), margin) {}

  rigid::RigidWorld world;
  std::vector<std::string> names;
  std::vector<BodyMotion> motion;
  std::vector<BodyFluidForce> force;  // of the last step
  std::vector<double> density;        // kg/m^3 (informative; mass is per unit width)
  // rad: the orientation the scene placed the body at (a box's shape.angle; 0 for an outline given by its points).
  // Bullet counts its angle from creation; bodies.csv and prescribed series state placed_angle + that.
  std::vector<double> placed_angle;

  int add(const std::string& name, const rigid::BodySpec& spec, const BodyMotion& m, double body_density,
          double placed_angle_rad = 0.0);
  std::size_t size() const { return names.size(); }

  // Body b's outline where it is now, counter-clockwise, m.
  std::vector<Vec<2>> outline_now(int b) const;
  // Pose and velocity of body b now.
  rigid::PlanarState state(int b) const { return world.state(b); }
  // Its angle as the scene states orientations: placed_angle + the rotation since creation, rad.
  double absolute_angle(int b) const { return placed_angle[static_cast<std::size_t>(b)] + state(b).angle; }

  // Applies the poses at `time` (prescribed bodies) and sets every body particle's position, velocity, normal and
  // acceleration from its body's pose. The acceleration is the rigid field a = A + alpha x r - omega^2 r, with A
  // and alpha the body's mean accelerations since the previous placement (zero at the first one, or when time
  // went back, as after settling); the boundary pressure needs it (fluid/wall_pressure.hpp: head along g - a).
  void place_particles(Particles<2>& P, double time);

  // The three exchanges, each called where the fluid computes the same pair terms, before the fluid's update.
  void add_viscous_forces(const Domain<2>& domain, const NeighborList& nl, double re, double n0, double lambda,
                          const ViscousWall& wall, double volume);
  void add_pressure_forces(const Domain<2>& domain, const NeighborList& nl, GradientModel model, double re, double n0,
                           double kappa, double volume);
  void add_collision_forces(const Domain<2>& domain, const NeighborList& nl, double distance, double restitution,
                            double volume, double dt);
  // The water's pressure on the faces that rest on a wall under water, where no fluid particle reaches: beside the pair
  // terms above, called with them (coupling/dry_face_pressure.hpp). `grid` bins P's positions.
  void add_dry_face_pressure(const Particles<2>& P, const NeighborGrid<2>& grid, const PorePressureField<2>& pore,
                             double dp);

  // Mean fluid and contact forces since the last call (time-weighted over the steps in between), for outputs:
  // a single step's force is noisy, the momentum a body received over an interval is not.
  struct MeanForces {
    BodyFluidForce fluid;
    Vec<2> contact = Vec<2>::Zero();
  };
  std::vector<MeanForces> take_mean_forces();

  // A settled start (coupling/relaxation.hpp) runs the step loop before t = 0. While it does, prescribed bodies stay
  // at their pose of t = 0, free bodies are held unless they float with the water (free_while_settling), and no
  // release time passes. Ending it restores the holds of t = 0 and stops every body.
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
  void accumulate(const Domain<2>& domain, const std::vector<Vec<2>>& per_particle, bool viscous);
  template <class PairForce>
  void exchange(const Domain<2>& domain, const NeighborList& nl, bool viscous, const PairForce& pair_force);
  BodyFluidForce& pending(int b) { return pending_[b]; }
  std::vector<BodyFluidForce> pending_;
  std::vector<MeanForces> impulse_;  // force x time since the last take_mean_forces
  double impulse_time_ = 0.0;
  std::vector<Vec<2>> scratch_;
  std::vector<std::vector<Vec<2>>> outline_;  // each body's outline about its centre of mass, as created (ccw)
  std::vector<rigid::PlanarState> placed_state_;  // at the last placement
  double placed_time_ = 0.0;
  bool settling_ = false;
};

}  // namespace slide
