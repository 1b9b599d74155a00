// Steps: the bodies of a 3-D scene (bodies[], dimension: 3). A body is a Bullet solid in six degrees of freedom
// (rigid/rigid_world.hpp: mass, centre of mass and inertia tensor from its closed surface, rigid/polyhedron.hpp) whose
// boundary particles (a wall layer half a spacing inside its surface, dummies behind it) move with it and exchange
// forces with the fluid (coupling/rigid_bodies.hpp). Boxes so far.
#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include "cases/body_choices.hpp"
#include "cases/body_model.hpp"
#include "cases/csv_table.hpp"
#include "cases/scene_build.hpp"
#include "cases/solid_shape.hpp"
#include "coupling/position_text.hpp"
#include "fluid/walls.hpp"

namespace slide::cases {
namespace {

// The shape of bodies[k] as the scene states it, cut by the symmetry planes; with its boundary points when
// `with_points`.
SolidShape body_shape(const SceneBuild<3>& b, const YAML::Node& bn, const std::string& path, bool with_points) {
  return solid_shape(bn["shape"], path, symmetry_planes(b.r), b.dp,
                     with_points ? boundary_layers(b.sim->options.re_over_dp) : 0, b.scene_dir);
}

// Mass from density or mass, and the inertia tensor from the surface (uniform density). A body cut by a symmetry
// plane is its part on the scene's side: `mass` states the whole body's, of which the part has its share of the volume.
rigid::SolidSpec solid_spec(const YAML::Node& bn, const SolidShape& shape, const std::string& path) {
  const rigid::TriangleSurface& surface = shape.surface;
  const rigid::MassProperties m = rigid::mass_properties(surface);
  const double density_key = bn["density"].as<double>(), mass_key = bn["mass"].as<double>();
  if ((density_key > 0) == (mass_key > 0))
    throw SceneError(path + ".density", "give exactly one of density and mass, both positive");
  rigid::SolidSpec spec;
  spec.hulls = {surface};
  spec.centre_of_mass = m.centroid;
  spec.mass = mass_key > 0 ? mass_key * (m.volume / shape.whole_volume) : density_key * m.volume;
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

// Every vertex inside a tank (when the scene has tanks): a body behind a wall would hold water on both sides of it.
void check_inside_tanks(const SceneBuild<3>& b, const rigid::TriangleSurface& surface, const std::string& path) {
  if (b.tanks.empty()) return;
  const double e = 1e-9 * b.dp;  // a cut body's cap lies on its symmetry face
  for (const auto& v : surface.vertices) {
    bool inside = false;
    for (const auto& [lo, hi] : b.tanks)
      inside = inside || (v[0] >= lo[0] - e && v[0] <= hi[0] + e && v[1] >= lo[1] - e && v[1] <= hi[1] + e &&
                          v[2] >= lo[2] - e);
    if (!inside)
      throw SceneError(path + ".shape", fmt::format("corner {} lies outside every tank", position_text<3>(Vec<3>(v))));
  }
}

// The angle of the rotation q, in [0, pi] (q and -q are one rotation).
double turn_angle(const rigid::Quat& q) {
  const double a = Eigen::AngleAxisd(q).angle();
  return std::min(a, 2.0 * M_PI - a);
}

// A body cut by a symmetry plane moves as its mirror image does: along the plane, without turning (rotations are
// locked all three or none). The scene says so: locked holds the plane's normal translation and rx, ry, rz; a
// prescribed body's direction lies in the plane.
void check_symmetry_locks(const SceneBuild<3>& b, const YAML::Node& bn, const SolidShape& shape,
                          const rigid::SolidSpec& spec, const BodyMotion& motion, const std::string& path) {
  if (!shape.cut()) return;
  for (const auto& plane : symmetry_planes(b.r)) {
    const bool on_it = std::any_of(shape.surface.vertices.begin(), shape.surface.vertices.end(), [&](const auto& v) {
      return std::abs(plane.normal.dot(Vec<3>(v)) - plane.offset) <= 1e-9 * b.dp;
    });
    if (!on_it) continue;
    if (motion.prescribed_3d && !motion.prescribed_3d->samples().empty()) {
      const auto& first = motion.prescribed_3d->samples().front();
      for (const auto& m : motion.prescribed_3d->samples())
        if (std::abs(plane.normal.dot(Vec<3>(m.position - first.position))) > 1e-9 * b.dp ||
            std::abs(plane.normal.dot(Vec<3>(m.velocity))) > 1e-6 || turn_angle(m.orientation) > 1e-9)
          throw SceneError(path + ".prescribed.file",
                           fmt::format("the symmetry plane {} cuts this body, which must then move along it without "
                                       "turning; at t = {:.6g} s the series leaves it or turns",
                                       plane.key, m.time));
      continue;
    }
    if (spec.kinematic) {
      const std::string moved_by = bn["rail"] ? "rail" : "prescribed";
      // The force across the rail would count the half body's push against the plane, which its mirror half cancels.
      if (bn["rail"] && bn["rail"]["friction"].as<double>() > 0.0)
        throw SceneError(path + ".rail.friction", fmt::format("the symmetry plane {} cuts this body: a rail's friction "
                                                              "on a cut body is not modelled yet (use 0)",
                                                              plane.key));
      const Vec<3> d = vec_of<3>(bn[moved_by]["direction"]);
      if (std::abs(plane.normal.dot(d)) > 1e-12 * d.norm())
        throw SceneError(path + "." + moved_by + ".direction",
                         fmt::format("the symmetry plane {} cuts this body, which must then move along it", plane.key));
      continue;
    }
    const int axis = plane.normal[0] != 0.0 ? 0 : 1;
    if (!spec.locked[axis] || !spec.locked[3])
      throw SceneError(path + ".locked", fmt::format("the symmetry plane {} cuts this body, which must then move along "
                                                     "it without turning: lock {} and rx, ry, rz",
                                                     plane.key, "xy"[axis]));
  }
}

// A body on a rail (bodies[k].rail): its direction made unit, its friction.
rigid::Rail read_rail(const YAML::Node& bn, const std::string& path) {
  if (!bn["rail"]) throw SceneError(path + ".rail", "motion: rail needs a rail map (its direction)");
  if (bn["locked"].size() > 0)
    throw SceneError(path + ".locked", "applies to free motion only (a rail holds the rest)");
  const Vec<3> d = vec_of<3>(bn["rail"]["direction"]);
  if (!(d.norm() > 0.0)) throw SceneError(path + ".rail.direction", "must not be zero");
  rigid::Rail rail;
  for (int a = 0; a < 3; ++a) rail.direction[a] = d[a] / d.norm();
  rail.friction = bn["rail"]["friction"].as<double>();
  return rail;
}

// A 3-D prescribed series (bodies[k].prescribed.file): a CSV whose header names at least time, x, y, z, qw, qx, qy, qz
// (the centre of mass and the orientation as the scene states it, as bodies.csv has them; vx, vy, vz and body
// optional). Its orientations are made Bullet's, counted from the body's creation at `placed`: q placed^-1.
rigid::SpatialPrescribedMotion read_pose_series(const std::filesystem::path& file, const std::string& body,
                                                const std::string& key, const rigid::Quat& placed) {
  CsvTable t;
  try {
    t = read_csv(file);
  } catch (const std::runtime_error&) {
    throw SceneError(key, "cannot read " + file.string());
  }
  std::array<int, 8> pose{};
  const std::array<const char*, 8> pose_names{"time", "x", "y", "z", "qw", "qx", "qy", "qz"};
  for (std::size_t c = 0; c < pose.size(); ++c)
    if ((pose[c] = t.find_column(pose_names[c])) < 0)
      throw SceneError(key, file.string() + ": the header must name the columns time, x, y, z, qw, qx, qy and qz");
  const int cvx = t.find_column("vx"), cvy = t.find_column("vy"), cvz = t.find_column("vz"),
            cb = t.find_column("body");
  const bool has_velocity = cvx >= 0 && cvy >= 0 && cvz >= 0;
  std::vector<rigid::SpatialSample> samples;
  for (std::size_t k = 0; k < t.rows.size(); ++k) {
    const auto& f = t.rows[k];
    if (cb >= 0 && (cb >= int(f.size()) || f[cb] != body)) continue;
    rigid::SpatialSample m;
    try {
      const auto cell = [&](int c) { return std::stod(f.at(static_cast<std::size_t>(c))); };
      m.time = cell(pose[0]);
      m.position = rigid::Vec3(cell(pose[1]), cell(pose[2]), cell(pose[3]));
      m.orientation = rigid::Quat(cell(pose[4]), cell(pose[5]), cell(pose[6]), cell(pose[7]));
      if (has_velocity) m.velocity = rigid::Vec3(cell(cvx), cell(cvy), cell(cvz));
    } catch (const std::exception&) {
      throw SceneError(key, fmt::format("{}: row {} is not numeric", file.string(), t.line_numbers[k]));
    }
    const double norm = m.orientation.norm();
    if (!(std::abs(norm - 1.0) <= 1e-3))
      throw SceneError(key, fmt::format("{}: row {}: the quaternion (qw, qx, qy, qz) has length {:.6g}, not 1",
                                        file.string(), t.line_numbers[k], norm));
    m.orientation = rigid::Quat(m.orientation.normalized() * placed.conjugate());
    // Repeated times (a run's last row written twice) keep the first.
    if (!samples.empty() && m.time <= samples.back().time) continue;
    samples.push_back(m);
  }
  if (samples.size() < 2)
    throw SceneError(key, fmt::format("{}: fewer than two rows for body \"{}\"", file.string(), body));
  return rigid::SpatialPrescribedMotion::from_samples(std::move(samples), has_velocity);
}

// A series must cover the run and start where the body is put: its centre of mass within 0.01 dp, its orientation
// within 1e-6 rad.
void check_series_start(const SceneBuild<3>& b, const rigid::SpatialPrescribedMotion& m, const Vec<3>& start,
                        const rigid::Quat& placed, const std::string& key) {
  const double end_time = b.r["end_time"].as<double>();
  if (m.first_time() > 1e-9 || m.last_time() < end_time - 1e-9)
    throw SceneError(key, fmt::format("the series covers [{:.6g}, {:.6g}] s, which must include [0, end_time = {:.6g}] s",
                                      m.first_time(), m.last_time(), end_time));
  const rigid::SpatialState s0 = m.at(0.0);
  if ((Vec<3>(s0.position) - start).norm() > 0.01 * b.dp || turn_angle(s0.orientation) > 1e-6) {
    const rigid::Quat q(s0.orientation * placed);
    throw SceneError(key, fmt::format("the series starts at {}, orientation (qw, qx, qy, qz) = ({:.6g}, {:.6g}, {:.6g}, "
                                      "{:.6g}), but the body's centre of mass is at {}, orientation ({:.6g}, {:.6g}, "
                                      "{:.6g}, {:.6g})",
                                      position_text<3>(Vec<3>(s0.position)), q.w(), q.x(), q.y(), q.z(),
                                      position_text<3>(start), placed.w(), placed.x(), placed.y(), placed.z()));
  }
}

// Free, prescribed or on a rail (bodies[k].motion); a prescribed body follows the ln cosh law from its centre of mass
// `start`, or a series of poses that starts there, at the orientation `placed`.
BodyMotion read_motion(const SceneBuild<3>& b, const YAML::Node& bn, const std::string& path, const Vec<3>& start,
                       const rigid::Quat& placed) {
  BodyMotion motion;
  motion.mode = BodyMotion::mode_names.parse(bn["motion"].as<std::string>());
  if (motion.mode != BodyMotion::Mode::prescribed && bn["prescribed"])
    throw SceneError(path + ".prescribed", "applies to motion: prescribed only");
  if (motion.mode != BodyMotion::Mode::rail && bn["rail"])
    throw SceneError(path + ".rail", "applies to motion: rail only");
  if (motion.mode == BodyMotion::Mode::free) return motion;
  if (motion.mode == BodyMotion::Mode::rail) {
    motion.rail = read_rail(bn, path);
    return motion;
  }
  if (!bn["prescribed"]) throw SceneError(path + ".prescribed", "motion: prescribed needs a prescribed map");
  if (bn["locked"].size() > 0) throw SceneError(path + ".locked", "applies to free motion only");
  if (bn["release_time"].as<double>() > 0.0)
    throw SceneError(path + ".release_time",
                     "applies to free and rail motion only (a prescribed body starts at start_time)");
  const YAML::Node pr = bn["prescribed"];
  if (prescribed_law_names.parse(pr["type"].as<std::string>()) == PrescribedLaw::series) {
    const std::string who = pr["body"].as<std::string>().empty() ? bn["name"].as<std::string>()
                                                                   : pr["body"].as<std::string>();
    const std::string key = path + ".prescribed.file";
    motion.prescribed_3d = read_pose_series(b.scene_dir / pr["file"].as<std::string>(), who, key, placed);
    check_series_start(b, *motion.prescribed_3d, start, placed, key);
    return motion;
  }
  const Vec<3> direction = vec_of<3>(pr["direction"]);
  if (!(direction.norm() > 0.0)) throw SceneError(path + ".prescribed.direction", "must not be zero");
  motion.prescribed_3d = rigid::SpatialPrescribedMotion::ln_cosh(
      start, direction, rigid::LnCoshLaw(pr["s0"].as<double>(), pr["t0"].as<double>(), pr["start_time"].as<double>()));
  return motion;
}

// The rigid world, with each tank's floor and sides as static boxes 10 dp thick and each terrain as a static mesh when
// bodies collide with the walls.
std::shared_ptr<RigidBodies<3>> make_rigid_world(const SceneBuild<3>& b) {
  auto bodies = std::make_shared<RigidBodies<3>>(b.sim->options.gravity,
                                                 b.r["rigid"]["collision_margin"].as<double>() * b.dp);
  if (!b.r["rigid"]["wall_contact"].as<bool>()) return bodies;
  const double t = 10.0 * b.dp;
  for (const auto& terrain : b.terrains) bodies->world.add_static_mesh(terrain.surface, 1.0, 1.0);
  const auto planes = symmetry_planes(b.r);
  for (const auto& [lo, hi] : b.tanks) {
    const Vec<3> outer_lo = lo - Vec<3>::Constant(t);
    Vec<3> outer_hi = hi + Vec<3>::Constant(t);
    outer_hi[2] = hi[2];
    // A symmetry face is no wall for a body: the body's part beyond it is its mirror image.
    const auto symmetry = [&](int axis, double side, double at) {
      for (const auto& plane : planes)
        if (plane.normal[axis] == side && std::abs(side * plane.offset - at) <= 1e-9 * b.dp) return true;
      return false;
    };
    auto add = [&](Vec<3> a, Vec<3> c) { bodies->world.add_static_box(a, c, 1.0, 1.0); };
    add(outer_lo, Vec<3>(outer_hi[0], outer_hi[1], lo[2]));                                       // floor
    if (!symmetry(0, -1.0, lo[0])) add(outer_lo, Vec<3>(lo[0], outer_hi[1], hi[2]));             // -x
    if (!symmetry(0, 1.0, hi[0])) add(Vec<3>(hi[0], outer_lo[1], outer_lo[2]), outer_hi);        // +x
    if (!symmetry(1, -1.0, lo[1])) add(outer_lo, Vec<3>(outer_hi[0], lo[1], hi[2]));             // -y
    if (!symmetry(1, 1.0, hi[1])) add(Vec<3>(outer_lo[0], hi[1], outer_lo[2]), outer_hi);        // +y
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
    const SolidShape shape = body_shape(b, bn, path, false);
    const rigid::TriangleSurface& surface = shape.surface;
    const double mass = solid_spec(bn, shape, path).mass;
    if (mass >= water_density * rigid::mass_properties(surface).volume) continue;  // it sinks
    const double rise = rise_to_draft(surface, mass, water_density, level);
    if (std::abs(rise) < 1e-9 * b.dp) continue;
    YAML::Node centre = bn["shape"][placement_key(bn["shape"])];
    centre[2] = centre[2].as<double>() + rise;
    b.moved_to_draft.emplace_back(path, rise);
  }
}

// A deformable slide: its phase and shape (cut by the symmetry planes); its particles are placed with the water
// (fill_fluid_regions). Keys of the rigid model (mass, friction, motion, ...) are left as they are: switching back
// uses them again.
void add_deformable_slide(SceneBuild<3>& b, const YAML::Node& bn, const std::string& path, const SolidShape& shape,
                          RheologyModel model) {
  check_inside_tanks(b, shape.surface, path);
  SlideReportOf<3> rep = add_slide_phase(b, bn, path, model);
  const rigid::MassProperties m = rigid::mass_properties(shape.surface);
  rep.volume = m.volume;
  SceneBuild<3>::Slide slide;
  slide.path = path;
  slide.phase = rep.phase;
  slide.vertices = shape.surface.vertices;
  slide.centroid = m.centroid;
  slide.signed_distance = shape.signed_distance;
  slide.lo = slide.hi = slide.vertices[0];
  for (const auto& v : slide.vertices) slide.lo = slide.lo.cwiseMin(v), slide.hi = slide.hi.cwiseMax(v);
  slide.lo.array() -= b.dp, slide.hi.array() += b.dp;  // a lattice point on a cut face may lie beyond it by rounding
  b.slides.push_back(slide);
  b.scene->slides.push_back(rep);
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
    const BodyModel model = body_model_names.parse(bn["model"].as<std::string>());
    if (const auto rheology = sediment_rheology(model)) {
      add_deformable_slide(b, bn, path, body_shape(b, bn, path, false), *rheology);
      continue;
    }
    const SolidShape shape = body_shape(b, bn, path, true);
    const rigid::TriangleSurface& surface = shape.surface;
    check_inside_tanks(b, surface, path);
    rigid::SolidSpec spec = solid_spec(bn, shape, path);
    const rigid::Quat placed(Eigen::Quaterniond(Eigen::Matrix3d(shape.axes)));
    BodyMotion motion = read_motion(b, bn, path, spec.centre_of_mass, placed);
    spec.kinematic = motion.mode != BodyMotion::Mode::free;  // a rail body's one freedom is integrated outside Bullet
    check_symmetry_locks(b, bn, shape, spec, motion, path);
    rigid::SolidSpec collision = spec;
    collision.hulls = shape.inset(b.r["rigid"]["collision_margin"].as<double>() * b.dp);
    collision.hull_inset = true;
    motion.release_time = bn["release_time"].as<double>();
    motion.free_while_settling =
        during_settling_names.parse(bn["during_settling"].as<std::string>()) == DuringSettling::free;
    if (motion.free_while_settling && spec.kinematic)
      throw SceneError(path + ".during_settling", "free needs motion: free (a prescribed body follows its law, a rail "
                                                  "body waits for its release)");
    if (motion.free_while_settling && motion.release_time > 0.0)
      throw SceneError(path + ".during_settling", "free contradicts release_time > 0 (which holds the body)");
    if (motion.free_while_settling && b.initial_state != InitialState::settled)
      throw SceneError(path + ".during_settling", "free needs method.initial_state: settled (there is no settling "
                                                  "otherwise)");
    const double volume = rigid::mass_properties(surface).volume, density = spec.mass / volume;
    int body = 0;
    try {
      body = b.bodies->add(name, collision, motion, density, placed);
    } catch (const std::invalid_argument& e) {
      throw SceneError(path + ".shape", e.what());
    }
    const Vec<3> c = spec.centre_of_mass;
    BodyReportOf<3> rep;
    rep.name = name;
    rep.motion = std::string(BodyMotion::mode_names.name(motion.mode));
    rep.area = volume;
    rep.mass = spec.mass;
    rep.inertia = spec.inertia.trace() / 3.0;
    rep.placed = c;
    rep.free_while_settling = motion.free_while_settling;
    for (const auto& [moved, rise] : b.moved_to_draft)
      if (moved == path) rep.moved_to_draft = rise;
    const auto& pts = shape.points;
    for (const auto& bp : pts) {
      // Every body particle's frame, held here or not (cases/build_share.hpp): the frames are the same everywhere.
      const std::int32_t frame = b.counting ? -1 : P.add_body_frame(body, bp.position - c, bp.normal);
      const auto i = b.add(bp.position, bp.layer == 0 ? Kind::wall : Kind::dummy, 0, density, 0.0);
      if (!i) continue;
      P.wall_normal[*i] = bp.normal;
      P.wall_depth[*i] = bp.depth;
      P.body_frame[*i] = frame;
      b.boundary_owner.push_back(path);
    }
    rep.particles = pts.size();
    b.scene->bodies.push_back(rep);
    b.solids.push_back(surface);
    b.solid_distance.push_back(shape.signed_distance);
  }
}

// Whether p lies inside a body or within dp/2 of its surface: no water there (the body's wall layer lies dp/2
// inside it, and water keeps 0.75 dp from boundary particles: check_overlaps).
int body_near(const SceneBuild<3>& b, const Vec<3>& p) {
  for (std::size_t k = 0; k < b.solid_distance.size(); ++k)
    if (b.solid_distance[k](p) < 0.5 * b.dp - 1e-9 * b.dp) return static_cast<int>(k);
  return -1;
}

// The face a slide rests on: a terrain or a tank's floor within a spacing of its lowest point (the steepest of them;
// a terrain's face is the one nearest the slide's centroid, its normal from there to the centroid), and the layer the
// yield criterion takes: its top at the surface's vertex furthest from that face.
std::optional<RestingFace<3>> resting_face_of(const SceneBuild<3>& b, const SceneBuild<3>::Slide& slide) {
  const double g = b.sim->options.gravity.norm();
  const Vec<3> down = g > 0.0 ? Vec<3>(b.sim->options.gravity / g) : Vec<3>(0.0, 0.0, -1.0);
  std::optional<RestingFace<3>> best;
  const auto consider = [&](const Vec<3>& foot, const Vec<3>& normal) {
    RestingFace<3> rest;
    rest.normal = normal;
    rest.slope_angle_deg = std::acos(std::min(1.0, std::abs(normal.dot(down)))) * 180.0 / M_PI;
    rest.top = slide.vertices[0];
    for (const auto& v : slide.vertices)
      if ((v - foot).dot(normal) > rest.thickness) rest.thickness = (v - foot).dot(normal), rest.top = v;
    if (!best || rest.slope_angle_deg > best->slope_angle_deg) best = rest;
  };
  for (const auto& t : b.terrains) {
    double nearest = INFINITY;
    for (const auto& v : slide.vertices) nearest = std::min(nearest, t.distance->distance(v));
    const Vec<3> foot = t.distance->nearest_point(slide.centroid);
    if (nearest < b.dp && (slide.centroid - foot).norm() > 0.0) consider(foot, (slide.centroid - foot).normalized());
  }
  for (const auto& [lo, hi] : b.tanks) {
    double lowest = INFINITY;
    for (const auto& v : slide.vertices) lowest = std::min(lowest, v[2]);
    if (std::abs(lowest - lo[2]) < b.dp) consider(Vec<3>(slide.centroid[0], slide.centroid[1], lo[2]), Vec<3>::UnitZ());
  }
  return best;
}

void finish_bodies(SceneBuild<3>& b) {
  for (std::size_t k = 0; k < b.slides.size(); ++k)
    finish_slide_report(b, b.slides[k], resting_face_of(b, b.slides[k]), b.scene->slides[k]);
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
