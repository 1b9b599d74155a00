// Step: the fluid solver's options from the scene, one reader per part of FluidOptions (method, time step, checks),
// and what the hexagonal lattice demands of the other choices.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "cases/scene_build.hpp"

namespace slide::cases {
namespace {

// particle_spacing, lattice and method.* (the sound speed is chosen later, from the water: choose_sound_speed).
void read_method(const YAML::Node& r, MethodOptions& o) {
  const YAML::Node m = r["method"];
  o.dp = r["particle_spacing"].as<double>();
  o.lattice = lattice_kind_names.parse(r["lattice"].as<std::string>());
  o.re_over_dp = m["kernel_radius"].as<double>();
  o.skin_over_dp = m["neighbor_skin"].as<double>();
  o.gradient = gradient_model_names.parse(m["gradient"].as<std::string>());
  o.gamma = m["gamma"].as<double>();
  o.free_surface_beta = m["free_surface_beta"].as<double>();
  o.clamp_negative_pressure = m["clamp_negative_pressure"].as<bool>();
  o.surface_pressure = surface_pressure_names.parse(m["surface_pressure"].as<std::string>());
  o.wall_slip = wall_slip_names.parse(m["wall_slip"].as<std::string>());
  o.artificial_viscosity = m["artificial_viscosity"].as<double>();
  o.collision_distance_over_dp = m["collision_distance"].as<double>();
  o.collision_restitution = m["collision_restitution"].as<double>();
  o.wall_pressure = wall_pressure_names.parse(m["wall_pressure"].as<std::string>());
  o.pore_pressure = pore_pressure_names.parse(m["pore_pressure"].as<std::string>());
}

// time_step.*
void read_time_step(const YAML::Node& t, TimeStepOptions& o) {
  o.cfl = t["cfl"].as<double>();
  o.viscous_number = t["viscous_number"].as<double>();
  o.force_number = t["force_number"].as<double>();
  o.dt_max = t["max"].as<double>();
}

// checks.* (the domain is set once the particles are placed: set_domain).
template <int D>
void read_checks(const YAML::Node& c, CheckOptions<D>& o) {
  o.max_number_density_ratio = c["max_number_density_ratio"].as<double>();
  o.max_speed_over_c0 = c["max_speed_over_c0"].as<double>();
}

}  // namespace

template <int D>
void read_fluid_options(SceneBuild<D>& b) {
  const YAML::Node& r = b.r;  // (b is of a dependent type: r's .as<T>() needs no 'template')
  FluidOptions<D>& opt = b.options();
  read_method(r, opt);
  read_time_step(r["time_step"], opt);
  read_checks(r["checks"], opt);
  opt.gravity = vec_of<D>(r["gravity"]);
  b.dp = opt.dp;
  b.close_packed = opt.lattice != LatticeKind::square;
  b.initial_state = initial_state_names.parse(r["method"]["initial_state"].as<std::string>());
}

// In 3-D the mirror wall pressure is refused on any lattice: the narrow 3-D dam break (cases/dam_break_3d.yaml, square
// lattice) went unstable with it at t = 0.079 s, a particle through the edge between the floor and a side wall, where
// with extrapolated wall pressure it ran on and its front stayed within 1.1 % of the 2-D run's (docs/three-d.md).
template <int D>
void check_lattice_choices(SceneBuild<D>& b) {
  const YAML::Node& r = b.r;  // (b is of a dependent type: r's .as<T>() needs no 'template')
  if (D == 3 && b.options().wall_pressure == WallPressure::mirror)
    throw SceneError("method.wall_pressure", "the mirror model is 2-D only so far (in 3-D its images at a tank's edges "
                                             "let water through: docs/three-d.md); use extrapolated");
  if (!b.close_packed) return;
  const std::string_view lattice = to_string(b.options().lattice);
  if (b.options().wall_pressure == WallPressure::mirror)
    throw SceneError("method.wall_pressure", fmt::format("the mirror model needs lattice: square (its images assume "
                                                         "the square lattice); use extrapolated with lattice: {}",
                                                         lattice));
  if (b.initial_state == InitialState::hydrostatic)
    throw SceneError("method.initial_state", fmt::format("lattice: {} starts from lattice or settled (settling "
                                                         "compresses it); the column-wise hydrostatic start needs "
                                                         "lattice: square",
                                                         lattice));
  for (std::size_t w = 0; w < r["walls"].size(); ++w)
    if (r["walls"][w]["layers"] && r["walls"][w]["layers"].as<long>() != 0)
      throw SceneError(fmt::format("walls[{}].layers", w),
                       fmt::format("with lattice: {} walls are cut from the lattice to the depth re; leave layers at 0",
                                   lattice));
}

// A periodic domain's period must hold a whole number of the lattice's columns (dp apart on the square lattice,
// 1.0746 dp on the hexagonal one): otherwise the lattice does not join across the seam, and the particles either side
// of it stand too close or too far apart (a 0.2 m period at dp 0.01 on the hexagonal lattice holds 18.6 columns: a
// seam 1.6 columns wide in every row). Within 1e-3 of a column: the seam's spacing is then a's to 0.1 %.
template <int D>
void check_period(SceneBuild<D>& b) {
  const YAML::Node& r = b.r;  // (b is of a dependent type: r's .as<T>() needs no 'template')
  const YAML::Node d = r["domain"];
  if (!d || !d["periodic_x"].as<bool>()) return;
  const double x_min = d["min"][0].as<double>(), x_max = d["max"][0].as<double>();
  // The lattice repeats along x every column: dp, a (hexagonal), or two planes (fcc: its points alternate between
  // planes).
  const LatticeKind kind = b.options().lattice;
  const double column = kind == LatticeKind::fcc ? 2.0 * row_spacing(kind, b.dp) : nearest_spacing(kind, b.dp);
  const double columns = (x_max - x_min) / column;
  const double whole = std::round(columns);
  if (whole < 1.0 || std::abs(columns - whole) > 1e-3)
    throw SceneError("domain.max",
                     fmt::format("the period {} m holds {:.4f} columns of the {} lattice (spacing {:.17g} m); make it a "
                                 "whole number of columns, e.g. max.x = {:.17g} or {:.17g} m",
                                 x_max - x_min, columns, to_string(b.options().lattice), column,
                                 x_min + std::max(1.0, std::floor(columns)) * column,
                                 x_min + std::max(2.0, std::ceil(columns)) * column));
  b.period_x = PeriodicX{x_min, x_max};
}


template void read_fluid_options(SceneBuild<2>&);
template void read_fluid_options(SceneBuild<3>&);
template void check_lattice_choices(SceneBuild<2>&);
template void check_lattice_choices(SceneBuild<3>&);
template void check_period(SceneBuild<2>&);
template void check_period(SceneBuild<3>&);

}  // namespace slide::cases
