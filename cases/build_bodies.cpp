// Step: the bodies (bodies[]). A slide or floating body is declared once with its outline; its `model` decides what
// fills the outline (build_slides_and_bodies). model rigid: a Bullet rigid body (mass and inertia from the outline,
// free or prescribed motion) whose boundary particles (wall layer + dummies inside the outline) exchange forces with
// the fluid. Also the bodies' report for `slide check`.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

#include "cases/body_choices.hpp"
#include "cases/body_model.hpp"
#include "cases/csv_table.hpp"
#include "cases/scene_build.hpp"
#include "fluid/walls.hpp"

namespace slide::cases {
namespace {

// rad: the orientation a body's scene states, a box's shape.angle; an outline given by its points is at angle 0.
double placed_angle(const YAML::Node& bn) {
  const YAML::Node sh = bn["shape"];
  return sh["type"].as<std::string>() == "box" ? sh["angle"].as<double>() * M_PI / 180.0 : 0.0;
}

// Reads a prescribed-motion series: a CSV with a header naming at least time, x, y, angle (vx, vy, omega and body
// optional), as bodies.csv has them.
rigid::PrescribedMotion read_motion_series(const std::filesystem::path& file, const std::string& body,
                                           const std::string& key, double placed_angle) {
  CsvTable t;
  try {
    t = read_csv(file);
  } catch (const std::runtime_error&) {
    throw SceneError(key, "cannot read " + file.string());
  }
  const int ct = t.find_column("time"), cx = t.find_column("x"), cy = t.find_column("y"),
            ca = t.find_column("angle"), cvx = t.find_column("vx"), cvy = t.find_column("vy"),
            cw = t.find_column("omega"), cb = t.find_column("body");
  if (ct < 0 || cx < 0 || cy < 0 || ca < 0)
    throw SceneError(key, file.string() + ": the header must name the columns time, x, y and angle");
  const bool has_velocity = cvx >= 0 && cvy >= 0 && cw >= 0;
  std::vector<rigid::MotionSample> samples;
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    const auto& f = t.rows[k];
    if (cb >= 0 && (cb >= int(f.size()) || f[cb] != body)) continue;
    try {
      rigid::MotionSample m;
      m.time = std::stod(f.at(ct));
      m.state.position = rigid::Vec2(std::stod(f.at(cx)), std::stod(f.at(cy)));
      m.state.angle = std::stod(f.at(ca)) - placed_angle;  // the series states absolute angles, as bodies.csv
      if (has_velocity) {
        m.state.velocity = rigid::Vec2(std::stod(f.at(cvx)), std::stod(f.at(cvy)));
        m.state.angular_velocity = std::stod(f.at(cw));
      }
      // Repeated times (a run's last row written twice) keep the first.
      if (!samples.empty() && m.time <= samples.back().time) continue;
      samples.push_back(m);
    } catch (const std::exception&) {
      throw SceneError(key, fmt::format("{}: row {} is not numeric", file.string(), t.line_numbers[k]));
    }
  }
  if (samples.size() < 2)
    throw SceneError(key, fmt::format("{}: fewer than two rows for body \"{}\"", file.string(), body));
  return rigid::PrescribedMotion::from_samples(std::move(samples), has_velocity);
}

// The Bullet world, with the wall faces as static segments when bodies collide with the walls.
std::shared_ptr<RigidBodies<2>> make_rigid_world(const SceneBuild<2>& b) {
  auto bodies = std::make_shared<RigidBodies<2>>(b.sim->options.gravity,
                                              b.r["rigid"]["collision_margin"].as<double>() * b.dp);
  if (b.r["rigid"]["wall_contact"].as<bool>())
    for (const auto& f : b.faces)
      bodies->world.add_static_segment(to_rigid(f.a), to_rigid(f.b), to_rigid(-f.inward), 10.0 * b.dp, 1.0, 1.0);
  return bodies;
}

void check_in_front_of_walls(const SceneBuild<2>& b, const std::vector<rigid::Vec2>& outline, const std::string& path) {
  for (const auto& v : outline)
    if (!b.faces.empty() && signed_face_distance(b.faces, from_rigid(v)) < -1e-6 * b.dp)
      throw SceneError(path + ".shape", fmt::format("vertex ({:.6g}, {:.6g}) lies behind a wall face", v[0], v[1]));
}

// Mass and inertia per unit width from the outline and density or mass, friction, restitution, locked components.
rigid::BodySpec rigid_spec(const YAML::Node& bn, const std::vector<rigid::Vec2>& outline, const std::string& path) {
  const double area = rigid::signed_area(outline);
  const double density_key = bn["density"].as<double>(), mass_key = bn["mass"].as<double>();
  if ((density_key > 0) == (mass_key > 0))
    throw SceneError(path + ".density", "give exactly one of density and mass (per unit width), both positive");
  rigid::BodySpec spec;
  spec.outline = outline;
  spec.mass = mass_key > 0 ? mass_key : density_key * area;
  const double density = spec.mass / area;
  spec.inertia = density * rigid::polar_moment_about_centroid(outline);
  spec.friction = bn["friction"].as<double>();
  spec.restitution = bn["restitution"].as<double>();
  for (const auto& l : bn["locked"]) {
    spec.locked[static_cast<std::size_t>(locked_component_names.parse(l.as<std::string>()))] = true;
  }
  return spec;
}

// The law of a prescribed body (bodies[k].prescribed): a series from a CSV file, or ln_cosh.
rigid::PrescribedMotion read_prescribed(const SceneBuild<2>& b, const YAML::Node& bn, const std::string& path,
                                        const std::vector<rigid::Vec2>& outline) {
  if (!bn["prescribed"]) throw SceneError(path + ".prescribed", "motion: prescribed needs a prescribed map");
  const YAML::Node pr = bn["prescribed"];
  const rigid::Vec2 c = rigid::centroid(outline);
  if (prescribed_law_names.parse(pr["type"].as<std::string>()) == PrescribedLaw::ln_cosh) {
    const Vec<2> d = vec2(pr["direction"]);
    if (d.norm() == 0.0) throw SceneError(path + ".prescribed.direction", "must not be zero");
    return rigid::PrescribedMotion::ln_cosh(c, 0.0, to_rigid(d), pr["s0"].as<double>(), pr["t0"].as<double>(),
                                            pr["start_time"].as<double>());
  }
  const std::string file = pr["file"].as<std::string>();
  if (file.empty()) throw SceneError(path + ".prescribed.file", "a series needs a CSV file");
  const std::string name = bn["name"].as<std::string>();
  const std::string who = pr["body"].as<std::string>().empty() ? name : pr["body"].as<std::string>();
  const double placed = placed_angle(bn);
  const auto m = read_motion_series(b.scene_dir / file, who, path + ".prescribed.file", placed);
  const double end_time = b.r["end_time"].as<double>();
  if (m.first_time() > 1e-9 || m.last_time() < end_time - 1e-9)
    throw SceneError(path + ".prescribed.file",
                     fmt::format("the series covers [{:.6g}, {:.6g}] s, which must include [0, end_time = {:.6g}] s",
                                 m.first_time(), m.last_time(), end_time));
  const rigid::PlanarState s0 = m.at(0.0);
  if ((s0.position - c).norm() > 0.01 * b.dp || std::abs(s0.angle) > 1e-6)
    throw SceneError(path + ".prescribed.file",
                     fmt::format("the series starts at ({:.6g}, {:.6g}), angle {:.3g}, but the body's centre of "
                                 "mass is at ({:.6g}, {:.6g}), angle {:.3g}",
                                 s0.position[0], s0.position[1], s0.angle + placed, c[0], c[1], placed));
  return m;
}

// How the body moves: free or prescribed, held until release_time, held or free while the water settles.
BodyMotion read_motion(const SceneBuild<2>& b, const YAML::Node& bn, const std::string& path,
                       const std::vector<rigid::Vec2>& outline) {
  BodyMotion motion;
  motion.release_time = bn["release_time"].as<double>();
  motion.mode = BodyMotion::mode_names.parse(bn["motion"].as<std::string>());
  motion.free_while_settling =
      during_settling_names.parse(bn["during_settling"].as<std::string>()) == DuringSettling::free;
  if (motion.mode != BodyMotion::Mode::rail && bn["rail"])
    throw SceneError(path + ".rail", "applies to motion: rail only");
  if (motion.free_while_settling) {
    if (motion.mode != BodyMotion::Mode::free)
      throw SceneError(path + ".during_settling", "free needs motion: free (a prescribed body follows its law, a rail "
                                                  "body waits for its release)");
    if (motion.release_time > 0.0)
      throw SceneError(path + ".during_settling", "free contradicts release_time > 0 (which holds the body)");
    if (b.initial_state != InitialState::settled)
      throw SceneError(path + ".during_settling", "free needs method.initial_state: settled (there is no settling "
                                                  "otherwise)");
  }
  if (motion.mode == BodyMotion::Mode::rail) {  // as in 3-D (cases/build_bodies_3d.cpp read_rail), in the plane
    if (!bn["rail"]) throw SceneError(path + ".rail", "motion: rail needs a rail map (its direction)");
    if (bn["locked"].size() > 0)
      throw SceneError(path + ".locked", "applies to free motion only (a rail holds the rest)");
    const Vec<2> d = vec2(bn["rail"]["direction"]);
    if (!(d.norm() > 0.0)) throw SceneError(path + ".rail.direction", "must not be zero");
    motion.rail = rigid::Rail{{d[0] / d.norm(), d[1] / d.norm(), 0.0}, bn["rail"]["friction"].as<double>()};
  }
  if (motion.mode == BodyMotion::Mode::prescribed) motion.prescribed = read_prescribed(b, bn, path, outline);
  return motion;
}

// Boundary points of a body: the outline as a closed face with the fluid outside, layers inside. Acute corners (a
// wedge's tip): the first layer's mitred corner lies 0.5 dp / sin(angle / 2) inside the tip, which leaves the tip
// hollow, and fluid could slip into it. One more wall particle on the bisector, 0.55 dp nearer the tip, closes it.
std::vector<BoundaryPoint> body_boundary_points(const std::vector<rigid::Vec2>& outline, double dp, int layers) {
  std::vector<Vec<2>> face;
  for (const auto& v : outline) face.push_back(from_rigid(v));
  face.push_back(face.front());
  auto pts = polyline_boundary(face, false, dp, layers);
  for (std::size_t k = 0; k < outline.size(); ++k) {
    const Vec<2> v = from_rigid(outline[k]);
    const Vec<2> a = (from_rigid(outline[(k + outline.size() - 1) % outline.size()]) - v).normalized();
    const Vec<2> c = (from_rigid(outline[(k + 1) % outline.size()]) - v).normalized();
    const double angle = std::acos(std::clamp(a.dot(c), -1.0, 1.0));
    if (angle >= 0.5 * M_PI) continue;
    const Vec<2> inward = (a + c).normalized();
    const double s = 0.5 * dp / std::sin(0.5 * angle) - 0.55 * dp;
    if (s < 0.5 * dp) continue;
    pts.push_back({v + s * inward, -inward, s, 0});
  }
  return pts;
}

// The body's boundary particles (those inside the outline, none within dp/2 of another), moving with body `body`.
// Returns how many were added.
std::size_t add_body_particles(SceneBuild<2>& b, const std::vector<BoundaryPoint>& pts,
                               const std::vector<rigid::Vec2>& outline, int body, double density,
                               const std::string& path) {
  Particles<2>& P = b.particles();
  const double dp = b.dp;
  const Vec<2> c = from_rigid(rigid::centroid(outline));
  const std::size_t first = P.size();
  for (const auto& bp : pts) {
    bool duplicate = false;
    for (std::size_t i = first; i < P.size() && !duplicate; ++i)
      duplicate = distance_squared<2>(P.position[i], bp.position) < 0.25 * dp * dp;
    if (duplicate || !rigid::contains(outline, to_rigid(bp.position))) continue;
    const std::size_t i = P.add(bp.position, bp.layer == 0 ? Kind::wall : Kind::dummy, 0, density, 0.0);
    P.wall_normal[i] = bp.normal;
    P.wall_depth[i] = bp.depth;
    P.attach_to_body(i, body, bp.position - c, bp.normal);
    b.boundary_owner.push_back(path);
  }
  return P.size() - first;
}

// model: rigid. A Bullet body, its boundary particles, and its report.
void add_rigid_body(SceneBuild<2>& b, const YAML::Node& bn, const std::string& path,
                    const std::vector<rigid::Vec2>& outline) {
  rigid::BodySpec spec = rigid_spec(bn, outline, path);
  const BodyMotion motion = read_motion(b, bn, path, outline);
  spec.kinematic = motion.mode != BodyMotion::Mode::free;  // a rail body's one freedom is integrated outside Bullet
  const double area = rigid::signed_area(outline);
  const double density = spec.mass / area;
  const std::string name = bn["name"].as<std::string>();
  const int body = b.bodies->add(name, spec, motion, density, placed_angle(bn));
  const auto pts = body_boundary_points(outline, b.dp, boundary_layers(b.sim->options.re_over_dp));
  BodyReport rep;
  rep.name = name;
  rep.motion = std::string(BodyMotion::mode_names.name(motion.mode));
  rep.area = area;
  rep.mass = spec.mass;
  rep.inertia = spec.inertia;
  rep.particles = add_body_particles(b, pts, outline, body, density, path);
  rep.placed = from_rigid(rigid::centroid(outline));
  for (const auto& v : outline) rep.outline.push_back(from_rigid(v));
  rep.free_while_settling = motion.free_while_settling;
  for (const auto& [moved, rise] : b.moved_to_draft)
    if (moved == path) rep.moved_to_draft = rise;
  b.scene->bodies.push_back(rep);
}

// Mass and inertia summed over a dp lattice filling the outline, beside the outline's own, and the buoyancy at the
// still-water level.
void add_lattice_sums(BodyReport& rep, const std::vector<rigid::Vec2>& v, double dp, double level,
                      double water_density) {
  const double density = rep.mass / rep.area;
  const rigid::Vec2 c = rigid::centroid(v);
  rigid::Vec2 lo = v[0], hi = v[0];
  for (const auto& p : v) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  for (long j = long(std::floor(lo[1] / dp)) - 1; j <= long(std::ceil(hi[1] / dp)) + 1; ++j)
    for (long i = long(std::floor(lo[0] / dp)) - 1; i <= long(std::ceil(hi[0] / dp)) + 1; ++i) {
      const rigid::Vec2 p((i + 0.5) * dp, (j + 0.5) * dp);
      if (!rigid::contains(v, p)) continue;
      rep.mass_particles += density * dp * dp;
      rep.inertia_particles += density * dp * dp * (p - c).squaredNorm();
    }
  if (std::isfinite(level)) {
    rep.displaced_area = area_below(v, level);
    rep.buoyancy_ratio = water_density * rep.displaced_area / rep.mass;
  } else {
    rep.buoyancy_ratio = NAN;
  }
}

// A deformable slide: its phase and outline; its particles are placed with the water (fill_fluid_regions). Keys of
// the rigid model (mass, friction, motion, ...) are left as they are: switching back uses them again.
void add_deformable_slide(SceneBuild<2>& b, const YAML::Node& bn, const std::string& path,
                          const std::vector<rigid::Vec2>& outline, RheologyModel model) {
  SlideReport rep = add_slide_phase(b, bn, path, model);
  rep.volume = rigid::signed_area(outline);
  SceneBuild<2>::Slide slide{path, outline, rep.phase};
  for (const auto& v : outline) slide.vertices.push_back(from_rigid(v));
  slide.centroid = from_rigid(rigid::centroid(outline));
  b.slides.push_back(slide);
  b.scene->slides.push_back(rep);
}


}  // namespace

// The face a slide rests on (the steepest its outline lies along, theta its angle to the plane normal to gravity),
// and the layer the yield criterion takes: its top at the outline's vertex furthest from the face.
std::optional<RestingFace<2>> resting_face_of(const SceneBuild<2>& b, const SceneBuild<2>::Slide& slide) {
  const FluidOptions<2>& opt = b.sim->options;
  const double g = opt.gravity.norm();
  const Vec<2> down = g > 0.0 ? Vec<2>(opt.gravity / g) : Vec<2>(0.0, -1.0);
  const std::optional<FaceSegment> face = resting_face(b.faces, slide.outline, b.dp, down);
  if (!face) return std::nullopt;
  RestingFace<2> rest;
  const Vec<2> tangent = (face->b - face->a).normalized();
  rest.normal = face->inward;
  rest.slope_angle_deg = std::asin(std::min(1.0, std::abs(tangent.dot(down)))) * 180.0 / M_PI;
  rest.top = from_rigid(slide.outline[0]);
  const Vec<2> base0 = from_rigid(slide.outline[0]);
  for (const auto& v : slide.outline) {
    const double d = std::abs((from_rigid(v) - base0).dot(rest.normal));
    if (d > rest.thickness) rest.thickness = d, rest.top = from_rigid(v);
  }
  return rest;
}

std::vector<rigid::Vec2> body_outline(const YAML::Node& bn, const std::string& path) {
  std::vector<rigid::Vec2> outline;
  const YAML::Node sh = bn["shape"];
  if (sh["type"].as<std::string>() == "box") {
    const Vec<2> c = vec2(sh["center"]), size = vec2(sh["size"]);
    if (!(size[0] > 0 && size[1] > 0)) throw SceneError(path + ".shape.size", "width and height must be positive");
    const double a = placed_angle(bn), ca = std::cos(a), sa = std::sin(a);
    for (const auto& corner : {Vec<2>(-0.5, -0.5), Vec<2>(0.5, -0.5), Vec<2>(0.5, 0.5), Vec<2>(-0.5, 0.5)}) {
      const Vec<2> l(corner[0] * size[0], corner[1] * size[1]);
      outline.push_back(to_rigid(c + Vec<2>(ca * l[0] - sa * l[1], sa * l[0] + ca * l[1])));
    }
  } else if (sh["type"].as<std::string>() == "wedge") {
    const Vec<2> apex = vec2(sh["apex"]);
    const double leg = sh["leg"].as<double>(), s = sh["toward"].as<std::string>() == "+x" ? 1.0 : -1.0;
    for (const auto& v : {apex, Vec<2>(apex + Vec<2>(s * leg, 0.0)), Vec<2>(apex + Vec<2>(s * leg, -leg))})
      outline.push_back(to_rigid(v));
  } else {
    for (const auto& p : points_of(sh["points"])) outline.push_back(to_rigid(p));
  }
  outline = rigid::counter_clockwise(outline);
  if (!rigid::is_convex_ccw(outline)) throw SceneError(path + ".shape", "the outline must be a convex polygon");
  return outline;
}

// The decision point for what a body is made of: model rigid makes a Bullet body with boundary particles; any other
// model makes a deformable slide, a phase of its own (named after the body, of its density and rheology) whose
// particles fill the same outline (fill_fluid_regions). Everything else in the scene stays as it is.
void build_slides_and_bodies(SceneBuild<2>& b) {
  const YAML::Node list = b.r["bodies"];
  if (list.size() == 0) return;
  b.bodies = make_rigid_world(b);
  std::map<std::string, std::size_t> names;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const YAML::Node bn = list[k];
    const std::string path = fmt::format("bodies[{}]", k);
    const std::string name = unique_body_name(names, bn, k);
    const std::vector<rigid::Vec2> outline = body_outline(bn, path);
    check_in_front_of_walls(b, outline, path);
    const BodyModel model = body_model_names.parse(bn["model"].as<std::string>());
    if (const auto rheology = sediment_rheology(model)) {
      add_deformable_slide(b, bn, path, outline, *rheology);
      continue;
    }
    add_rigid_body(b, bn, path, outline);
    b.outlines.push_back(outline);
  }
}

std::string unique_body_name(std::map<std::string, std::size_t>& names, const YAML::Node& body, std::size_t k) {
  const std::string name = body["name"].as<std::string>();
  if (names.count(name)) throw SceneError(fmt::format("bodies[{}].name", k), "duplicate body name \"" + name + "\"");
  names[name] = k;
  return name;
}

// The still-water level the scene states: the highest below_level region's level (-infinity without one). The same
// as fill_fluid_regions sets as still_level, known before the walls and bodies are built.
double stated_still_level(const YAML::Node& r) {
  double level = -std::numeric_limits<double>::infinity();
  for (const auto& rn : r["fluid"]["regions"])
    if (rn["type"].as<std::string>() == "below_level") level = std::max(level, rn["level"].as<double>());
  return level;
}

namespace {

// How far up a body of mass m (per unit width) must move to float at level L: the s at which
// rho_w * area_below(outline + s, L) = m, by bisection (the area grows monotonically as the body goes down).
double rise_to_draft(const std::vector<rigid::Vec2>& outline, double mass, double water_density, double level) {
  double top = -std::numeric_limits<double>::infinity(), bottom = -top;
  for (const auto& v : outline) top = std::max(top, v[1]), bottom = std::min(bottom, v[1]);
  const auto displaced = [&](double s) {
    std::vector<rigid::Vec2> moved = outline;
    for (auto& v : moved) v[1] += s;
    return water_density * area_below(moved, level);
  };
  double lo = level - top, hi = level - bottom;  // fully submerged at lo, dry at hi
  for (int k = 0; k < 100 && hi - lo > 1e-12 * std::max(1.0, std::abs(hi)); ++k) {
    const double mid = 0.5 * (lo + hi);
    (displaced(mid) > mass ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

void move_shape_up(YAML::Node shape, double rise) {
  const std::string type = shape["type"].as<std::string>();
  const auto lift = [&](YAML::Node point) { point[1] = point[1].as<double>() + rise; };
  if (type == "box") lift(shape["center"]);
  else if (type == "wedge") lift(shape["apex"]);
  else
    for (YAML::Node p : shape["points"]) lift(p);
}

}  // namespace

// Why: water at rest on the lattice resists shear (coupling/relaxation.hpp), so a body floating with it while it
// settles stops where that strength holds it, not at its draft (measured, dp 0.005, boxes placed at the shipped
// floating case's height: 300 kg/m^3 +7.1 %, 700 kg/m^3 -3.4 % off Archimedes), and a user does not know a body's
// draft in advance. Archimedes on the outline gives it exactly (heave only: the body keeps its orientation).
void place_floating_bodies(SceneBuild<2>& b) {
  const double level = stated_still_level(b.r);
  const Vec<2> g = vec2(b.r["gravity"]);
  if (!std::isfinite(level) || !(g[1] < 0.0 && g[0] == 0.0)) return;  // the level is along y, below it is -y
  const double water_density = b.r["fluid"]["phases"][0]["density"].as<double>();
  YAML::Node bodies = b.r["bodies"];  // shares the resolved scene: run.json states where the body was run from
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    YAML::Node bn = bodies[k];
    if (bn["during_settling"].as<std::string>() != to_string(DuringSettling::free) ||
        bn["model"].as<std::string>() != "rigid" || bn["motion"].as<std::string>() != "free")
      continue;
    const std::string path = fmt::format("bodies[{}]", k);
    const std::vector<rigid::Vec2> outline = body_outline(bn, path);
    const double mass = rigid_spec(bn, outline, path).mass;
    if (mass >= water_density * rigid::signed_area(outline)) continue;  // it sinks: it settles onto what holds it
    const double rise = rise_to_draft(outline, mass, water_density, level);
    if (std::abs(rise) < 1e-9 * b.dp) continue;  // at its draft already: the scene's numbers stay as they are
    move_shape_up(bn["shape"], rise);
    b.moved_to_draft.emplace_back(path, rise);
  }
}

void finish_bodies(SceneBuild<2>& b) {
  for (std::size_t k = 0; k < b.slides.size(); ++k)
    finish_slide_report(b, b.slides[k], resting_face_of(b, b.slides[k]), b.scene->slides[k]);
  for (std::size_t k = 0; k < b.scene->bodies.size(); ++k)
    add_lattice_sums(b.scene->bodies[k], b.outlines[k], b.dp, b.still_level, b.phases.phases[0].density);
  if (b.outlines.empty()) return;
  b.sim->attach_bodies(std::move(b.bodies));
  b.scene->body_sample_interval = b.r["output"]["body_interval"].as<double>();
}

}  // namespace slide::cases
