#pragma once
// The one step loop (DESIGN.md, "The step loop"): neighbours, explicit viscosity and gravity, number density and
// pressure at the predicted positions, pressure-gradient correction, collisions, rigid bodies (fluid force in,
// Bullet step, boundary particles placed from the new poses), stability checks.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "fluid/equation_of_state.hpp"
#include "fluid/gradient.hpp"
#include "fluid/kernel.hpp"
#include "fluid/lattice.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"
#include "fluid/viscosity.hpp"

namespace slide {

class RigidBodies;  // coupling/rigid_bodies.hpp (2-D scenes)

template <int D>
struct FluidOptions {
  double dp = 0.01;                 // particle spacing, m
  double re_over_dp = 2.1;          // kernel radius in spacings
  LatticeKind lattice = LatticeKind::square;  // the lattice the particles start on: n0, lambda, kappa are its sums
  double skin_over_dp = 0.3;        // neighbour-list skin in spacings
  GradientModel gradient = GradientModel::symmetric;
  double gamma = 7.0;
  double sound_speed = 10.0;        // c0, m/s
  double free_surface_beta = 0.97;  // n < beta n0: free-surface particle, pressure set to zero
  bool clamp_negative_pressure = true;
  WallSlip wall_slip = WallSlip::no_slip;
  // number_density: wall-layer particles take the pressure of their own number density (seed eq. 7), dummies none
  // (classic MPS: a particle pressing on the wall raises the wall's pressure). extrapolated: wall and dummy
  // particles continue the fluid's pressure field; mirror: they take the pressure at their mirror image in the
  // fluid plus the hydrostatic head (fluid/wall_pressure.hpp).
  enum class WallPressure { number_density, extrapolated, mirror } wall_pressure = WallPressure::mirror;
  double artificial_viscosity = 0.0;  // Monaghan alpha; 0 = off
  double collision_distance_over_dp = 0.5;  // collision model (fluid/collision.hpp); 0 = off
  double collision_restitution = 0.2;
  double velocity_damping_rate = 0.0; // 1/s; fluid velocities decay as exp(-rate t); used only while relaxing
  Vec<D> gravity = Vec<D>::Zero();
  // Time step: dt = min(cfl dp / (c0 + |u|max), viscous_number dp^2 / nu_max, force_number sqrt(dp / |a|max), dt_max)
  double cfl = 0.2;
  double viscous_number = 0.1;
  double force_number = 0.25;
  double dt_max = 1e-3;
  // Stability checks
  double max_number_density_ratio = 1.5;  // n / n0 above this is a collapse
  double max_speed_over_c0 = 1.0;         // a fluid particle faster than this many c0 is a blow-up
  Vec<D> domain_lo = Vec<D>::Zero(), domain_hi = Vec<D>::Zero();
};

enum class TimeStepLimit { cfl = 0, viscous = 1, force = 2, dt_max = 3, end_time = 4 };
inline constexpr std::array<const char*, 5> time_step_limit_names{"cfl", "viscous", "force", "dt_max", "end_time"};

struct Instability {
  std::string reason;     // what went wrong
  double time = 0.0;
  long step = 0;
  std::uint32_t particle = 0;  // id
  std::vector<double> position;
};

template <int D>
class Simulation {
 public:
  Particles<D> particles;
  FluidOptions<D> options;
  // Rigid bodies two-way coupled with the fluid; null when the scene has none. 2-D only.
  std::shared_ptr<RigidBodies> bodies;

  double time = 0.0;
  long step_count = 0;
  std::array<long, 5> limit_counts{};  // how often each time-step limit ruled

  // Derived at initialise(): lattice constants, equation of state, grid.
  LatticeConstants lattice;
  EquationOfState eos;

  double re() const { return options.re_over_dp * options.dp; }

  // Computes n0 and lambda from the lattice, builds the neighbour list, and evaluates number density and
  // pressure at the initial positions.
  void initialise();

  // The time step the limits allow now, and which limit ruled.
  std::pair<double, TimeStepLimit> allowed_time_step() const;

  // Advances by dt. Returns the instability found after the step, if any (the state is then the failed one).
  std::optional<Instability> step(double dt, TimeStepLimit limit);

  // Checks the current state: non-finite values, particles out of the domain, number-density collapse, speed.
  std::optional<Instability> check() const;

  const NeighborList& neighbors() const { return list_; }
  const NeighborGrid<D>& grid() const { return grid_; }
  long neighbor_rebuilds() const { return rebuilds_; }
  double max_fluid_speed() const;

  // Fluid number density at an arbitrary point (fluid particles only), for free-surface detection by gauges.
  double fluid_number_density_at(const Vec<D>& point) const;

 private:
  void update_neighbors(bool force);
  void compute_pressure();

  NeighborGrid<D> grid_;
  NeighborList list_;
  std::vector<Vec<D>> position_at_build_;
  std::vector<Vec<D>> scratch_;
  long rebuilds_ = 0;
};

extern template class Simulation<2>;
extern template class Simulation<3>;

}  // namespace slide
