#include "cases/check_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "cases/particle_budget.hpp"
#include "coupling/position_text.hpp"
#include "coupling/rigid_bodies.hpp"
#include "coupling/water_gap.hpp"

namespace slide::cases {
namespace {

// " of N MB available (source)", or nothing where the limit cannot be read.
std::string memory_available() {
  try {
    if (const auto limit = memory_limit())
      return fmt::format(" of {:.0f} MB available ({})", limit->total_bytes() / 1e6, limit->source);
  } catch (const std::invalid_argument&) {  // refused with its message before the scene was built
  }
  return "";
}

// "[a, b] x [c, d]" (x [e, f] in 3-D): the domain's extent.
template <int D>
std::string extent_text(const Vec<D>& lo, const Vec<D>& hi) {
  std::string out;
  for (int k = 0; k < D; ++k) out += fmt::format("{}[{:.6g}, {:.6g}]", k ? " x " : "", lo[k], hi[k]);
  return out;
}

// How far the start lattice was moved: its rows to meet a 2-D body's bottom, or across x and y in 3-D to put one of
// the fcc lattice's planes on each plane of symmetry (cases/build_geometry_3d.cpp).
template <int D>
std::string lattice_move_text(const Vec<D>& offset) {
  if constexpr (D == 2) {
    return offset[1] != 0.0 ? fmt::format(", rows moved {:+.6g} m to meet bodies[0]'s bottom", offset[1]) : std::string();
  } else {
    if (offset[0] == 0.0 && offset[1] == 0.0) return {};
    return fmt::format(", moved ({:+.6g}, {:+.6g}) m in x and y to put a plane on each plane of symmetry", offset[0],
                       offset[1]);
  }
}

template <int D>
std::string summary(const Scene<D>& scene) {
  const auto& sim = *scene.simulation;
  const auto [dt, limit] = sim.allowed_time_step();
  const auto& o = sim.options;
  return fmt::format(
      "case            {}\n"
      "particles       {} total: {} fluid, {} wall, {} dummy\n"
      "spacing dp      {} m, kernel radius re = {} dp = {} m\n"
      "lattice         {} (nearest spacing {:.6g} dp){}\n"
      "n0, lambda      {:.9g}, {:.9g} m^2 (lambda / dp^2 = {:.6g})\n"
      "sound speed c0  {:.6g} m/s ({})\n"
      "gradient model  {}\n"
      "initial dt      {:.6g} s, limited by {}\n"
      "end time        {} s (about {:.0f} steps at the initial dt)\n"
      "domain          {} m\n"
      "memory          about {:.1f} MB at its peak{}\n",
      scene.name, sim.particles().real_count(), scene.fluid_count, scene.wall_count, scene.dummy_count, o.dp,
      o.re_over_dp, sim.re(), to_string(o.lattice), nearest_spacing(o.lattice, o.dp) / o.dp,
      lattice_move_text<D>(scene.lattice_offset),
      sim.lattice.n0, sim.lattice.lambda, sim.lattice.lambda / (o.dp * o.dp), o.sound_speed,
      scene.sound_speed_source, to_string(o.gradient), dt, to_string(limit), scene.end_time, scene.end_time / dt,
      extent_text<D>(o.domain_lo, o.domain_hi), scene.memory_estimate_bytes / 1e6,
      memory_available());
}

template <int D>
std::string start(const Scene<D>& scene) {
  std::string out;
  if (const auto& e = scene.equilibrium)
    out += fmt::format("hydrostatic start: equilibrium column relaxed for {:.4g} s ({} steps), residual row speed "
                       "{:.3g} m/s\n",
                       e->relaxation_time, e->steps, e->residual_speed);
  if (const auto& s = scene.settling)
    out += fmt::format("settled start: {:.4g} s of settling at damping {:.4g} 1/s ({} steps), largest speed {:.3g} "
                       "m/s, residual speed {:.3g} m/s, largest shift {:.3g} dp\n",
                       s->duration, s->damping_rate, s->steps, s->largest_speed, s->residual_speed,
                       s->largest_shift / scene.simulation->options.dp);
  if (scene.gate_particles > 0)
    out += fmt::format("gates: {} boundary particles held the water while it settled and are taken away at t = 0\n",
                       scene.gate_particles);
  return out;
}

// A body's outline where it stands now: as placed, turned by the angle it has turned since and moved with its
// centre of mass.
std::vector<Vec<2>> outline_now(const BodyReport& b, const rigid::PlanarState& s) {
  const double c = std::cos(s.angle), sn = std::sin(s.angle);
  std::vector<Vec<2>> out;
  for (const Vec<2>& v : b.outline) {
    const Vec<2> r = v - b.placed;
    out.push_back(Vec<2>(s.position[0] + c * r[0] - sn * r[1], s.position[1] + sn * r[0] + c * r[1]));
  }
  return out;
}

std::string bodies(const Scene<2>& scene) {
  std::string out;
  const double dp = scene.simulation->options.dp;
  for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
    const auto& b = scene.bodies[k];
    out += fmt::format(
        "body {:<10} {} motion, {} boundary particles\n"
        "  mass            {:.6g} kg/m (lattice sum {:.6g}), inertia {:.6g} kg m (lattice sum {:.6g})\n"
        "  area            {:.6g} m^2, displaced below the still-water level {:.6g} m^2, buoyancy / weight {:.4g}\n",
        b.name, b.motion, b.particles, b.mass, b.mass_particles, b.inertia, b.inertia_particles, b.area,
        b.displaced_area, b.buoyancy_ratio);
    const auto s = scene.simulation->bodies()->state(static_cast<int>(k));
    if (b.moved_to_draft != 0.0)
      out += fmt::format("  placed at its draft below the still-water level: moved {:+.3f} mm from where the scene "
                         "put it (Archimedes on its outline)\n",
                         1000.0 * b.moved_to_draft);
    // Where a body that floated with the water while it settled came to rest.
    if (b.free_while_settling && scene.settling)
      out += fmt::format("  settled with the water: centre ({:.6g}, {:.6g}) m, angle {:.4g} deg, {:.3g} mm from "
                         "where it was put\n",
                         s.position[0], s.position[1], s.angle * 180.0 / M_PI,
                         1000.0 * (Vec<2>(s.position[0], s.position[1]) - b.placed).norm());
    const WaterGap gap = water_gap_along_outline(*scene.simulation, outline_now(b, s));
    if (gap.wetted_length > 0.0)
      out += fmt::format("  water gap       {:+.3f} dp at t = 0, mean over {:.3g} m of wetted face (the water's edge "
                         "against the face; > 0: it stands off)\n",
                         gap.mean / dp, gap.wetted_length);
    else
      out += "  water gap       no wetted face at t = 0\n";
  }
  return out;
}

std::string bodies(const Scene<3>& scene) {
  std::string out;
  for (std::size_t k = 0; k < scene.bodies.size(); ++k) {
    const auto& b = scene.bodies[k];
    out += fmt::format(
        "body {:<10} {} motion ({}), {} boundary particles\n"
        "  mass            {:.6g} kg, inertia {:.6g} kg m^2 (the tensor's mean diagonal)\n"
        "  volume          {:.6g} m^3, displaced below the still-water level {:.6g} m^3, buoyancy / weight {:.4g}\n",
        b.name, b.motion, b.motion == "rail" ? "along its rail, not turning" : "six degrees of freedom", b.particles,
        b.mass, b.inertia, b.area, b.displaced_area, b.buoyancy_ratio);
    if (b.moved_to_draft != 0.0)
      out += fmt::format("  placed at its draft below the still-water level: moved {:+.3f} mm from where the scene "
                         "put it (Archimedes on its surface)\n",
                         1000.0 * b.moved_to_draft);
    if (b.free_while_settling && scene.settling) {
      const auto s = scene.simulation->bodies()->state(static_cast<int>(k));
      out += fmt::format("  settled with the water: centre {} m, turned {:.4g} deg, {:.3g} mm from where it was put\n",
                         position_text<3>(Vec<3>(s.position)),
                         s.orientation.angularDistance(rigid::Quat::Identity()) * 180.0 / M_PI,
                         1000.0 * (Vec<3>(s.position) - b.placed).norm());
    }
  }
  return out;
}

}  // namespace


// A phase's wall condition (fluid/basal_friction.hpp; free_slip leaves walls out of the viscous term whatever it says).
static std::string basal_condition(double mu_b, WallSlip slip) {
  if (slip == WallSlip::free_slip) return "free-slip at walls";
  if (!std::isfinite(mu_b)) return "no-slip at walls";
  return fmt::format("basal friction {:.4g} deg (mu_b {:.4g}) at walls", std::atan(mu_b) * 180.0 / M_PI, mu_b);
}

// The phases with their rheology and the viscous scheme; each deformable slide with its particles, mass and yield
// criterion at rest.
template <int D>
std::string phases_and_slides(const Scene<D>& scene) {
  const auto& sim = *scene.simulation;
  std::string out;
  for (const auto& p : sim.phases)
    out += fmt::format("phase {:<9} {} kg/m^3, {}, {}\n", p.name, p.density_kg_m3, model_name(p.rheology),
                       basal_condition(p.basal_friction, sim.options.wall_slip));
  out += fmt::format("viscous scheme  {}\n", to_string(sim.options.viscous_scheme));
  // Per unit width in 2-D: an area and kg/m; in 3-D a volume and kg.
  const std::string size = D == 2 ? "area" : "volume", size_unit = D == 2 ? "m^2" : "m^3";
  const std::string mass_unit = D == 2 ? "kg/m" : "kg";
  for (const auto& s : scene.slides)
    out += fmt::format("slide {:<9} deformable ({}), {} particles, {} {:.6g} {}, mass {:.6g} {} (particles {:.6g})\n"
                       "  at rest         {}\n",
                       s.name, s.model, s.particles, size, s.volume, size_unit, s.density * s.volume, mass_unit,
                       s.mass_particles, s.criterion);
  for (const auto& s : scene.slides)
    if (!s.rigid_at_rest_warning.empty()) out += "warning: " + s.rigid_at_rest_warning + "\n";
  for (const auto& s : scene.slides)
    if (!s.floats_warning.empty()) out += "warning: " + s.floats_warning + "\n";
  return out;
}

template <int D>
std::string check_report(const Scene<D>& scene) {
  std::string out = summary(scene) + phases_and_slides(scene) + start(scene);
  return out + bodies(scene);
}

template std::string check_report(const Scene<2>&);
template std::string check_report(const Scene<3>&);

}  // namespace slide::cases
