#include "coupling/equilibrium_column.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "coupling/advance.hpp"
#include "fluid/hydrostatic_start.hpp"
#include "fluid/ghosts.hpp"
#include "fluid/walls.hpp"

namespace slide {
namespace {

// After every step, every column moves with the first one (no shear, so the lattice cannot rearrange: the columns
// differ only by rounding, their neighbours being listed in another order); the loop stops once the rows have stopped
// (after t_min, row speeds below the tolerance). Ghosts are copied again from the columns they stand for.
class ColumnObserver : public StepObserver<2> {
 public:
  ColumnObserver(Particles<2>& P, std::size_t first_fluid, int columns, int rows, double dp, double tolerance,
                 double t_min)
      : y(rows), vy(rows), P_(P), first_fluid_(first_fluid), columns_(columns), dp_(dp),
        tolerance_(tolerance), t_min_(t_min) {}

  bool before_step(const Simulation<2>& sim) override { return !(sim.time() > t_min_ && speed < tolerance_); }

  void after_step(Simulation<2>&, double) override {
    speed = 0.0;
    const std::size_t n = P_.real_count();
    for (std::size_t i = 0; i < n; ++i)
      if (P_.kind[i] == Kind::fluid && column_of(P_.id[i]) == 0) {
        y[row_of(P_.id[i])] = P_.position[i][1];
        vy[row_of(P_.id[i])] = P_.velocity[i][1];
        speed = std::max(speed, std::abs(P_.velocity[i][1]));
      }
    for (std::size_t i = 0; i < n; ++i)
      if (P_.kind[i] == Kind::fluid) {
        P_.position[i] = Vec<2>((column_of(P_.id[i]) + 0.5) * dp_, y[row_of(P_.id[i])]);
        P_.velocity[i] = Vec<2>(0.0, vy[row_of(P_.id[i])]);
      }
    if (P_.ghost_count() != 0) sync_ghosts(P_);
  }

  std::vector<double> y, vy;  // per row, of the first column
  double speed = std::numeric_limits<double>::infinity();  // largest row speed after the last step

 private:
  int row_of(ParticleId id) const { return static_cast<int>((id - first_fluid_) / columns_); }
  int column_of(ParticleId id) const { return static_cast<int>((id - first_fluid_) % columns_); }
  Particles<2>& P_;
  std::size_t first_fluid_;
  int columns_;
  double dp_, tolerance_, t_min_;
};

// One relaxation of the column at Courant number cfl.
struct ColumnRelaxation {
  std::string instability;   // empty when the column stayed stable
  bool at_rest = false;      // stable, and the rows stopped (speed below the tolerance)
  std::vector<double> y;     // row heights of the first column, bottom to top
  double speed = 0.0, time = 0.0, column_dt = 0.0, run_dt = 0.0;
  long steps = 0;
};

ColumnRelaxation relax_column(const FluidOptions<2>& options, double density, double viscosity, int rows,
                              double cfl) {
  const double dp = options.dp, re = options.re_over_dp * dp;
  const double g = -options.gravity[1];
  // A periodic slab of the fewest columns the periodic ghosts allow (a period of at least twice the neighbour
  // list's radius): it is the infinite lattice, so every column has a complete neighbourhood. Why: the slab it
  // replaced, 4 ceil(re / dp) + 1 columns on a floor twice as wide (13 at the default re), computed all of them to use
  // the middle one, and was 74 % of the bench case's setup (docs/profile.md); at the default re and skin, 5 columns.
  const double list_radius = re + options.skin_over_dp * dp;
  int columns = static_cast<int>(std::ceil(2.0 * list_radius / dp - 1e-9));
  while (columns * dp < 2.0 * list_radius) ++columns;  // the period check has no tolerance (2 (re + skin) / dp whole)

  Simulation<2> sim;
  sim.options = options;
  sim.options.gravity = Vec<2>(0.0, -g);
  const PeriodicX period{0.0, columns * dp};
  sim.options.periodic_x = period;
  sim.options.cfl = cfl;
  auto& P = sim.particles();
  // The floor's layers over one period: a longer floor's points that fall in it (they lie on the lattice columns' x
  // minus half a spacing, as a scene's floor does beside water whose columns start at its end).
  const double floor_reach = (columns + 2) * dp;
  for (const auto& b : polyline_boundary({Vec<2>(-floor_reach, 0.0), Vec<2>(period.x_max + floor_reach, 0.0)}, true,
                                         dp, boundary_layers(options.re_over_dp))) {
    if (!(b.position[0] >= period.x_min && b.position[0] < period.x_max - 1e-9 * dp)) continue;
    const std::size_t i = P.add(b.position, b.layer == 0 ? Kind::wall : Kind::dummy, 0, density, viscosity);
    P.wall_normal[i] = b.normal;
    P.wall_depth[i] = b.depth;
  }
  const std::size_t first_fluid = P.size();
  for (int j = 0; j < rows; ++j)
    for (int c = 0; c < columns; ++c) P.add(Vec<2>((c + 0.5) * dp, (j + 0.5) * dp), Kind::fluid, 0, density, viscosity);
  // Start from the equation-of-state estimate.
  const LatticeConstants lc = lattice_constants<2>(dp, re);
  compress_hydrostatically<2>(P, dp, re, EquationOfState(lc.n0, options.sound_speed, options.gamma), g, true, {});
  const double height = rows * dp;
  sim.options.domain_lo = Vec<2>(period.x_min, -4 * re);
  sim.options.domain_hi = Vec<2>(period.x_max, 1.5 * height + 4 * re);
  // Slowest mode: the column's quarter-wave acoustic mode; damp it critically.
  const double omega = M_PI * options.sound_speed / (2.0 * height);
  sim.set_velocity_damping(2.0 * omega);
  sim.initialise();

  ColumnObserver column(P, first_fluid, columns, rows, dp, 1e-7 * std::sqrt(g * height), 3.0 / omega);
  const AdvanceResult result = advance<2>(sim, 60.0 / omega, {&column});
  ColumnRelaxation out;
  out.speed = column.speed;
  out.y = column.y;
  out.time = sim.time();
  out.steps = sim.step_count();
  // The steps at rest, at the relaxation's Courant number and at the run's (the last step taken may have been cut
  // short to land on the end time).
  out.column_dt = sim.allowed_time_step().first;
  sim.options.cfl = options.cfl;
  out.run_dt = sim.allowed_time_step().first;
  if (result.instability) out.instability = "the equilibrium column went unstable: " + result.instability->reason;
  out.at_rest = !result.instability && column.speed < 1e-7 * std::sqrt(g * height);
  return out;
}

}  // namespace

EquilibriumColumn equilibrium_column(const FluidOptions<2>& options, double density, double viscosity, int rows,
                                     double relaxation_cfl) {
  const double dp = options.dp, g = -options.gravity[1];
  if (rows < 1 || g <= 0.0) throw std::invalid_argument("equilibrium_column needs rows >= 1 and downward gravity");
  // Relaxed at relaxation_cfl (or the run's Courant number, if larger), and again at the run's if that does not come to
  // rest. The gaps between rows do not depend on the step: in still water every fluid particle's predicted position
  // is x + dt^2 g, and the rows balance where the pressure at the predicted positions holds them. Only the bottom
  // row's height over the floor does, by dt^2 g, which is corrected below to the step the run takes in still water
  // as the column sees it (water's Courant and viscous limits, dt_max; a scene whose step another phase sets runs at
  // a smaller one, as it did with the column before, and its bottom row starts up to dt^2 g off, 1e-5 dp or less). Measured on the bench
  // case (dp 0.01, 200 rows): 2047 steps instead of 5958 at 0.2, and every particle placed within 7.4e-7 dp of where
  // the relaxation at 0.2 puts it (the relaxation's own tolerance: it stops at row speeds of 1e-7 sqrt(g H)).
  ColumnRelaxation r = relax_column(options, density, viscosity, rows, std::max(relaxation_cfl, options.cfl));
  if (!r.at_rest && options.cfl < relaxation_cfl) r = relax_column(options, density, viscosity, rows, options.cfl);
  if (!r.instability.empty()) throw std::runtime_error(r.instability);
  const double shift = (r.column_dt * r.column_dt - r.run_dt * r.run_dt) * g;
  EquilibriumColumn out;
  out.residual_speed = r.speed;
  out.relaxation_time = r.time;
  out.steps = r.steps;
  out.gap_from_top.resize(rows);
  const std::vector<double>& y = r.y;
  for (int k = 0; k < rows; ++k) {
    const int j = rows - 1 - k;  // row index from the bottom
    out.gap_from_top[k] = j > 0 ? y[j] - y[j - 1] : y[0] - shift + 0.5 * dp;
  }
  return out;
}

}  // namespace slide
