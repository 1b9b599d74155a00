// Step: what a deformable slide is, in 2-D and 3-D alike: its phase (named after the body, of its density and
// rheology), and its report for `slide check` (particles, mass, warnings, the yield criterion at rest). The shape it
// fills is the dimension's own (build_bodies.cpp: an outline; build_bodies_3d.cpp: a closed surface).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cases/body_model.hpp"
#include "cases/scene_build.hpp"
#include "cases/solid_shape.hpp"
#include "fluid/basal_friction.hpp"
#include "fluid/pore_pressure.hpp"
#include "fluid/water_surface.hpp"

namespace slide::cases {
namespace {

// The density its weight acts with at rest: less the water's where its centroid starts below the still-water level.
template <int D>
double weight_density(const SceneBuild<D>& b, const typename SceneBuild<D>::Slide& slide, double density) {
  const bool below = std::isfinite(b.still_level) && slide.centroid[D - 1] < b.still_level;
  return density - (below ? b.phases.phases[0].density : 0.0);
}

// Whether the slide's own weight can yield it at rest anywhere: in a block or layer at rest under its buoyant
// weight the shear stress stays below rho' g H, H its height along gravity (on an infinite slope of angle theta the
// base carries rho' g h sin(theta), h <= H; a free vertical side of a purely cohesive material stands up to
// H = 3.83 c / (rho' g), the critical height of a vertical cut from Taylor's stability number 0.261), so a strength
// at zero normal stress of rho' g H or more holds it rigid at rest. (Overhangs can carry more; the warning is for the
// shapes slides have.)
template <int D>
void warn_if_rigid_at_rest(const SceneBuild<D>& b, const typename SceneBuild<D>::Slide& slide,
                           const Rheology& rheology, SlideReportOf<D>& rep) {
  double strength = 0.0;
  if (const auto* hb = std::get_if<HerschelBulkley>(&rheology)) strength = hb->yield_stress_pa;
  else if (const auto* mc = std::get_if<MohrCoulomb>(&rheology)) strength = mc->cohesion_pa;
  const double g = b.sim->options.gravity.norm();
  if (!(strength > 0.0) || g == 0.0) return;
  const Vec<D> down = b.sim->options.gravity / g;
  double top = std::numeric_limits<double>::infinity(), bottom = -top;
  for (const auto& v : slide.vertices) {
    const double depth = v.dot(down);
    top = std::min(top, depth), bottom = std::max(bottom, depth);
  }
  const double height = bottom - top;
  const double buoyant_weight = std::abs(weight_density(b, slide, rep.density)) * g * height;  // Pa
  if (strength < buoyant_weight) return;
  const std::string ratio =
      buoyant_weight > 0.0 ? fmt::format("{:.3g} times", strength / buoyant_weight) : std::string("above");
  rep.rigid_at_rest_warning = fmt::format(
      "{}: its strength at rest ({:.4g} Pa) is {} its buoyant weight per area over its {:.3g} m height ({:.4g} Pa), "
      "so its own weight yields it nowhere: it stays rigid until the water loads it; {}.model: rigid models such a "
      "slide at less cost",
      rep.key, strength, ratio, height, buoyant_weight, rep.key);
}

// The yield criterion at rest, an infinite-slope estimate on the face the slide rests on (theta its angle to the plane
// normal to gravity): a layer of thickness h normal to that face, its top at the slide's point furthest from the face
// and its base at that point's foot on the face. With the same functions the solver uses (fluid/water_surface.hpp,
// fluid/pore_pressure.hpp, fluid/rheology/rheology.hpp strength_at_rest):
//   total normal stress at the base   sigma = p_w(top) + rho_s g h cos(theta)   (the water above, then the layer),
//   pore pressure at the base         p_w(base), hydrostatic below the water's surface (0 with pore_pressure none:
//                                     the solver's frictional strengths then take the total stress),
//   effective normal stress           sigma' = sigma - p_w(base),
//   basal shear stress                tau = (rho_s h - rho_w h_w) g sin(theta), h_w the layer's submerged thickness
//                                     (its buoyant weight's component along the face; the water's head adds none);
// it holds strength_at_rest(sigma') (tau_y, c + sigma' tan(phi), mu_s sigma', nothing), and with a basal friction mu_b
// the wall holds mu_b sigma' at its base.
template <int D>
void yield_criterion_at_rest(const SceneBuild<D>& b, const typename SceneBuild<D>::Slide& slide,
                             const RestingFace<D>& face, SlideReportOf<D>& rep) {
  const Particles<D>& P = b.sim->particles();
  const FluidOptions<D>& opt = b.sim->options;
  const double g = opt.gravity.norm();
  const Rheology rheology = b.phases.phases[slide.phase].rheology;
  rep.slope_angle_deg = face.slope_angle_deg;
  const double theta = rep.slope_angle_deg * M_PI / 180.0, h = face.thickness;
  const Vec<D> top = face.top, base = top - h * face.normal;
  // The water as the solver sees it: the first phase, when Newtonian, is the water (Simulation::pore_pressure_field).
  const auto& water = b.phases.phases[0];
  const bool has_water = slide.phase != 0 && std::holds_alternative<Newtonian>(water.rheology);
  WaterSurface<D> surface;
  if (has_water) surface.build(P, opt.gravity, b.dp, [&](std::size_t i) { return P.phase[i] == 0; }, b.processes);
  const PorePressureField<D> head{water.density, g, has_water ? &surface : nullptr};
  const bool effective = opt.pore_pressure == PorePressureModel::hydrostatic;
  const double p_top = head.at(top), p_base = head.at(base);
  const double total = p_top + rep.density * g * h * std::cos(theta);
  const double normal_stress = effective_pressure(total, effective ? p_base : 0.0);
  const double submerged = std::cos(theta) > 0.0 ? (p_base - p_top) / (water.density * g * std::cos(theta)) : 0.0;
  rep.basal_shear_stress = (rep.density * h - water.density * submerged) * g * std::sin(theta);
  rep.strength = strength_at_rest(rheology, normal_stress);
  const std::string where = submerged >= h - 1e-9 ? "under water" : submerged > 0.0 ? "partly under water" : "dry";
  rep.criterion = fmt::format(
      "on a {:.3g} degree face, thickness {:.3g} m, {} (density {:.4g} kg/m^3; effective normal stress {:.4g} Pa at "
      "its base, method.pore_pressure {}): basal shear stress {:.4g} Pa against {:.4g} Pa it holds: {}",
      rep.slope_angle_deg, h, where, rep.density, normal_stress, to_string(opt.pore_pressure), rep.basal_shear_stress,
      rep.strength, rep.basal_shear_stress <= rep.strength ? "stands at rest (rigid throughout)" : "flows");
  // A Coulomb basal friction (fluid/basal_friction.hpp) bounds what the wall holds at the base.
  const double mu_b = b.phases.phases[slide.phase].basal_friction;
  if (std::isfinite(mu_b))
    rep.criterion += fmt::format("; at its base the wall holds mu_b x effective normal stress = {:.4g} Pa: {}",
                                 mu_b * std::max(normal_stress, 0.0),
                                 rep.basal_shear_stress <= mu_b * std::max(normal_stress, 0.0) ? "holds" : "slides");
}

}  // namespace

template <int D>
SlideReportOf<D> add_slide_phase(SceneBuild<D>& b, const YAML::Node& bn, const std::string& path,
                                 RheologyModel model) {
  const double density = bn["density"].as<double>();
  if (!(density > 0.0))
    throw SceneError(path + ".density", "a deformable slide needs its density (mass is for rigid bodies)");
  const std::string name = bn["name"].as<std::string>();
  const Rheology rheology = read_rheology(model, bn["rheology"], path + ".rheology");
  const std::size_t phase =
      b.phases.add(name, density, rheology, basal_friction_coefficient(bn["basal_friction_angle"].as<double>()),
                   path + ".name");
  SlideReportOf<D> rep;
  rep.key = path;
  rep.name = name;
  rep.model = std::string(rheology_model_names.name(model));
  rep.phase = static_cast<std::uint8_t>(phase);
  rep.density = density;
  const Vec<D> d = vec_of<D>(bn["front_direction"]);
  if (d.norm() == 0.0) throw SceneError(path + ".front_direction", "must not be zero");
  rep.front_direction = d.normalized();
  return rep;
}

template <int D>
void finish_slide_report(const SceneBuild<D>& b, const typename SceneBuild<D>::Slide& slide,
                         const std::optional<RestingFace<D>>& face, SlideReportOf<D>& rep) {
  const Particles<D>& P = b.sim->particles();
  // A particle on a plane of symmetry is its own image: half of it lies on the modelled side (one on two planes, a
  // quarter). Counted in quarters: whole numbers, summed across the processes of a scene built in parts.
  std::int64_t counts[2] = {0, 0};  // particles, quarters of them modelled
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] != Kind::fluid || P.phase[i] != slide.phase) continue;
    ++counts[0];
    std::int64_t quarters = 4;
    if constexpr (D == 3)
      for (const SymmetryPlane& plane : symmetry_planes(b.r))
        if (plane.holds(P.position[i], 1e-9 * b.dp)) quarters /= 2;
    counts[1] += quarters;
  }
  if (b.processes) b.processes->sum(counts, 2);
  rep.particles = static_cast<std::size_t>(counts[0]);
  rep.mass_particles = 0.25 * double(counts[1]) * rep.density * std::pow(b.dp, D);
  const double g = b.sim->options.gravity.norm();
  warn_if_rigid_at_rest(b, slide, b.phases.phases[slide.phase].rheology, rep);
  if (g > 0.0 && weight_density(b, slide, rep.density) < 0.0) {
    rep.floats_warning = fmt::format(
        "{}: its density ({:.4g} kg/m^3) is below the water's ({:.4g} kg/m^3) and it starts under water: it floats "
        "up rather than slides (the model carries it up as a light phase, as it would oil)",
        rep.key, rep.density, b.phases.phases[0].density);
    rep.criterion = "lighter than the water it starts in: it floats up; no yield criterion at rest";
    return;
  }
  if (!face || g == 0.0) {
    rep.criterion = "rests on no wall face: no yield criterion at rest";
    return;
  }
  yield_criterion_at_rest(b, slide, *face, rep);
}

#define SLIDE_BUILD_SLIDES(D)                                                                                    \
  template SlideReportOf<D> add_slide_phase(SceneBuild<D>&, const YAML::Node&, const std::string&, RheologyModel); \
  template void finish_slide_report(const SceneBuild<D>&, const typename SceneBuild<D>::Slide&,                  \
                                    const std::optional<RestingFace<D>>&, SlideReportOf<D>&);
SLIDE_BUILD_SLIDES(2)
SLIDE_BUILD_SLIDES(3)
#undef SLIDE_BUILD_SLIDES

}  // namespace slide::cases
