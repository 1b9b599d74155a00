// Step: how the water starts. The sound speed (from the scene, or a multiple of sqrt(g H) of the deepest water), the
// hydrostatic start (columns compressed to the equilibrium column's spacing, floating bodies lowered with them), the
// domain, and the settled start (damped settling before t = 0, coupling/relaxation.hpp).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "cases/scene_build.hpp"
#include "cases/solid_shape.hpp"
#include "coupling/position_text.hpp"
#include "fluid/periodic.hpp"
#include "coupling/equilibrium_column.hpp"
#include "coupling/relaxation.hpp"
#include "fluid/hydrostatic_start.hpp"
#include "fluid/walls.hpp"

namespace slide::cases {
namespace {

// Gravity along -(last axis): y in 2-D, z in 3-D.
template <int D>
double downward_gravity(const SceneBuild<D>& b) { return -b.sim->options.gravity[D - 1]; }

// Floating bodies go down with the water they rest on (free bodies only: a prescribed one keeps its law).
template <int D>
void lower_free_bodies(SceneBuild<D>& b, const std::vector<double>& body_shift) {
  Particles<D>& P = b.particles();
  for (std::size_t k = 0; k < body_shift.size(); ++k) {
    if (body_shift[k] == 0.0 || b.bodies->motion[k].mode != BodyMotion::Mode::free) continue;
    if constexpr (D == 2) b.bodies->world.translate(int(k), rigid::Vec2(0.0, body_shift[k]));
    else b.bodies->world.translate(int(k), rigid::Vec3(0.0, 0.0, body_shift[k]));
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.body_of(i) == int(k)) P.position[i][D - 1] += body_shift[k];
  }
}

}  // namespace

template <int D>
void choose_sound_speed(SceneBuild<D>& b) {
  const YAML::Node& r = b.r;  // (b is of a dependent type: r's .as<T>() needs no 'template')
  FluidOptions<D>& opt = b.options();
  Scene<D>& scene = *b.scene;
  const double g = downward_gravity(b);
  // A lattice column's particles are dp apart on the square lattice, two rows apart on the hexagonal one.
  scene.deepest_water =
      deepest_water<D>(b.particles(), b.dp, b.close_packed ? 2.0 * row_spacing(opt.lattice, b.dp) : b.dp);
  if (b.processes) b.processes->max(&scene.deepest_water, 1);  // (each process's runs are whole: cases/build_share.hpp)
  const double c0_key = r["method"]["sound_speed"].as<double>();
  if (c0_key > 0.0) {
    opt.sound_speed = c0_key;
    scene.sound_speed_source = "method.sound_speed";
    return;
  }
  if (g <= 0.0 || scene.deepest_water <= 0.0)
    throw SceneError("method.sound_speed", "cannot default to a multiple of sqrt(g H) without downward gravity; set it");
  const double factor = r["method"]["sound_speed_factor"].as<double>();
  opt.sound_speed = factor * std::sqrt(g * scene.deepest_water);
  scene.sound_speed_source = fmt::format("{:g} sqrt(g H) (method.sound_speed_factor), H = {:.6g} m (deepest water), "
                                         "g = {:.6g} m/s^2",
                                         factor, scene.deepest_water, g);
}

// 3-D: the equation of state's gaps (the equilibrium column is a 2-D periodic slab so far).
template <int D>
void start_hydrostatic(SceneBuild<D>& b) {
  const double g = downward_gravity(b);
  if (b.initial_state == InitialState::settled && !(g > 0.0))
    throw SceneError("method.initial_state", "a settled start needs downward gravity");
  // The hexagonal lattice is compressed by settling alone (its columns are not the square lattice's runs).
  if (b.initial_state == InitialState::lattice || !(g > 0.0) || b.close_packed) return;
  const FluidOptions<D>& opt = b.sim->options;
  const double dp = b.dp, re = opt.re_over_dp * dp;
  const LatticeConstants lc = lattice_constants<D>(dp, re);
  const int rows = static_cast<int>(std::lround(b.scene->deepest_water / dp));
  const auto& water = b.phases.phases[0];
  const double still_level = std::isfinite(b.still_level) ? b.still_level : std::numeric_limits<double>::quiet_NaN();
  const EquationOfState eos(lc.n0, opt.sound_speed, opt.gamma);
  try {
    if constexpr (D == 2) {
      const EquilibriumColumn column = equilibrium_column(opt, water.density, water.viscosity, rows);
      b.scene->equilibrium = column;
      std::vector<double> body_shift;
      compress_hydrostatically<2>(b.particles(), dp, re, eos, g, true, column.gap_from_top, still_level, &body_shift);
      lower_free_bodies(b, body_shift);
    } else {
      std::vector<double> body_shift;
      std::optional<ColumnShare<D>> columns;
      if constexpr (D == 3)
        if (b.share) columns = ColumnShare<D>{[&](const Vec<D>& x) { return b.share->owns(x); }, b.processes};
      compress_hydrostatically<D>(b.particles(), dp, re, eos, g, true, {}, still_level, &body_shift,
                                  columns ? &*columns : nullptr);
      lower_free_bodies(b, body_shift);
    }
  } catch (const std::runtime_error& e) {
    throw SceneError("method.initial_state", std::string("hydrostatic start failed: ") + e.what());
  }
}

// The scene's domain, or the particles' bounding box as placed enlarged by 4 re on every side and by half its
// height upwards. A fluid particle that leaves it through an open side is taken out of the run; the walls' faces,
// as thick as their particle layers, tell one that went through a wall (fluid/wall_crossing.hpp).
template <int D>
void set_domain(SceneBuild<D>& b) {
  const YAML::Node& r = b.r;  // (b is of a dependent type: r's .as<T>() needs no 'template')
  FluidOptions<D>& opt = b.options();
  const Particles<D>& P = b.particles();
  const double re = opt.re_over_dp * b.dp;
  // (A checkpoint's scene resolved before the key existed has no processes map: the default.)
  if (r["processes"] && r["processes"]["rebalance_imbalance"])
    opt.rebalance_imbalance = r["processes"]["rebalance_imbalance"].as<double>();
  if (!r["domain"]) {
    opt.domain_lo = b.lo - Vec<D>::Constant(4 * re);
    opt.domain_hi = b.hi + Vec<D>::Constant(4 * re) + Vec<D>::Unit(D - 1) * (0.5 * (b.hi[D - 1] - b.lo[D - 1]));
  } else {
    opt.domain_lo = vec_of<D>(r["domain"]["min"]);
    opt.domain_hi = vec_of<D>(r["domain"]["max"]);
    for (std::size_t i = 0; i < P.size(); ++i)
      for (int k = 0; k < D; ++k)
        if (P.position[i][k] < opt.domain_lo[k] || P.position[i][k] > opt.domain_hi[k])
          throw SceneError("domain", fmt::format("particle at {} lies outside the domain", position_text<D>(P.position[i])));
    opt.periodic_x = b.period_x;
  }
  if constexpr (D == 3) {
    opt.mirrors.clear();
    for (const SymmetryPlane& s : symmetry_planes(r)) {  // each plane once, however many tanks name it
      const MirrorPlane m = s.mirror();
      const bool named = std::any_of(opt.mirrors.begin(), opt.mirrors.end(), [&](const MirrorPlane& o) {
        return o.axis == m.axis && o.at == m.at && o.keeps_above == m.keeps_above;
      });
      if (!named) opt.mirrors.push_back(m);
    }
  }
  b.sim->wall_crossing = WallCrossing<D>(crossing_faces(b), opt.domain_lo, opt.domain_hi, re);
}

namespace {
// The kinds of a scene's particles counted (again after gates are lifted): on several processes, or by the parts of a
// scene built in parts (cases/build_share.hpp), each its own particles', summed over all of them.
template <int D>
void count_kinds(Scene<D>& scene, const Particles<D>& P, const Communicator* processes) {
  std::int64_t counts[3] = {0, 0, 0};  // fluid, wall, dummy
  for (std::size_t i = 0; i < P.real_count(); ++i)
    ++counts[P.kind[i] == Kind::fluid ? 0 : P.kind[i] == Kind::wall ? 1 : 2];
  if (processes) processes->sum(counts, 3);
  scene.fluid_count = static_cast<std::size_t>(counts[0]);
  scene.wall_count = static_cast<std::size_t>(counts[1]);
  scene.dummy_count = static_cast<std::size_t>(counts[2]);
}
}  // namespace

template <int D>
void count_particles(Scene<D>& scene) {
  const Domain<D>& domain = scene.simulation->domain();
  count_kinds(scene, scene.simulation->particles(), domain.distributed() ? domain.communicator() : nullptr);
}

template <int D>
void count_particles(SceneBuild<D>& b) {
  count_kinds(*b.scene, b.particles(), b.processes);
}

// A scene built in parts (cases/build_share.hpp): once no step reads across columns, each process keeps its own
// columns' particles (their storage shrunk to them).
template <int D>
void keep_own_columns(SceneBuild<D>& b) {
  if constexpr (D == 3) {
    if (!b.share) return;
    Particles<D>& P = b.particles();
    P.remove_keeping_ids([&](std::size_t i) { return !b.share->owns(P.position[i]); });
    P.removed_count = 0;  // the others hold them
    P.for_each_array([](auto& v) { v.shrink_to_fit(); });
    b.boundary_count = static_cast<std::size_t>(std::count_if(P.kind.begin(), P.kind.end(),
                                                              [](Kind k) { return k != Kind::fluid; }));
  }
}

// Settling is for water at rest: water that flows while it settles (a column that nothing holds) would start the
// run from wherever the damped flow left it. Water at rest moves only as it compresses under its own weight, which
// lowers its surface by about H g H / (2 c0^2) = H / 200 at the default c0, and as its surface rows find their
// places (measured: 2.9 dp in the 0.5 m still tank, 2.0 dp in the dam-break column behind a gate, 1.0 dp around
// the floating block; the dam-break column without its gate: 66 dp). Only Newtonian phases are checked: sediment
// settles as a fluid by design (coupling/relaxation.hpp) and may slump where it lies on a slope (measured: 10 dp
// for the Mohr-Coulomb layer on its slope in tests/test_sediment_block.cpp).
namespace {
// What refuses water that moved further than water at rest does (its message), or nothing: at the end of the settling,
// or by `time` s of it (a check while it settles: coupling/relaxation.hpp, refuse_if_not_at_rest).
template <int D>
std::optional<std::string> flowing_water(const Relaxation& s, const Simulation<D>& sim, double dp, double deepest_water,
                                         std::optional<double> time) {
  const double limit_dp = 5.0 + 0.01 * deepest_water / dp;
  for (std::size_t ph = 0; ph < s.largest_shift_by_phase.size(); ++ph) {
    const double shift_dp = s.largest_shift_by_phase[ph] / dp;
    if (!std::holds_alternative<Newtonian>(sim.phases[ph].rheology) || shift_dp <= limit_dp) continue;
    const std::string when =
        time ? fmt::format("by t = {:.3g} s of its {:.3g} s of settling", *time, s.duration) : "while it settled";
    return fmt::format("the {} moved up to {:.3g} dp {} ({}; water at rest moves less than {:.3g} dp): it is not at "
                       "rest; hold it while it settles with a gate (walls[].gate), or start it without settling "
                       "(initial_state: lattice, or hydrostatic with lattice: square)",
                       sim.phases[ph].name, shift_dp, when, s.largest_shift_where_by_phase.at(ph), limit_dp);
  }
  return std::nullopt;
}

template <int D>
void refuse_flowing_water(const Scene<D>& scene) {
  const auto why = flowing_water(*scene.settling, *scene.simulation, scene.particle_spacing, scene.deepest_water,
                                 std::nullopt);
  if (why) throw SceneError("method.initial_state", *why);
}

// After settling (or without it), the gates go.
template <int D>
void lift_gates(Scene<D>& scene) {
  if (scene.pending_gate_ids.empty()) return;
  Simulation<D>& sim = *scene.simulation;
  std::vector<ParticleId> gates = scene.pending_gate_ids;
  std::sort(gates.begin(), gates.end());
  sim.remove_particles(gates);
  scene.gate_particles = scene.pending_gate_ids.size();
  scene.pending_gate_ids.clear();
  count_particles(scene);
  sim.initialise();
}
}  // namespace

// What the settled start settles: its duration and damping, and the deformable slides held while the water settles
// around them, like rigid ones, free along the normal of the face they rest on (coupling/relaxation.hpp).
template <int D>
void plan_settling(SceneBuild<D>& b) {
  const YAML::Node& r = b.r;  // (b is of a dependent type: r's .as<T>() needs no 'template')
  b.scene->particle_spacing = b.dp;
  b.scene->pending_gate_ids = b.gate_ids;
  if (b.initial_state != InitialState::settled) return;
  const YAML::Node m = r["method"];
  SettlingPlan<D> plan{m["settling_time"].as<double>(), m["settling_damping"].as<double>(), {}, {}};
  // Checked as it settles too, so that water not at rest is refused when it is found, not at the end.
  plan.refuse_if_not_at_rest = [sim = b.sim.get(), dp = b.dp, deepest = b.scene->deepest_water](
                                   const Relaxation& so_far, double time) {
    if (const auto why = flowing_water(so_far, *sim, dp, deepest, time)) throw std::runtime_error(*why);
  };
  const Vec<D>& g = b.sim->options.gravity;
  const Vec<D> down = g.norm() > 0.0 ? Vec<D>(g.normalized()) : Vec<D>(-Vec<D>::Unit(D - 1));
  for (const auto& s : b.slides) {
    const auto face = resting_face_of(b, s);
    plan.held.push_back({static_cast<std::uint8_t>(s.phase), face ? Vec<D>(-face->normal) : down});
  }
  b.scene->pending_settling = plan;
}

template <int D>
void complete_start(Scene<D>& scene, const std::optional<Relaxation>& settled) {
  scene.pending_settling.reset();
  if (settled) {
    scene.settling = *settled;
    refuse_flowing_water(scene);
  }
  lift_gates(scene);
}

template <int D>
void settle_now(Scene<D>& scene) {
  std::optional<Relaxation> settled;
  if (scene.pending_settling) {
    try {
      settled = relax_at_rest(*scene.simulation, *scene.pending_settling);
    } catch (const std::runtime_error& e) {
      throw SceneError("method.initial_state", e.what());
    }
  }
  complete_start(scene, settled);
}

#define SLIDE_INITIAL_STATE_STEPS(D)                                               \
  template void choose_sound_speed(SceneBuild<D>&);                               \
  template void start_hydrostatic(SceneBuild<D>&);                                \
  template void set_domain(SceneBuild<D>&);                                       \
  template void count_particles(SceneBuild<D>&);                                  \
  template void keep_own_columns(SceneBuild<D>&);                                 \
  template void plan_settling(SceneBuild<D>&);                                    \
  template void complete_start(Scene<D>&, const std::optional<Relaxation>&);      \
  template void settle_now(Scene<D>&);
SLIDE_INITIAL_STATE_STEPS(2)
SLIDE_INITIAL_STATE_STEPS(3)
#undef SLIDE_INITIAL_STATE_STEPS

}  // namespace slide::cases
