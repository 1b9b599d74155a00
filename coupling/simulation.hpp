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
#include "fluid/fluid_options.hpp"
#include "fluid/gradient.hpp"
#include "fluid/kernel.hpp"
#include "fluid/lattice.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/particles.hpp"
#include "fluid/viscosity.hpp"

namespace slide {

class RigidBodies;  // coupling/rigid_bodies.hpp (2-D scenes)

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
  std::array<long, time_step_limit_count> limit_counts{};  // how often each time-step limit ruled

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
