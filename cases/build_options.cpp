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
void read_checks(const YAML::Node& c, CheckOptions<2>& o) {
  o.max_number_density_ratio = c["max_number_density_ratio"].as<double>();
  o.max_speed_over_c0 = c["max_speed_over_c0"].as<double>();
}

}  // namespace

void read_fluid_options(SceneBuild& b) {
  FluidOptions<2>& opt = b.options();
  read_method(b.r, opt);
  read_time_step(b.r["time_step"], opt);
  read_checks(b.r["checks"], opt);
  opt.gravity = vec2(b.r["gravity"]);
  b.dp = opt.dp;
  b.hexagonal = opt.lattice == LatticeKind::hexagonal;
  b.initial_state = initial_state_names.parse(b.r["method"]["initial_state"].as<std::string>());
}

void check_lattice_choices(SceneBuild& b) {
  if (!b.hexagonal) return;
  if (b.options().wall_pressure == WallPressure::mirror)
    throw SceneError("method.wall_pressure", "the mirror model needs lattice: square (its images assume the square "
                                             "lattice); use extrapolated with lattice: hexagonal");
  if (b.initial_state == InitialState::hydrostatic)
    throw SceneError("method.initial_state", "lattice: hexagonal starts from lattice or settled (settling "
                                             "compresses it); the column-wise hydrostatic start needs lattice: square");
  for (std::size_t w = 0; w < b.r["walls"].size(); ++w)
    if (b.r["walls"][w]["layers"].as<long>() != 0)
      throw SceneError(fmt::format("walls[{}].layers", w),
                       "with lattice: hexagonal walls are cut from the lattice to the depth re; leave layers at 0");
}

// A periodic domain's period must hold a whole number of the lattice's columns (dp apart on the square lattice,
// 1.0746 dp on the hexagonal one): otherwise the lattice does not join across the seam, and the particles either side
// of it stand too close or too far apart (a 0.2 m period at dp 0.01 on the hexagonal lattice holds 18.6 columns: a
// seam 1.6 columns wide in every row). Within 1e-3 of a column: the seam's spacing is then a's to 0.1 %.
void check_period(SceneBuild& b) {
  const YAML::Node d = b.r["domain"];
  if (!d || !d["periodic_x"].as<bool>()) return;
  const double x_min = d["min"][0].as<double>(), x_max = d["max"][0].as<double>();
  const double column = nearest_spacing(b.options().lattice, b.dp), columns = (x_max - x_min) / column;
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

bool SceneBuild::in_period(double x) const {
  if (!period_x) return true;
  const double quarter = 0.25 * nearest_spacing(sim->options.lattice, dp);
  return x >= period_x->x_min - quarter && x < period_x->x_max - quarter;
}

}  // namespace slide::cases
