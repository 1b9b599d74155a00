#include "cases/scene.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <fstream>
#include <functional>
#include <sstream>
#include <map>

#include "cases/initial_state.hpp"
#include "cases/scene_geometry.hpp"
#include "coupling/equilibrium_column.hpp"
#include "coupling/relaxation.hpp"
#include "coupling/rigid_bodies.hpp"
#include "fluid/hydrostatic_start.hpp"
#include "rigid/polygon.hpp"
#include "fluid/walls.hpp"

namespace slide::cases {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

struct BodiesBuilt {
  std::shared_ptr<RigidBodies> bodies;
  std::vector<std::vector<rigid::Vec2>> outlines;  // counter-clockwise, world coordinates at t = 0
};

rigid::Vec2 r2(const Vec<2>& v) { return rigid::Vec2(v[0], v[1]); }
Vec<2> v2(const rigid::Vec2& v) { return Vec<2>(v[0], v[1]); }

// Reads a prescribed-motion series: a CSV with a header naming at least time, x, y, angle (vx, vy, omega and body
// optional), as bodies.csv has them.
rigid::PrescribedMotion read_motion_series(const std::filesystem::path& file, const std::string& body,
                                           const std::string& key) {
  std::ifstream in(file);
  if (!in) throw SceneError(key, "cannot read " + file.string());
  std::string line;
  std::vector<std::string> header;
  auto split = [](const std::string& l) {
    std::vector<std::string> out;
    std::stringstream ss(l);
    std::string c;
    while (std::getline(ss, c, ',')) out.push_back(c);
    return out;
  };
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') {
      header = split(line);
      break;
    }
  auto col = [&](const std::string& name) -> int {
    for (std::size_t k = 0; k < header.size(); ++k)
      if (header[k] == name) return static_cast<int>(k);
    return -1;
  };
  const int ct = col("time"), cx = col("x"), cy = col("y"), ca = col("angle"), cvx = col("vx"), cvy = col("vy"),
            cw = col("omega"), cb = col("body");
  if (ct < 0 || cx < 0 || cy < 0 || ca < 0)
    throw SceneError(key, file.string() + ": the header must name the columns time, x, y and angle");
  const bool has_velocity = cvx >= 0 && cvy >= 0 && cw >= 0;
  std::vector<rigid::MotionSample> samples;
  long row = 1;
  while (std::getline(in, line)) {
    ++row;
    if (line.empty() || line[0] == '#') continue;
    const auto f = split(line);
    if (cb >= 0 && (cb >= int(f.size()) || f[cb] != body)) continue;
    try {
      rigid::MotionSample m;
      m.time = std::stod(f.at(ct));
      m.state.position = rigid::Vec2(std::stod(f.at(cx)), std::stod(f.at(cy)));
      m.state.angle = std::stod(f.at(ca));
      if (has_velocity) {
        m.state.velocity = rigid::Vec2(std::stod(f.at(cvx)), std::stod(f.at(cvy)));
        m.state.angular_velocity = std::stod(f.at(cw));
      }
      // Repeated times (a run's last row written twice) keep the first.
      if (!samples.empty() && m.time <= samples.back().time) continue;
      samples.push_back(m);
    } catch (const std::exception&) {
      throw SceneError(key, fmt::format("{}: row {} is not numeric", file.string(), row));
    }
  }
  if (samples.size() < 2)
    throw SceneError(key, fmt::format("{}: fewer than two rows for body \"{}\"", file.string(), body));
  return rigid::PrescribedMotion::from_samples(std::move(samples), has_velocity);
}

// A body's outline from its shape, counter-clockwise in world coordinates at t = 0; it must be convex.
std::vector<rigid::Vec2> body_outline(const YAML::Node& bn, const std::string& path) {
  std::vector<rigid::Vec2> outline;
  const YAML::Node sh = bn["shape"];
  if (sh["type"].as<std::string>() == "box") {
    const Vec<2> c = vec2(sh["center"]), size = vec2(sh["size"]);
    if (!(size[0] > 0 && size[1] > 0)) throw SceneError(path + ".shape.size", "width and height must be positive");
    const double a = sh["angle"].as<double>() * M_PI / 180.0, ca = std::cos(a), sa = std::sin(a);
    for (const auto& corner : {Vec<2>(-0.5, -0.5), Vec<2>(0.5, -0.5), Vec<2>(0.5, 0.5), Vec<2>(-0.5, 0.5)}) {
      const Vec<2> l(corner[0] * size[0], corner[1] * size[1]);
      outline.push_back(r2(c + Vec<2>(ca * l[0] - sa * l[1], sa * l[0] + ca * l[1])));
    }
  } else {
    for (const auto& p : points_of(sh["points"])) outline.push_back(r2(p));
  }
  outline = rigid::counter_clockwise(outline);
  if (!rigid::is_convex_ccw(outline)) throw SceneError(path + ".shape", "the outline must be a convex polygon");
  return outline;
}

BodiesBuilt build_bodies(const YAML::Node& r, const std::filesystem::path& scene_dir,
                         const std::vector<FaceSegment>& faces, const FluidOptions<2>& opt, Particles<2>& P,
                         std::vector<std::string>& boundary_owner, std::vector<BodyReport>& reports) {
  BodiesBuilt out;
  const YAML::Node list = r["bodies"];
  if (list.size() == 0) return out;
  const double dp = opt.dp;
  out.bodies = std::make_shared<RigidBodies>(opt.gravity, r["rigid"]["collision_margin"].as<double>() * dp);
  if (r["rigid"]["wall_contact"].as<bool>())
    for (const auto& f : faces)
      out.bodies->world.add_static_segment(r2(f.a), r2(f.b), r2(-f.inward), 10.0 * dp, 1.0, 1.0);
  const double end_time = r["end_time"].as<double>();
  std::map<std::string, std::size_t> names;
  for (std::size_t k = 0; k < list.size(); ++k) {
    const YAML::Node bn = list[k];
    const std::string path = fmt::format("bodies[{}]", k);
    const std::string name = bn["name"].as<std::string>();
    if (names.count(name)) throw SceneError(path + ".name", "duplicate body name \"" + name + "\"");
    names[name] = k;
    const std::vector<rigid::Vec2> outline = body_outline(bn, path);
    for (const auto& v : outline)
      if (!faces.empty() && signed_face_distance(faces, v2(v)) < -1e-6 * dp)
        throw SceneError(path + ".shape", fmt::format("vertex ({:.6g}, {:.6g}) lies behind a wall face", v[0], v[1]));
    const double area = rigid::signed_area(outline);
    const double density_key = bn["density"].as<double>(), mass_key = bn["mass"].as<double>();
    if ((density_key > 0) == (mass_key > 0))
      throw SceneError(path + ".density", "give exactly one of density and mass (per unit width), both positive");
    const double mass = mass_key > 0 ? mass_key : density_key * area;
    const double density = mass / area;
    rigid::BodySpec spec;
    spec.outline = outline;
    spec.mass = mass;
    spec.inertia = density * rigid::polar_moment_about_centroid(outline);
    spec.friction = bn["friction"].as<double>();
    spec.restitution = bn["restitution"].as<double>();
    for (const auto& l : bn["locked"]) {
      const std::string c = l.as<std::string>();
      spec.locked[c == "x" ? 0 : c == "y" ? 1 : 2] = true;
    }
    BodyMotion motion;
    motion.release_time = bn["release_time"].as<double>();
    const std::string mode = bn["motion"].as<std::string>();
    motion.mode = BodyMotion::mode_names.parse(mode);
    motion.free_while_settling = bn["during_settling"].as<std::string>() == "free";
    if (motion.free_while_settling) {
      if (motion.mode != BodyMotion::Mode::free)
        throw SceneError(path + ".during_settling", "free needs motion: free (a prescribed body follows its law)");
      if (motion.release_time > 0.0)
        throw SceneError(path + ".during_settling", "free contradicts release_time > 0 (which holds the body)");
      if (initial_state_names.parse(r["method"]["initial_state"].as<std::string>()) != InitialState::settled)
        throw SceneError(path + ".during_settling", "free needs method.initial_state: settled (there is no settling "
                                                    "otherwise)");
    }
    if (motion.mode == BodyMotion::Mode::prescribed) {
      spec.kinematic = true;
      if (!bn["prescribed"]) throw SceneError(path + ".prescribed", "motion: prescribed needs a prescribed map");
      const YAML::Node pr = bn["prescribed"];
      const rigid::Vec2 c = rigid::centroid(outline);
      if (pr["type"].as<std::string>() == "series") {
        const std::string file = pr["file"].as<std::string>();
        if (file.empty()) throw SceneError(path + ".prescribed.file", "a series needs a CSV file");
        const std::string who = pr["body"].as<std::string>().empty() ? name : pr["body"].as<std::string>();
        const auto m = read_motion_series(scene_dir / file, who, path + ".prescribed.file");
        if (m.first_time() > 1e-9 || m.last_time() < end_time - 1e-9)
          throw SceneError(path + ".prescribed.file",
                           fmt::format("the series covers [{:.6g}, {:.6g}] s, which must include [0, end_time = {:.6g}] s",
                                       m.first_time(), m.last_time(), end_time));
        const rigid::PlanarState s0 = m.at(0.0);
        if ((s0.position - c).norm() > 0.01 * dp || std::abs(s0.angle) > 1e-6)
          throw SceneError(path + ".prescribed.file",
                           fmt::format("the series starts at ({:.6g}, {:.6g}), angle {:.3g}, but the body's centre of "
                                       "mass is at ({:.6g}, {:.6g}), angle 0",
                                       s0.position[0], s0.position[1], s0.angle, c[0], c[1]));
        motion.prescribed = m;
      } else {
        const Vec<2> d = vec2(pr["direction"]);
        if (d.norm() == 0.0) throw SceneError(path + ".prescribed.direction", "must not be zero");
        motion.prescribed = rigid::PrescribedMotion::ln_cosh(c, 0.0, r2(d), pr["s0"].as<double>(), pr["t0"].as<double>(),
                                                             pr["start_time"].as<double>());
      }
    }
    const int b = out.bodies->add(name, spec, motion, density);
    // Boundary particles: the outline as a closed face with the fluid outside, layers inside.
    std::vector<Vec<2>> face;
    for (const auto& v : outline) face.push_back(v2(v));
    face.push_back(face.front());
    auto pts = polyline_boundary(face, false, dp, boundary_layers(opt.re_over_dp));
    // Acute corners (a wedge's tip): the first layer's mitred corner lies 0.5 dp / sin(angle / 2) inside the tip,
    // which leaves the tip hollow, and fluid could slip into it. One more wall particle on the bisector, 0.55 dp
    // nearer the tip, closes it.
    for (std::size_t k = 0; k < outline.size(); ++k) {
      const Vec<2> v = v2(outline[k]);
      const Vec<2> a = (v2(outline[(k + outline.size() - 1) % outline.size()]) - v).normalized();
      const Vec<2> b = (v2(outline[(k + 1) % outline.size()]) - v).normalized();
      const double angle = std::acos(std::clamp(a.dot(b), -1.0, 1.0));
      if (angle >= 0.5 * M_PI) continue;
      const Vec<2> inward = (a + b).normalized();
      const double s = 0.5 * dp / std::sin(0.5 * angle) - 0.55 * dp;
      if (s < 0.5 * dp) continue;
      pts.push_back({v + s * inward, -inward, s, 0});
    }
    const Vec<2> c = v2(rigid::centroid(outline));
    const std::size_t first = P.size();
    for (const auto& bp : pts) {
      bool duplicate = false;
      for (std::size_t i = first; i < P.size() && !duplicate; ++i)
        duplicate = distance_squared<2>(P.position[i], bp.position) < 0.25 * dp * dp;
      if (duplicate || !rigid::contains(outline, r2(bp.position))) continue;
      const std::size_t i = P.add(bp.position, bp.layer == 0 ? Kind::wall : Kind::dummy, 0, density, 0.0);
      P.wall_normal[i] = bp.normal;
      P.wall_depth[i] = bp.depth;
      P.body[i] = b;
      P.body_offset[i] = bp.position - c;
      P.body_normal[i] = bp.normal;
      boundary_owner.push_back(path);
    }
    BodyReport rep;
    rep.name = name;
    rep.motion = mode;
    rep.area = area;
    rep.mass = mass;
    rep.inertia = spec.inertia;
    rep.particles = P.size() - first;
    rep.placed = c;
    rep.free_while_settling = motion.free_while_settling;
    reports.push_back(rep);
    out.outlines.push_back(outline);
  }
  return out;
}

void finish_body_reports(std::vector<BodyReport>& reports, const BodiesBuilt& built, double dp, double level,
                         double water_density) {
  for (std::size_t b = 0; b < reports.size(); ++b) {
    auto& rep = reports[b];
    const auto& v = built.outlines[b];
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
}

}  // namespace

YAML::Node load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  YAML::Node raw;
  try {
    raw = YAML::LoadFile(file.string());
  } catch (const YAML::BadFile&) {
    throw SceneError("<file>", "cannot read scene file " + file.string());
  } catch (const YAML::Exception& e) {
    throw SceneError("<file>", "not valid YAML: " + std::string(e.what()));
  }
  if (!raw.IsMap()) throw SceneError("<root>", "a scene file must be a YAML mapping");
  for (const auto& o : overrides) apply_override(raw, o);
  return scene_schema().resolve(raw);
}

std::unique_ptr<Scene> build_scene(const YAML::Node& r, const std::string& default_name,
                                   const std::filesystem::path& scene_dir) {
  auto scene = std::make_unique<Scene>();
  scene->resolved = r;
  scene->name = r["name"].as<std::string>().empty() ? default_name : r["name"].as<std::string>();
  scene->end_time = r["end_time"].as<double>();
  auto sim = std::make_unique<Simulation<2>>();
  auto& opt = sim->options;
  auto& P = sim->particles;
  const double dp = r["particle_spacing"].as<double>();
  const YAML::Node m = r["method"];
  opt.dp = dp;
  opt.lattice = lattice_kind_names.parse(r["lattice"].as<std::string>());
  const bool hexagonal = opt.lattice == LatticeKind::hexagonal;
  const InitialState initial_state = initial_state_names.parse(m["initial_state"].as<std::string>());
  const WallPressure opt_wall_pressure = wall_pressure_names.parse(m["wall_pressure"].as<std::string>());
  if (hexagonal) {
    if (opt_wall_pressure == WallPressure::mirror)
      throw SceneError("method.wall_pressure", "the mirror model needs lattice: square (its images assume the square "
                                               "lattice); use extrapolated or number_density with lattice: hexagonal");
    if (initial_state == InitialState::hydrostatic)
      throw SceneError("method.initial_state", "lattice: hexagonal starts from lattice or settled (settling "
                                               "compresses it); the column-wise hydrostatic start needs lattice: square");
    for (std::size_t w = 0; w < r["walls"].size(); ++w)
      if (r["walls"][w]["layers"].as<long>() != 0)
        throw SceneError(fmt::format("walls[{}].layers", w),
                         "with lattice: hexagonal walls are cut from the lattice to the depth re; leave layers at 0");
  }
  opt.re_over_dp = m["kernel_radius"].as<double>();
  opt.skin_over_dp = m["neighbor_skin"].as<double>();
  opt.gradient = gradient_model_names.parse(m["gradient"].as<std::string>());
  opt.gamma = m["gamma"].as<double>();
  opt.free_surface_beta = m["free_surface_beta"].as<double>();
  opt.clamp_negative_pressure = m["clamp_negative_pressure"].as<bool>();
  opt.wall_slip = wall_slip_names.parse(m["wall_slip"].as<std::string>());
  opt.artificial_viscosity = m["artificial_viscosity"].as<double>();
  opt.collision_distance_over_dp = m["collision_distance"].as<double>();
  opt.collision_restitution = m["collision_restitution"].as<double>();
  opt.wall_pressure = wall_pressure_names.parse(m["wall_pressure"].as<std::string>());
  opt.gravity = vec2(r["gravity"]);
  opt.cfl = r["time_step"]["cfl"].as<double>();
  opt.viscous_number = r["time_step"]["viscous_number"].as<double>();
  opt.force_number = r["time_step"]["force_number"].as<double>();
  opt.dt_max = r["time_step"]["max"].as<double>();
  opt.max_number_density_ratio = r["checks"]["max_number_density_ratio"].as<double>();
  opt.max_speed_over_c0 = r["checks"]["max_speed_over_c0"].as<double>();
  const double re = opt.re_over_dp * dp;

  // Phases.
  std::map<std::string, std::size_t> phase_index;
  std::vector<std::pair<double, double>> phase_props;  // density, viscosity
  for (std::size_t k = 0; k < r["fluid"]["phases"].size(); ++k) {
    const auto ph = r["fluid"]["phases"][k];
    const std::string name = ph["name"].as<std::string>();
    if (phase_index.count(name))
      throw SceneError(fmt::format("fluid.phases[{}].name", k), "duplicate phase name \"" + name + "\"");
    phase_index[name] = k;
    phase_props.emplace_back(ph["density"].as<double>(), ph["viscosity"].as<double>());
  }

  // With bodies on the hexagonal lattice, the lattice is moved up or down (by less than half a row spacing) so that
  // a row lies dp/2 below the lowest point of the first body, where the fluid fill puts its nearest water. Why: the
  // lattice's rows are 0.93 dp apart and fixed, so water under a body would otherwise start up to a row spacing
  // further off than dp/2; the water cannot close such a gap under a held body (at rest, particles on a lattice
  // resist shear like a solid), and on release a block of water density sank 6.5 mm onto it (issue 4's note).
  Vec<2> lattice_offset = Vec<2>::Zero();
  if (hexagonal && r["bodies"].size() > 0) {
    double lowest = inf;
    for (const auto& v : body_outline(r["bodies"][0], "bodies[0]")) lowest = std::min(lowest, v[1]);
    lattice_offset[1] = row_offset_to_meet(opt.lattice, dp, lowest - 0.5 * dp);
  }
  scene->lattice_offset = lattice_offset;

  // Walls first (regions of type below_level need their faces).
  std::vector<FaceSegment> faces;
  std::vector<std::string> boundary_owner;
  for (std::size_t w = 0; w < r["walls"].size(); ++w) {
    const auto wn = r["walls"][w];
    const auto face = points_of(wn["points"]);
    const bool left = wn["fluid_side"].as<std::string>() == "left";
    const long layers_key = wn["layers"].as<long>();
    const int layers = layers_key == 0 ? boundary_layers(opt.re_over_dp) : static_cast<int>(layers_key);
    std::vector<BoundaryPoint> pts;
    try {
      pts = hexagonal ? lattice_boundary(face, left, dp, opt.re_over_dp * dp, opt.lattice, lattice_offset)
                      : polyline_boundary(face, left, dp, layers);
    } catch (const std::invalid_argument& e) {
      throw SceneError(fmt::format("walls[{}].points", w), e.what());
    }
    for (std::size_t s = 0; s + 1 < face.size(); ++s) {
      const Vec<2> d = (face[s + 1] - face[s]).normalized();
      const Vec<2> l(-d[1], d[0]);
      faces.push_back({face[s], face[s + 1], left ? l : Vec<2>(-l)});
    }
    // Boundary particles of the first phase's density; they carry no viscosity of their own.
    for (const auto& b : pts) {
      bool duplicate = false;  // overlapping layers at convex corners or where walls meet
      for (std::size_t i = 0; i < P.size() && !duplicate; ++i)
        duplicate = distance_squared<2>(P.position[i], b.position) < 0.25 * dp * dp;
      if (duplicate) continue;
      const std::size_t i = P.add(b.position, b.layer == 0 ? Kind::wall : Kind::dummy, 0, phase_props[0].first,
                                  phase_props[0].second);
      P.wall_normal[i] = b.normal;
      P.wall_depth[i] = b.depth;
      boundary_owner.push_back(fmt::format("walls[{}]", w));
    }
  }
  BodiesBuilt built = build_bodies(r, scene_dir, faces, opt, P, boundary_owner, scene->bodies);
  const std::size_t boundary_count = P.size();
  // Lattice points of a fluid region must lie outside every body, at least dp/2 from its outline.
  auto clear_of_bodies = [&](const Vec<2>& p) -> int {
    for (std::size_t b = 0; b < built.outlines.size(); ++b) {
      const rigid::Vec2 q(p[0], p[1]);
      if (rigid::contains(built.outlines[b], q) || rigid::distance_to_outline(built.outlines[b], q) < 0.5 * dp - 1e-9 * dp)
        return static_cast<int>(b);
    }
    return -1;
  };

  // Bounding box of the wall faces, for below_level regions.
  Vec<2> face_lo = Vec<2>::Constant(inf), face_hi = Vec<2>::Constant(-inf);
  for (const auto& f : faces) {
    face_lo = face_lo.cwiseMin(f.a).cwiseMin(f.b);
    face_hi = face_hi.cwiseMax(f.a).cwiseMax(f.b);
  }

  // Fluid regions.
  double still_level = -inf;  // highest below_level level, for the bodies' buoyancy report
  std::vector<std::size_t> region_of_particle;
  for (std::size_t k = 0; k < r["fluid"]["regions"].size(); ++k) {
    const auto rn = r["fluid"]["regions"][k];
    const std::string path = fmt::format("fluid.regions[{}]", k);
    std::string phase_name = rn["phase"].as<std::string>();
    if (phase_name.empty()) phase_name = r["fluid"]["phases"][0]["name"].as<std::string>();
    if (!phase_index.count(phase_name))
      throw SceneError(path + ".phase", "no phase named \"" + phase_name + "\" in fluid.phases");
    const std::size_t ph = phase_index[phase_name];
    const std::string type = rn["type"].as<std::string>();
    Vec<2> lo, hi;
    std::function<bool(const Vec<2>&)> inside;
    std::vector<Vec<2>> poly;
    // Half the extent of a particle's cell: dp / 2 on the square lattice; half a spacing across and half a row
    // spacing up on the hexagonal one.
    const double half_x = 0.5 * nearest_spacing(opt.lattice, dp), half_y = 0.5 * row_spacing(opt.lattice, dp);
    if (type == "rectangle") {
      lo = vec2(rn["min"]);
      hi = vec2(rn["max"]);
      if (!(lo[0] < hi[0] && lo[1] < hi[1])) throw SceneError(path + ".max", "must exceed min in x and y");
      inside = [&, half_x, half_y](const Vec<2>& p) {
        const double e = 1e-9 * dp;
        return p[0] - half_x >= lo[0] - e && p[0] + half_x <= hi[0] + e && p[1] - half_y >= lo[1] - e &&
               p[1] + half_y <= hi[1] + e;
      };
    } else if (type == "polygon") {
      poly = points_of(rn["points"]);
      lo = hi = poly[0];
      for (const auto& q : poly) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
      inside = [&](const Vec<2>& p) { return inside_polygon(poly, p); };
    } else {
      if (faces.empty()) throw SceneError(path, "a below_level region needs walls around it");
      const double level = rn["level"].as<double>();
      lo = face_lo;
      hi = Vec<2>(face_hi[0], std::min(level, face_hi[1]));
      // On the hexagonal lattice the walls hold every lattice point on or behind a face, the water every one in
      // front of it; on the square lattice the water starts half a spacing in front of the faces.
      const double clearance = hexagonal ? 1e-9 * dp : 0.5 * dp - 1e-9 * dp;
      inside = [&, level, clearance](const Vec<2>& p) {
        return p[1] < level && signed_face_distance(faces, p) >= clearance && clear_of_bodies(p) < 0;
      };
      still_level = std::max(still_level, level);
    }
    std::size_t added = 0;
    for_each_lattice_point(opt.lattice, dp, lo, hi, [&](const Vec<2>& p) {
        if (!inside(p)) return;
        if (const int b = clear_of_bodies(p); b >= 0)
          throw SceneError(path, fmt::format("water at ({:.6g}, {:.6g}) lies inside body bodies[{}] or within dp/2 of "
                                             "its outline",
                                             p[0], p[1], b));
        P.add(p, Kind::fluid, static_cast<std::uint8_t>(ph), phase_props[ph].first, phase_props[ph].second);
        region_of_particle.push_back(k);
        ++added;
      }, lattice_offset);
    if (added == 0) throw SceneError(path, fmt::format("the region holds no particle at spacing dp = {} m", dp));
  }

  // Overlaps: fluid particles too close to a boundary particle or to each other.
  Vec<2> lo = P.position[0], hi = P.position[0];
  for (const auto& x : P.position) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  {
    NeighborGrid<2> g(lo - Vec<2>::Constant(dp), hi + Vec<2>::Constant(dp), dp);
    g.bin(P.position);
    for (std::size_t i = boundary_count; i < P.size(); ++i) {
      const std::string path = fmt::format("fluid.regions[{}]", region_of_particle[i - boundary_count]);
      g.for_each_near(P.position[i], 0.75 * dp, P.position, [&](std::uint32_t j, double r2) {
        if (j == i) return;
        if (j < boundary_count)
          throw SceneError(path, fmt::format("water overlaps {}: a particle at ({:.6g}, {:.6g}) is {:.3g} dp "
                                             "from one of its boundary particles (at least 0.75 dp needed)",
                                             boundary_owner[j], P.position[i][0], P.position[i][1],
                                             std::sqrt(r2) / dp));
        if (j < i)
          throw SceneError(path, fmt::format("overlaps fluid.regions[{}] at ({:.6g}, {:.6g})",
                                             region_of_particle[j - boundary_count], P.position[i][0],
                                             P.position[i][1]));
      });
    }
  }

  // Sound speed and hydrostatic start.
  const double g = -opt.gravity[1];
  // A lattice column's particles are dp apart on the square lattice, two rows apart on the hexagonal one.
  scene->deepest_water = deepest_water<2>(P, dp, hexagonal ? 2.0 * row_spacing(opt.lattice, dp) : dp);
  const double c0_key = m["sound_speed"].as<double>();
  if (c0_key > 0.0) {
    opt.sound_speed = c0_key;
    scene->sound_speed_source = "method.sound_speed";
  } else {
    if (g <= 0.0 || scene->deepest_water <= 0.0)
      throw SceneError("method.sound_speed", "cannot default to 10 sqrt(g H) without downward gravity; set it");
    opt.sound_speed = 10.0 * std::sqrt(g * scene->deepest_water);
    scene->sound_speed_source =
        fmt::format("default 10 sqrt(g H), H = {:.6g} m (deepest water), g = {:.6g} m/s^2", scene->deepest_water, g);
  }
  if (initial_state == InitialState::settled && !(g > 0.0))
    throw SceneError("method.initial_state", "a settled start needs downward gravity");
  // The hexagonal lattice is compressed by settling alone (its columns are not the square lattice's runs).
  if (initial_state != InitialState::lattice && g > 0.0 && !hexagonal) {
    const LatticeConstants lc = lattice_constants<2>(dp, re);
    const int rows = static_cast<int>(std::lround(scene->deepest_water / dp));
    try {
      const EquilibriumColumn column = equilibrium_column(opt, phase_props[0].first, phase_props[0].second, rows);
      scene->equilibrium = column;
      std::vector<double> body_shift;
      compress_hydrostatically<2>(P, dp, re, EquationOfState(lc.n0, opt.sound_speed, opt.gamma), g, true,
                                  column.gap_from_top,
                                  std::isfinite(still_level) ? still_level : std::numeric_limits<double>::quiet_NaN(),
                                  &body_shift);
      // Floating bodies go down with the water they rest on (free bodies only: a prescribed one keeps its law).
      for (std::size_t b = 0; b < body_shift.size(); ++b) {
        if (body_shift[b] == 0.0 || built.bodies->motion[b].mode != BodyMotion::Mode::free) continue;
        built.bodies->world.translate(int(b), rigid::Vec2(0.0, body_shift[b]));
        for (std::size_t i = 0; i < P.size(); ++i)
          if (P.body[i] == int(b)) P.position[i][1] += body_shift[b];
      }
    } catch (const std::runtime_error& e) {
      throw SceneError("method.initial_state", std::string("hydrostatic start failed: ") + e.what());
    }
  }

  // Domain.
  if (r["domain"]) {
    opt.domain_lo = vec2(r["domain"]["min"]);
    opt.domain_hi = vec2(r["domain"]["max"]);
    for (std::size_t i = 0; i < P.size(); ++i)
      for (int k = 0; k < 2; ++k)
        if (P.position[i][k] < opt.domain_lo[k] || P.position[i][k] > opt.domain_hi[k])
          throw SceneError("domain", fmt::format("particle at ({:.6g}, {:.6g}) lies outside the domain",
                                                 P.position[i][0], P.position[i][1]));
  } else {
    opt.domain_lo = lo - Vec<2>::Constant(4 * re);
    opt.domain_hi = hi + Vec<2>::Constant(4 * re) + Vec<2>(0.0, 0.5 * (hi[1] - lo[1]));
  }

  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.kind[i] == Kind::fluid) ++scene->fluid_count;
    else if (P.kind[i] == Kind::wall) ++scene->wall_count;
    else ++scene->dummy_count;
  }

  // Gauges and diagnostics.
  for (std::size_t k = 0; k < r["gauges"].size(); ++k)
    scene->gauges.push_back({r["gauges"][k]["name"].as<std::string>(), r["gauges"][k]["x"].as<double>()});
  const auto sf = r["diagnostics"]["surge_front"];
  scene->surge_front = {sf["enabled"].as<bool>(), sf["wall_face_x"].as<double>(), sf["floor_y"].as<double>(),
                        sf["column_width"].as<double>()};
  if (r["profiles"]) {
    const auto pn = r["profiles"];
    for (const auto& t : pn["times"]) scene->profiles.times.push_back(t.as<double>());
    if (!std::is_sorted(scene->profiles.times.begin(), scene->profiles.times.end()))
      throw SceneError("profiles.times", "must be in increasing order");
    scene->profiles.x_min = pn["x_min"].as<double>();
    scene->profiles.x_max = pn["x_max"].as<double>();
    if (!scene->profiles.times.empty() && !(scene->profiles.x_max > scene->profiles.x_min))
      throw SceneError("profiles.x_max", "must exceed profiles.x_min");
    scene->profiles.spacing = pn["spacing"].as<double>() > 0 ? pn["spacing"].as<double>() : dp;
  }
  scene->output.snapshots = r["output"]["snapshots"].as<bool>();
  scene->output.snapshot_interval = r["output"]["snapshot_interval"].as<double>();
  scene->output.gauge_interval = r["output"]["gauge_interval"].as<double>();

  finish_body_reports(scene->bodies, built, dp, still_level, phase_props[0].first);
  if (!built.outlines.empty()) {
    sim->attach_bodies(std::move(built.bodies));
    scene->body_sample_interval = r["output"]["body_interval"].as<double>();
  }
  sim->initialise();
  if (initial_state == InitialState::settled) {
    try {
      scene->settling = relax_at_rest(*sim, m["settling_time"].as<double>(), m["settling_damping"].as<double>());
    } catch (const std::runtime_error& e) {
      throw SceneError("method.initial_state", e.what());
    }
  }
  scene->simulation = std::move(sim);
  return scene;
}

}  // namespace slide::cases
