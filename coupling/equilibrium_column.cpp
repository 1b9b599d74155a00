#include "coupling/equilibrium_column.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "coupling/advance.hpp"
#include "fluid/hydrostatic_start.hpp"
#include "fluid/walls.hpp"

namespace slide {
namespace {

// After every step, every column moves with the middle one (no shear, so the lattice cannot rearrange); the loop
// stops once the rows have stopped (after t_min, row speeds below the tolerance).
class ColumnObserver : public StepObserver<2> {
 public:
  ColumnObserver(Particles<2>& P, std::size_t first_fluid, int columns, int half, int rows, double dp, double tolerance,
                 double t_min)
      : y(rows), vy(rows), P_(P), first_fluid_(first_fluid), columns_(columns), half_(half), dp_(dp),
        tolerance_(tolerance), t_min_(t_min) {}

  bool before_step(const Simulation<2>& sim) override { return !(sim.time() > t_min_ && speed < tolerance_); }

  void after_step(Simulation<2>&, double) override {
    speed = 0.0;
    for (std::size_t i = 0; i < P_.size(); ++i)
      if (P_.kind[i] == Kind::fluid && column_of(P_.id[i]) == 0) {
        y[row_of(P_.id[i])] = P_.position[i][1];
        vy[row_of(P_.id[i])] = P_.velocity[i][1];
        speed = std::max(speed, std::abs(P_.velocity[i][1]));
      }
    for (std::size_t i = 0; i < P_.size(); ++i)
      if (P_.kind[i] == Kind::fluid) {
        P_.position[i] = Vec<2>((column_of(P_.id[i]) + 0.5) * dp_, y[row_of(P_.id[i])]);
        P_.velocity[i] = Vec<2>(0.0, vy[row_of(P_.id[i])]);
      }
  }

  std::vector<double> y, vy;  // per row, of the middle column
  double speed = std::numeric_limits<double>::infinity();  // largest row speed after the last step

 private:
  int row_of(std::uint32_t id) const { return static_cast<int>((id - first_fluid_) / columns_); }
  int column_of(std::uint32_t id) const { return static_cast<int>((id - first_fluid_) % columns_) - half_; }
  Particles<2>& P_;
  std::size_t first_fluid_;
  int columns_, half_;
  double dp_, tolerance_, t_min_;
};

}  // namespace

EquilibriumColumn equilibrium_column(const FluidOptions<2>& options, double density, double viscosity, int rows) {
  const double dp = options.dp, re = options.re_over_dp * dp;
  const double g = -options.gravity[1];
  if (rows < 1 || g <= 0.0) throw std::invalid_argument("equilibrium_column needs rows >= 1 and downward gravity");
  const int reach = static_cast<int>(std::ceil(re / dp));
  const int half = 2 * reach;  // columns on each side of the middle one

  Simulation<2> sim;
  sim.options = options;
  sim.options.gravity = Vec<2>(0.0, -g);
  auto& P = sim.particles;
  const double floor_half_width = (half + 2 * reach + 1) * dp;
  for (const auto& b : polyline_boundary({Vec<2>(-floor_half_width, 0.0), Vec<2>(floor_half_width, 0.0)}, true, dp,
                                         boundary_layers(options.re_over_dp))) {
    const std::size_t i = P.add(b.position, b.layer == 0 ? Kind::wall : Kind::dummy, 0, density, viscosity);
    P.wall_normal[i] = b.normal;
    P.wall_depth[i] = b.depth;
  }
  const std::size_t first_fluid = P.size();
  const int columns = 2 * half + 1;
  for (int j = 0; j < rows; ++j)
    for (int c = -half; c <= half; ++c) P.add(Vec<2>((c + 0.5) * dp, (j + 0.5) * dp), Kind::fluid, 0, density, viscosity);
  // Start from the equation-of-state estimate.
  const LatticeConstants lc = lattice_constants<2>(dp, re);
  compress_hydrostatically<2>(P, dp, re, EquationOfState(lc.n0, options.sound_speed, options.gamma), g, true, {});
  const double height = rows * dp;
  sim.options.domain_lo = Vec<2>(-floor_half_width - 4 * re, -4 * re);
  sim.options.domain_hi = Vec<2>(floor_half_width + 4 * re, 1.5 * height + 4 * re);
  // Slowest mode: the column's quarter-wave acoustic mode; damp it critically.
  const double omega = M_PI * options.sound_speed / (2.0 * height);
  sim.set_velocity_damping(2.0 * omega);
  sim.initialise();

  ColumnObserver column(P, first_fluid, columns, half, rows, dp, 1e-7 * std::sqrt(g * height), 3.0 / omega);
  const AdvanceResult result = advance<2>(sim, 60.0 / omega, {&column});
  if (result.instability) throw std::runtime_error("the equilibrium column went unstable: " + result.instability->reason);
  EquilibriumColumn out;
  out.residual_speed = column.speed;
  const std::vector<double>& y = column.y;
  out.relaxation_time = sim.time();
  out.steps = sim.step_count();
  out.gap_from_top.resize(rows);
  for (int k = 0; k < rows; ++k) {
    const int j = rows - 1 - k;  // row index from the bottom
    out.gap_from_top[k] = j > 0 ? y[j] - y[j - 1] : y[0] + 0.5 * dp;
  }
  return out;
}

}  // namespace slide
