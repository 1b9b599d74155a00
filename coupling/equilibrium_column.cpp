#include "coupling/equilibrium_column.hpp"

#include <cmath>
#include <stdexcept>

#include "fluid/hydrostatic_start.hpp"
#include "fluid/walls.hpp"

namespace slide {

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
  sim.options.velocity_damping_rate = 2.0 * omega;
  sim.initialise();

  auto row_of = [&](std::uint32_t id) { return static_cast<int>((id - first_fluid) / columns); };
  auto column_of = [&](std::uint32_t id) { return static_cast<int>((id - first_fluid) % columns) - half; };
  std::vector<double> y(rows), vy(rows);
  const double tolerance = 1e-7 * std::sqrt(g * height);
  const double t_min = 3.0 / omega, t_max = 60.0 / omega;
  EquilibriumColumn out;
  for (;;) {
    auto [dt, limit] = sim.allowed_time_step();
    if (auto bad = sim.step(dt, limit))
      throw std::runtime_error("the equilibrium column went unstable: " + bad->reason);
    double speed = 0.0;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.kind[i] == Kind::fluid && column_of(P.id[i]) == 0) {
        y[row_of(P.id[i])] = P.position[i][1];
        vy[row_of(P.id[i])] = P.velocity[i][1];
        speed = std::max(speed, std::abs(P.velocity[i][1]));
      }
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.kind[i] == Kind::fluid) {
        P.position[i] = Vec<2>((column_of(P.id[i]) + 0.5) * dp, y[row_of(P.id[i])]);
        P.velocity[i] = Vec<2>(0.0, vy[row_of(P.id[i])]);
      }
    out.residual_speed = speed;
    if ((sim.time > t_min && speed < tolerance) || sim.time > t_max) break;
  }
  out.relaxation_time = sim.time;
  out.steps = sim.step_count;
  out.gap_from_top.resize(rows);
  for (int k = 0; k < rows; ++k) {
    const int j = rows - 1 - k;  // row index from the bottom
    out.gap_from_top[k] = j > 0 ? y[j] - y[j - 1] : y[0] + 0.5 * dp;
  }
  return out;
}

}  // namespace slide
