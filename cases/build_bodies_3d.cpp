// Steps: the bodies of a 3-D scene (bodies[], dimension: 3). A body is a Bullet solid in six degrees of freedom
// (rigid/rigid_world.hpp: mass, centre of mass and inertia tensor from its closed surface, rigid/polyhedron.hpp) whose
// boundary particles (a wall layer half a spacing inside its surface, dummies behind it) move with it and exchange
// forces with the fluid (coupling/rigid_bodies.hpp). Boxes so far.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "cases/body_choices.hpp"
#include "cases/scene_build.hpp"
#include "coupling/position_text.hpp"
#include "fluid/walls.hpp"

namespace slide::cases {
namespace {

// R = Rz(yaw) Ry(pitch) Rx(roll), from shape.angles = [roll, pitch, yaw] in degrees (bodies.csv's convention).
rigid::Mat3 box_axes(const YAML::Node& shape) {
  const Vec<3> a = vec_of<3>(shape["angles"]) * (M_PI / 180.0);
  return rigid::Mat3(Eigen::AngleAxisd(a[2], Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(a[1], Eigen::Vector3d::UnitY()) *
                     Eigen::AngleAxisd(a[0], Eigen::Vector3d::UnitX()));
}

rigid::TriangleSurface body_surface(const YAML::Node& bn, const std::string& path) {
  const YAML::Node sh = bn["shape"];
  const Vec<3> size = vec_of<3>(sh["size"]);
  if (!(size.minCoeff() > 0.0)) throw SceneError(path + ".shape.size", "every edge length must be positive");
  return rigid::box_surface(vec_of<3>(sh["center"]), size, box_axes(sh));
}

// Mass from density or mass, and the inertia tensor from the surface (uniform density).
rigid::SolidSpec solid_spec(const YAML::Node& bn, const rigid::TriangleSurface& surface, const std::string& path) {
  const rigid::MassProperties m = rigid::mass_properties(surface);
  const double density_key = bn["density"].as<double>(), mass_key = bn["mass"].as<double>();
  if ((density_key > 0) == (mass_key > 0))
    throw SceneError(path + ".density", "give exactly one of density and mass, both positive");
  rigid::SolidSpec spec;
  spec.hull = surface;
  spec.centre_of_mass = m.centroid;
  spec.mass = mass_key > 0 ? mass_key : density_key * m.volume;
  spec.inertia = (spec.mass / m.volume) * m.inertia;
  spec.friction = bn["friction"].as<double>();
  spec.restitution = bn["restitution"].as<double>();
  static constexpr const char* components[] = {"x", "y", "z", "rx", "ry", "rz"};
  for (const auto& l : bn["locked"])
    for (int k = 0; k < 6; ++k) spec.locked[k] = spec.locked[k] || l.as<std::string>() == components[k];
  // Bullet's angular factor masks a torque's world components, but the inertia tensor and the gyroscopic term still
  // turn a body about a locked axis when it spins about another (measured: a box with ry locked spinning about x and
  // z reached w_y = 0.46 rad/s): rotations are locked all three or none until a constraint holds single ones.
  if (spec.locked[3] != spec.locked[4] || spec.locked[3] != spec.locked[5])
    throw SceneError(path + ".locked", "lock the rotations rx, ry and rz all together or none of them (a single "
                                       "rotation lock is not held in 3-D yet)");
  return spec;
}

// Boundary points of a box body in its own frame: the points (i + 1/2) h_a along each axis (h_a = its edge over
// round(edge / dp), so the wall layer lies h_a / 2 inside each face) within `layers` grid layers of its surface. A
// point's layer is its least layer index over the axes; behind one face (one axis at that index) its normal is that
// face's outward normal and its depth the distance to it; in the same layer behind two or three faces (along an edge
// or at a corner of the layer) its normal points to that edge or corner and its depth is the distance to it, so that
// its mirror image lies in the fluid's corner, as the tanks' walls do (fluid/box_walls.hpp) and the mitred corners of
// 2-D outlines.
std::vector<BoundaryPointOf<3>> box_body_points(const Vec<3>& size, const rigid::Mat3& axes, const Vec<3>& centre,
                                                double dp, int layers) {
  std::array<long, 3> n{};
  Vec<3> h;
  for (int a = 0; a < 3; ++a) {
    n[a] = std::max(1L, std::lround(size[a] / dp));
    h[a] = size[a] / double(n[a]);
  }
  const double eps = 1e-9 * dp;
  std::vector<BoundaryPointOf<3>> out;
  for (long i = 0; i < n[0]; ++i)
    for (long j = 0; j < n[1]; ++j)
      for (long k = 0; k < n[2]; ++k) {
        const Vec<3> local((i + 0.5) * h[0] - 0.5 * size[0], (j + 0.5) * h[1] - 0.5 * size[1],
                           (k + 0.5) * h[2] - 0.5 * size[2]);
        Vec<3> to_face;  // per axis: the distance to the nearer face, signed by its side
        std::array<long, 3> index{};  // per axis: the grid layer, 0 next to the face
        for (int a = 0; a < 3; ++a) {
          const long cell = a == 0 ? i : a == 1 ? j : k;
          to_face[a] = std::copysign(0.5 * size[a] - std::abs(local[a]), local[a]);
          index[a] = std::min(cell, n[a] - 1 - cell);
        }
        const long layer = std::min({index[0], index[1], index[2]});
        if (layer >= layers) continue;
        Vec<3> out_dir = Vec<3>::Zero();
        for (int a = 0; a < 3; ++a)
          if (index[a] == layer) out_dir[a] = to_face[a];
        out.push_back({centre + axes * local, Vec<3>(axes * out_dir.normalized()), out_dir.norm(), int(layer)});
      }
  return out;
}

// Every vertex inside a tank (when the scene has tanks): a body behind a wall would hold water on both sides of it.
void check_inside_tanks(const SceneBuild<3>& b, const rigid::TriangleSurface& surface, const std::string& path) {
  if (b.tanks.empty()) return;
  for (const auto& v : surface.vertices) {
    bool inside = false;
    for (const auto& [lo, hi] : b.tanks)
      inside = inside || (v[0] >= lo[0] && v[0] <= hi[0] && v[1] >= lo[1] && v[1] <= hi[1] && v[2] >= lo[2]);
    if (!inside)
      throw SceneError(path + ".shape", fmt::format("corner {} lies outside every tank", position_text<3>(Vec<3>(v))));
  }
}

// The rigid world, with each tank's floor and sides as static boxes 10 dp thick when bodies collide with the walls.
std::shared_ptr<RigidBodies<3>> make_rigid_world(const SceneBuild<3>& b) {
  auto bodies = std::make_shared<RigidBodies<3>>(b.sim->options.gravity,
                                                 b.r["rigid"]["collision_margin"].as<double>() * b.dp);
  if (!b.r["rigid"]["wall_contact"].as<bool>()) return bodies;
  const double t = 10.0 * b.dp;
  for (const auto& [lo, hi] : b.tanks) {
    const Vec<3> outer_lo = lo - Vec<3>::Constant(t);
    Vec<3> outer_hi = hi + Vec<3>::Constant(t);
    outer_hi[2] = hi[2];
    auto add = [&](Vec<3> a, Vec<3> c) { bodies->world.add_static_box(a, c, 1.0, 1.0); };
    add(outer_lo, Vec<3>(outer_hi[0], outer_hi[1], lo[2]));                      // floor
    add(outer_lo, Vec<3>(lo[0], outer_hi[1], hi[2]));                           // -x
    add(Vec<3>(hi[0], outer_lo[1], outer_lo[2]), outer_hi);                      // +x
    add(outer_lo, Vec<3>(outer_hi[0], lo[1], hi[2]));                           // -y
    add(Vec<3>(outer_lo[0], hi[1], outer_lo[2]), outer_hi);                      // +y
  }
  return bodies;
}

// How far up a body of mass m must move to float at level L: the s at which rho_w V_below(surface + s e_z, L) = m, by
// bisection (the volume below grows monotonically as the body goes down).
double rise_to_draft(const rigid::TriangleSurface& surface, double mass, double water_density, double level) {
  double top = -std::numeric_limits<double>::infinity(), bottom = -top;
  for (const auto& v : surface.vertices) top = std::max(top, v[2]), bottom = std::min(bottom, v[2]);
  const auto displaced = [&](double s) { return water_density * rigid::volume_below(surface, level - s); };
  double lo = level - top, hi = level - bottom;  // fully submerged at lo, dry at hi
  for (int k = 0; k < 100 && hi - lo > 1e-12 * std::max(1.0, std::abs(hi)); ++k) {
    const double mid = 0.5 * (lo + hi);
    (displaced(mid) > mass ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

// As in 2-D (build_bodies.cpp, place_floating_bodies): a free body lighter than water that floats while the water
// settles starts at its Archimedes draft (heave only), so that the water is laid around it there.
void place_floating_bodies(SceneBuild<3>& b) {
  const double level = stated_still_level(b.r);
  const Vec<3> g = vec_of<3>(b.r["gravity"]);
  if (!std::isfinite(level) || !(g[2] < 0.0 && g[0] == 0.0 && g[1] == 0.0)) return;
  const double water_density = b.r["fluid"]["phases"][0]["density"].as<double>();
  YAML::Node bodies = b.r["bodies"];  // shares the resolved scene: run.json states where the body was run from
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    YAML::Node bn = bodies[k];
    if (bn["during_settling"].as<std::string>() != to_string(DuringSettling::free)) continue;
    const std::string path = fmt::format("bodies[{}]", k);
    const rigid::TriangleSurface surface = body_surface(bn, path);
    const double mass = solid_spec(bn, surface, path).mass;
    if (mass >= water_density * rigid::mass_properties(surface).volume) continue;  // it sinks
    const double rise = rise_to_draft(surface, mass, water_density, level);
    if (std::abs(rise) < 1e-9 * b.dp) continue;
    YAML::Node centre = bn["shape"]["center"];
    centre[2] = centre[2].as<double>() + rise;
    b.moved_to_draft.emplace_back(path, rise);
  }
}

void build_slides_and_bodies(SceneBuild<3>& b) {
  const YAML::Node list = b.r["bodies"];
  if (list.size() == 0) return;
  b.bodies = make_rigid_world(b);
  Particles<3>& P = b.particles();
  std::map<std::string, std::size_t> names;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const YAML::Node bn = list[k];
    const std::string path = fmt::format("bodies[{}]", k);
    const std::string name = unique_body_name(names, bn, k);
    const rigid::TriangleSurface surface = body_surface(bn, path);
    check_inside_tanks(b, surface, path);
    const rigid::SolidSpec spec = solid_spec(bn, surface, path);
    BodyMotion motion;
    motion.release_time = bn["release_time"].as<double>();
    motion.free_while_settling =
        during_settling_names.parse(bn["during_settling"].as<std::string>()) == DuringSettling::free;
    if (motion.free_while_settling && motion.release_time > 0.0)
      throw SceneError(path + ".during_settling", "free contradicts release_time > 0 (which holds the body)");
    if (motion.free_while_settling && b.initial_state != InitialState::settled)
      throw SceneError(path + ".during_settling", "free needs method.initial_state: settled (there is no settling "
                                                  "otherwise)");
    const rigid::Mat3 axes = box_axes(bn["shape"]);
    int body = 0;
    try {
      body = b.bodies->add(name, spec, motion, spec.mass / rigid::mass_properties(surface).volume,
                           rigid::Quat(Eigen::Quaterniond(Eigen::Matrix3d(axes))));
    } catch (const std::invalid_argument& e) {
      throw SceneError(path + ".shape", e.what());
    }
    const Vec<3> c = spec.centre_of_mass;
    const double density = spec.mass / rigid::mass_properties(surface).volume;
    BodyReportOf<3> rep;
    rep.name = name;
    rep.motion = "free";
    rep.area = rigid::mass_properties(surface).volume;
    rep.mass = spec.mass;
    rep.inertia = spec.inertia.trace() / 3.0;
    rep.placed = c;
    rep.free_while_settling = motion.free_while_settling;
    for (const auto& [moved, rise] : b.moved_to_draft)
      if (moved == path) rep.moved_to_draft = rise;
    const auto pts = box_body_points(vec_of<3>(bn["shape"]["size"]), axes, vec_of<3>(bn["shape"]["center"]), b.dp,
                                     boundary_layers(b.sim->options.re_over_dp));
    for (const auto& bp : pts) {
      const std::size_t i = P.add(bp.position, bp.layer == 0 ? Kind::wall : Kind::dummy, 0, density, 0.0);
      P.wall_normal[i] = bp.normal;
      P.wall_depth[i] = bp.depth;
      P.attach_to_body(i, body, bp.position - c, bp.normal);
      b.boundary_owner.push_back(path);
    }
    rep.particles = pts.size();
    b.scene->bodies.push_back(rep);
    b.solids.push_back(surface);
  }
}

// Whether p lies inside a body or within dp/2 of its surface: no water there (the body's wall layer lies dp/2
// inside it, and water keeps 0.75 dp from boundary particles: check_overlaps).
int body_near(const SceneBuild<3>& b, const Vec<3>& p) {
  for (std::size_t k = 0; k < b.solids.size(); ++k)
    if (rigid::inside_convex(b.solids[k], p) || rigid::distance_to_surface(b.solids[k], p) < 0.5 * b.dp - 1e-9 * b.dp)
      return static_cast<int>(k);
  return -1;
}

void finish_bodies(SceneBuild<3>& b) {
  if (b.solids.empty()) return;
  for (auto& rep : b.scene->bodies) {
    rep.displaced_area = std::isfinite(b.still_level) ? rigid::volume_below(b.solids[&rep - &b.scene->bodies[0]],
                                                                            b.still_level)
                                                      : 0.0;
    rep.buoyancy_ratio =
        std::isfinite(b.still_level) ? b.phases.phases[0].density * rep.displaced_area / rep.mass : NAN;
  }
  b.sim->attach_bodies(std::move(b.bodies));
  b.scene->body_sample_interval = b.r["output"]["body_interval"].as<double>();
}

}  // namespace slide::cases
