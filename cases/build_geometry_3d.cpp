// Steps of a 3-D scene's geometry (dimension: 3): its walls (tanks: fluid/box_walls.hpp; terrains:
// cases/terrain_layers.hpp), its fluid regions (box, below_level inside the tanks, the inside of a shape) on the scene's lattice, and its
// particle count estimated before any is made.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <utility>
#include <vector>
#include <tuple>

#include "cases/height_grid.hpp"
#include "cases/scene_build.hpp"
#include "cases/terrain_layers.hpp"
#include "coupling/position_text.hpp"
#include "fluid/box_walls.hpp"

namespace slide::cases {
namespace {

// Walls on the fcc lattice are cut to the depth re (layers must stay 0: check_lattice_choices).
int tank_layers(const SceneBuild<3>& b, const YAML::Node& wn) {
  const long key = wn["layers"].as<long>();
  return key == 0 ? boundary_layers(b.sim->options.re_over_dp) : static_cast<int>(key);
}

// A lattice point's index, the key that tells two walls' points at the same place apart from neighbours.
std::tuple<long, long, long> lattice_index(const SceneBuild<3>& b, const Vec<3>& p) {
  const double spacing = row_spacing(b.sim->options.lattice, b.dp);
  const Vec<3> q = (p - b.scene->lattice_offset) / spacing;
  return {std::lround(q[0] - 0.5), std::lround(q[1] - 0.5), std::lround(q[2] - 0.5)};
}

// Which of a wall's lattice points are the first at their place: where two tanks meet, or a terrain covers a tank's
// floor, the earlier wall's point stands. A build in parts (cases/build_share.hpp) holds only some of the points: the
// counting pass, which meets every one, notes the repeated ones by their number, and the parts skip those. The places
// taken are a sorted vector, merged wall by wall: 24 B a point, where a std::set of them took 64 B a point (measured,
// resident, a million points), held on every process while it counts.
class WallPlaces {
 public:
  using Index = std::tuple<long, long, long>;
  explicit WallPlaces(SceneBuild<3>& b) : b_(b) {}
  // Of one wall's points, in order, whether each is the first at its place (among earlier walls' and its own).
  std::vector<bool> first(const std::vector<BoundaryPointOf<3>>& points) {
    const std::uint64_t numbered_from = offered_;
    offered_ += points.size();
    std::vector<bool> fresh(points.size(), true);
    if (b_.counted) {
      const auto& repeated = b_.counted->repeated_wall_points;
      for (auto r = std::lower_bound(repeated.begin(), repeated.end(), numbered_from);
           r != repeated.end() && *r < offered_; ++r)
        fresh[*r - numbered_from] = false;
      return fresh;
    }
    std::vector<std::pair<Index, std::size_t>> keyed(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) keyed[k] = {lattice_index(b_, points[k].position), k};
    std::sort(keyed.begin(), keyed.end());  // (at one place, the earliest point first)
    std::vector<Index> taken;
    for (std::size_t k = 0; k < keyed.size(); ++k) {
      const Index& at = keyed[k].first;
      if ((k > 0 && keyed[k - 1].first == at) || std::binary_search(placed_.begin(), placed_.end(), at))
        fresh[keyed[k].second] = false;
      else
        taken.push_back(at);
    }
    const auto middle = placed_.insert(placed_.end(), taken.begin(), taken.end());
    std::inplace_merge(placed_.begin(), middle, placed_.end());
    if (b_.counting)
      for (std::size_t k = 0; k < points.size(); ++k)
        if (!fresh[k]) b_.counting->repeated_wall_points.push_back(numbered_from + k);
    return fresh;
  }

 private:
  SceneBuild<3>& b_;
  std::vector<Index> placed_;  // sorted
  std::uint64_t offered_ = 0;
};

// A wall's or a body's boundary particle at bp, where this process holds it (SceneBuild::add): its index, or none.
std::optional<std::size_t> add_boundary_point(SceneBuild<3>& b, const BoundaryPointOf<3>& bp, double density,
                                              double viscosity, const std::string& owner) {
  const auto i = b.add(bp.position, bp.layer == 0 ? Kind::wall : Kind::dummy, 0, density, viscosity);
  if (!i) return i;
  Particles<3>& P = b.particles();
  P.wall_normal[*i] = bp.normal;
  P.wall_depth[*i] = bp.depth;
  b.boundary_owner.push_back(owner);
  return i;
}

// On the fcc lattice a plane of symmetry must pass through one of the lattice's planes: then its particles are their
// own images and the images of the planes beside it are the lattice's next planes (A B A). A plane midway between two
// (B | A) puts A's images where B belongs, a second A 0.794 dp straight across from A: a stacking fault (stop 44,
// docs/three-d.md). So the lattice is moved along each plane's axis to meet it; two planes on one axis must then lie a
// whole number of plane spacings apart, to the billionth of dp within which a point counts as on a plane (and gets no
// image). On the square lattice the planes lie midway between planes, on multiples of dp
// (check_on_the_cubic_lattice), where the images continue the lattice: no move.
Vec<3> lattice_offset_for_planes(const SceneBuild<3>& b) {
  Vec<3> offset = Vec<3>::Zero();
  if (b.sim->options.lattice != LatticeKind::fcc) return offset;
  const double s = fcc_plane_spacing(b.dp);
  std::array<const SymmetryPlane*, 3> first{};
  for (const SymmetryPlane& plane : symmetry_planes(b.r)) {
    const MirrorPlane m = plane.mirror();
    const double move = m.at - (std::round(m.at / s - 0.5) + 0.5) * s;  // in [-s/2, s/2]
    if (!first[m.axis]) {
      first[m.axis] = &plane;
      offset[m.axis] = move;
      continue;
    }
    const double from = first[m.axis]->mirror().at, apart = (m.at - from) / s;
    const double nearest = from + std::round(apart) * s;  // m, the lattice's plane nearest to this one
    if (std::abs(m.at - nearest) > 1e-9 * b.dp)
      throw SceneError(plane.key, fmt::format("on the fcc lattice a plane of symmetry passes through one of the "
                                              "lattice's planes, {:.12g} m apart across {}; this one lies {:.9g} of "
                                              "them from {}: put it at {:.12g} m",
                                              s, "xyz"[m.axis], apart, first[m.axis]->key, nearest));
  }
  return offset;
}

// The box [lo, hi] closed on the planes of symmetry its faces lie on: a lattice point on such a plane is its own
// mirror image, and the inside's (the water's, a terrain's) as its images beyond would be.
std::array<Vec<3>, 2> closed_on_planes(const std::vector<SymmetryPlane>& planes, Vec<3> lo, Vec<3> hi, double eps) {
  for (const SymmetryPlane& plane : planes) {
    const MirrorPlane m = plane.mirror();
    Vec<3>& face = m.keeps_above ? lo : hi;
    if (std::abs(face[m.axis] - m.at) <= eps) face[m.axis] += m.keeps_above ? -2.0 * eps : 2.0 * eps;
  }
  return {lo, hi};
}

// Whether p lies on the scene's side of every plane of symmetry, or on one.
bool on_modelled_side(const std::vector<SymmetryPlane>& planes, const Vec<3>& p, double eps) {
  for (const SymmetryPlane& plane : planes)
    if (!plane.keeps(p) && !plane.holds(p, eps)) return false;
  return true;
}

// Whether a lattice point p belongs to the box [lo, hi], by the 2-D rules: on the square lattice its cell lies inside
// (within a billionth of dp); on the fcc lattice, whose walls are cut from the same lattice, its centre lies strictly
// inside (a point on a face is the wall's).
bool in_box(LatticeKind kind, const Vec<3>& p, const Vec<3>& lo, const Vec<3>& hi, double dp) {
  const double e = 1e-9 * dp, half = kind == LatticeKind::square ? 0.5 * dp : 0.0;
  const double slack = kind == LatticeKind::square ? e : -e;
  for (int a = 0; a < 3; ++a)
    if (p[a] - half < lo[a] - slack || p[a] + half > hi[a] + slack) return false;
  return true;
}

// On the cubic lattice a tank's faces must lie between lattice planes, on multiples of dp (all but its top): a face
// elsewhere leaves a plane that is neither wall nor water (its cell is not inside), a gap of up to 2 dp between them.
void check_on_the_cubic_lattice(const Vec<3>& lo, const Vec<3>& hi, double dp, std::size_t w) {
  const auto off = [dp](double v) { return std::abs(v / dp - std::round(v / dp)) > 1e-6; };
  for (int a = 0; a < 3; ++a)
    if (off(lo[a]) || (a < 2 && off(hi[a])))
      throw SceneError(fmt::format("walls[{}].{}", w, off(lo[a]) ? "min" : "max"),
                       fmt::format("on the square lattice a tank's faces lie on multiples of particle_spacing ({} m; "
                                   "max.z, its top, excepted), so that the walls continue the water's lattice; this one's "
                                   "{} is {:.9g} m, {:.6g} spacings: move it to a whole number",
                                   dp, "xyz"[a], off(lo[a]) ? lo[a] : hi[a], (off(lo[a]) ? lo[a] : hi[a]) / dp));
}

// A terrain's grid (walls[w].file), refused naming the key, the file and what is wrong with it.
HeightGrid terrain_grid(const SceneBuild<3>& b, const YAML::Node& wn, std::size_t w) {
  const std::filesystem::path file = b.scene_dir / wn["file"].as<std::string>();
  try {
    return read_height_grid(file);
  } catch (const std::exception& e) {  // what the reader says; a grid too large to hold (std::bad_alloc) as well
    throw SceneError(fmt::format("walls[{}].file", w), fmt::format("{}: {}", file.string(), e.what()));
  }
}

// How deep a terrain's particles reach under its surface: the kernel's radius on the fcc lattice, whole layers of dp
// on the square lattice, as a tank's walls (fluid/box_walls.hpp).
double terrain_reach(const SceneBuild<3>& b) {
  const FluidOptions<3>& opt = b.sim->options;
  return opt.lattice == LatticeKind::square ? boundary_layers(opt.re_over_dp) * b.dp : opt.re_over_dp * b.dp;
}

// A terrain (walls[w], type: terrain): its grid read from the scene's folder, its surface, and its boundary particles,
// the lattice's points below the surface to the kernel's reach (cases/terrain_layers.hpp). Built after the tanks: a
// point is kept strictly inside a tank (the tank's own points are its faces and beyond) and on the scene's side of its
// symmetry planes (the images beyond come from the mirror ghosts), and only where no wall has put one (`placed`).
void build_terrain(SceneBuild<3>& b, const YAML::Node& wn, std::size_t w, WallPlaces& places) {
  typename SceneBuild<3>::Terrain t;
  t.grid = terrain_grid(b, wn, w);
  t.surface = terrain_surface(t.grid);
  t.distance = std::make_shared<const mesh::MeshDistance>(t.surface, false);
  auto pts = terrain_layers(t.grid, *t.distance, b.sim->options.lattice, b.dp, terrain_reach(b),
                            b.scene->lattice_offset);
  const auto& first_phase = b.phases.phases[0];
  const double eps = 1e-9 * b.dp;
  const auto planes = symmetry_planes(b.r);
  std::vector<std::array<Vec<3>, 2>> insides;
  for (const auto& [lo, hi] : b.tanks) insides.push_back(closed_on_planes(planes, lo, hi, eps));
  const auto kept = [&](const Vec<3>& p) {
    return on_modelled_side(planes, p, eps) &&
           (insides.empty() || std::any_of(insides.begin(), insides.end(), [&](const auto& in) {
              return inside_tank(p, in[0], in[1], eps);
            }));
  };
  const std::string owner = fmt::format("walls[{}]", w);
  std::erase_if(pts, [&](const BoundaryPointOf<3>& bp) { return !b.in_period(bp.position[0]) || !kept(bp.position); });
  const std::vector<bool> first = places.first(pts);
  for (std::size_t k = 0; k < pts.size(); ++k)
    if (first[k]) add_boundary_point(b, pts[k], first_phase.density, first_phase.viscosity, owner);
  b.terrains.push_back(std::move(t));
}

// Whether water may stand at p as far as the terrains go: above each one it covers (cases/terrain_layers.hpp).
bool clear_of_terrains(const SceneBuild<3>& b, const Vec<3>& p) {
  return std::all_of(b.terrains.begin(), b.terrains.end(),
                     [&](const auto& t) { return above_terrain(t.grid, p, 1e-9 * b.dp); });
}

// Two planes of symmetry across one axis must stand at least two neighbour-search radii apart (the mirror images of
// each side's particles would otherwise meet the other's, coupling/simulation.cpp): refused here naming the plane and
// the spacing that would fit, before anything is made.
void refuse_planes_too_close(const SceneBuild<3>& b) {
  const auto planes = symmetry_planes(b.r);
  const double radius_over_dp = b.sim->options.re_over_dp + b.sim->options.skin_over_dp;
  for (std::size_t k = 0; k < planes.size(); ++k)
    for (std::size_t l = 0; l < k; ++l) {
      const MirrorPlane a = planes[l].mirror(), c = planes[k].mirror();
      const double apart = std::abs(a.at - c.at);
      if (a.axis != c.axis || apart >= 2.0 * radius_over_dp * b.dp) continue;
      throw SceneError(planes[k].key,
                       fmt::format("stands {:.6g} m from the plane of symmetry {} across {}: closer than twice the "
                                   "neighbour search's radius, 2 (method.kernel_radius + method.neighbor_skin) "
                                   "particle_spacing = {:.6g} m; particle_spacing {:.6g} m or less fits",
                                   apart, planes[l].key, "xyz"[c.axis], 2.0 * radius_over_dp * b.dp,
                                   apart / (2.0 * radius_over_dp)));
    }
}

}  // namespace

// Boundary particles of the first phase's density, as in 2-D; a point already placed by an earlier wall (where two
// tanks meet) is left out.
void build_walls(SceneBuild<3>& b) {
  const auto& first_phase = b.phases.phases[0];
  WallPlaces places(b);
  refuse_planes_too_close(b);
  b.scene->lattice_offset = lattice_offset_for_planes(b);
  for (std::size_t w = 0; w < b.r["walls"].size(); ++w) {
    const auto wn = b.r["walls"][w];
    if (wn["type"].as<std::string>() == "terrain") continue;  // after the tanks (build_terrain)
    const Vec<3> lo = vec_of<3>(wn["min"]), hi = vec_of<3>(wn["max"]);
    if (b.sim->options.lattice == LatticeKind::square) check_on_the_cubic_lattice(lo, hi, b.dp, w);
    // Sides of symmetry have no particles beyond them (the mirror images of what stands near them take their place);
    // on the fcc lattice those on one are their own images.
    unsigned mirror_sides = 0;
    for (std::size_t f = 0; f < wn["symmetry"].size(); ++f) {
      const std::string side = wn["symmetry"][f].as<std::string>();
      mirror_sides |= tank_side_bit(side[0] == 'x' ? 0 : 1, side.substr(2) == "max");
    }
    std::vector<BoundaryPointOf<3>> pts;
    try {
      const FluidOptions<3>& opt = b.sim->options;
      pts = tank_boundary(opt.lattice, lo, hi, b.dp, tank_layers(b, wn), opt.re_over_dp * b.dp, mirror_sides,
                          b.scene->lattice_offset);
    } catch (const std::invalid_argument& e) {
      throw SceneError(fmt::format("walls[{}].max", w), e.what());
    }
    std::erase_if(pts, [&](const BoundaryPointOf<3>& p) { return !b.in_period(p.position[0]); });
    const std::string owner = fmt::format("walls[{}]", w);
    const std::vector<bool> first = places.first(pts);
    for (std::size_t k = 0; k < pts.size(); ++k)
      if (first[k]) add_boundary_point(b, pts[k], first_phase.density, first_phase.viscosity, owner);
    b.tanks.push_back({lo, hi});
  }
  for (std::size_t w = 0; w < b.r["walls"].size(); ++w)
    if (b.r["walls"][w]["type"].as<std::string>() == "terrain") build_terrain(b, b.r["walls"][w], w, places);
}

// A tank's floor and its sides that are not planes of symmetry, two triangles each, as thick as its particles reach
// (fluid/box_walls.hpp); a terrain's triangles, facing up, as deep as its particles reach (terrain_reach).
std::vector<WallFace<3>> crossing_faces(const SceneBuild<3>& b) {
  std::vector<WallFace<3>> faces;
  const auto rectangle = [&](const Vec<3>& a, const Vec<3>& along, const Vec<3>& across, int axis, double sign,
                             double thickness) {
    const Vec<3> inward = sign * Vec<3>::Unit(axis);
    faces.push_back({{a, a + along, a + along + across}, inward, thickness});
    faces.push_back({{a, a + along + across, a + across}, inward, thickness});
  };
  const FluidOptions<3>& opt = b.sim->options;
  for (std::size_t w = 0; w < b.r["walls"].size(); ++w) {
    const auto wn = b.r["walls"][w];
    if (wn["type"].as<std::string>() == "terrain") continue;
    const Vec<3> lo = vec_of<3>(wn["min"]), hi = vec_of<3>(wn["max"]), size = hi - lo;
    const double thickness =
        opt.lattice == LatticeKind::square ? tank_layers(b, wn) * b.dp : opt.re_over_dp * b.dp;
    std::set<std::string> symmetric;
    for (std::size_t f = 0; f < wn["symmetry"].size(); ++f) symmetric.insert(wn["symmetry"][f].as<std::string>());
    const Vec<3> x = Vec<3>::UnitX() * size[0], y = Vec<3>::UnitY() * size[1], z = Vec<3>::UnitZ() * size[2];
    rectangle(lo, x, y, 2, 1.0, thickness);
    if (!symmetric.count("x_min")) rectangle(lo, y, z, 0, 1.0, thickness);
    if (!symmetric.count("x_max")) rectangle(lo + x, y, z, 0, -1.0, thickness);
    if (!symmetric.count("y_min")) rectangle(lo, x, z, 1, 1.0, thickness);
    if (!symmetric.count("y_max")) rectangle(lo + y, x, z, 1, -1.0, thickness);
  }
  for (const auto& t : b.terrains)
    for (const auto& tri : t.surface.triangles) {
      const Vec<3> p0 = t.surface.vertices[tri[0]], p1 = t.surface.vertices[tri[1]], p2 = t.surface.vertices[tri[2]];
      Vec<3> up = (p1 - p0).cross(p2 - p0).normalized();
      if (up[2] < 0.0) up = -up;
      faces.push_back({{p0, p1, p2}, up, terrain_reach(b)});
    }
  return faces;
}

namespace {

// The deformable slide whose shape holds p (its centre strictly inside); -1 when none does. Slide and water particles
// sit on the same lattice, so the shape alone divides them, with no gap.
int slide_holding(const SceneBuild<3>& b, const Vec<3>& p) {
  for (std::size_t k = 0; k < b.slides.size(); ++k) {
    const auto& s = b.slides[k];
    // Its surface's bounding box first: the signed distance (a ray-parity test) for every water point was the cost.
    bool in_box = true;
    for (int a = 0; a < 3; ++a) in_box = in_box && p[a] >= s.lo[a] && p[a] <= s.hi[a];
    if (in_box && s.signed_distance(p) < 0.0) return static_cast<int>(k);
  }
  return -1;
}

// Fills the deformable slides (before the water), then the regions: box, the particles whose cell lies inside
// [min, max] (one inside a slide is an error); below_level, those whose cell lies inside a tank, with their centre
// below the level and outside the slides (which raises the still-water level to it). All on the scene's lattice (moved
// to meet its planes of symmetry), on the scene's side of those planes, a point on one included (its own image), and
// clear of the bodies and above the terrains.
struct RegionFill {
  SceneBuild<3>& b;
  std::vector<SymmetryPlane> planes;
  std::vector<std::array<Vec<3>, 2>> insides;  // the tanks', closed on the planes and open above

  explicit RegionFill(SceneBuild<3>& build) : b(build), planes(symmetry_planes(build.r)) {
    for (const auto& [lo, hi] : b.tanks) {
      insides.push_back(closed_on_planes(planes, lo, hi, 1e-9 * b.dp));
      insides.back()[1][2] = INFINITY;
    }
  }

  bool in_tank(const Vec<3>& p, std::size_t u) const {
    return in_box(b.sim->options.lattice, p, insides[u][0], insides[u][1], b.dp);
  }

  // Visits the lattice points of [lo, hi] that the scene's geometry leaves to fluid, adding those `inside` accepts as
  // phase `ph` owned by `path`; returns how many (the whole build's, whether this process holds them or not).
  template <class Inside>
  std::size_t fill(const Vec<3>& lo, const Vec<3>& hi, std::size_t ph, const std::string& path, Inside&& inside) {
    const auto& phase = b.phases.phases[ph];
    const double eps = 1e-9 * b.dp;
    std::size_t added = 0;
    for_each_lattice_point(b.sim->options.lattice, b.dp, lo, hi, [&](const Vec<3>& p) {
      // The scene's side first: `inside` may refuse a point (outside the tanks, in a slide) that a plane cuts off.
      if (!b.in_period(p[0]) || !on_modelled_side(planes, p, eps) || !inside(p) || body_near(b, p) >= 0 ||
          !clear_of_terrains(b, p))
        return;
      if (b.add(p, Kind::fluid, static_cast<std::uint8_t>(ph), phase.density, phase.viscosity))
        b.fluid_owner.push_back(path);
      ++added;
    }, b.scene->lattice_offset);
    return added;
  }

  // Water outside every tank (where the scene has tanks: nothing would hold it) or inside a deformable slide is an
  // error naming the region (`outside_key`: the key that places it).
  void refuse_misplaced(const Vec<3>& p, const std::string& path, const std::string& outside_key) const {
    bool in_a_tank = insides.empty();
    for (std::size_t u = 0; u < insides.size(); ++u) in_a_tank = in_a_tank || in_tank(p, u);
    if (!in_a_tank) throw SceneError(outside_key, fmt::format("water at {} lies outside every tank", position_text(p)));
    if (const int k = slide_holding(b, p); k >= 0)
      throw SceneError(path, fmt::format("water at {} lies inside the deformable slide {}", position_text(p),
                                         b.slides[k].path));
  }

  void refuse_if_empty(std::size_t added, const std::string& path) const {
    if (added == 0) throw SceneError(path, fmt::format("the region holds no particle at spacing dp = {} m", b.dp));
  }

  // A slide: the lattice points inside its shape (and inside a tank, where the scene has tanks).
  void slide(std::size_t k) {
    const auto& s = b.slides[k];
    refuse_if_empty(fill(s.lo, s.hi, s.phase, s.path, [&](const Vec<3>& p) {
                      if (s.signed_distance(p) >= 0.0) return false;
                      bool in_a_tank = insides.empty();
                      for (std::size_t u = 0; u < insides.size(); ++u) in_a_tank = in_a_tank || in_tank(p, u);
                      return in_a_tank;
                    }),
                    s.path);
  }

  void box(const YAML::Node& rn, std::size_t ph, const std::string& path) {
    const Vec<3> lo = vec_of<3>(rn["min"]), hi = vec_of<3>(rn["max"]);
    for (int a = 0; a < 3; ++a)
      if (!(lo[a] < hi[a])) throw SceneError(path + ".max", "must exceed min in x, y and z");
    const auto [in_lo, in_hi] = closed_on_planes(planes, lo, hi, 1e-9 * b.dp);
    refuse_if_empty(fill(lo, hi, ph, path, [&](const Vec<3>& p) {
                      if (!in_box(b.sim->options.lattice, p, in_lo, in_hi, b.dp)) return false;
                      refuse_misplaced(p, path, path + ".max");
                      return true;
                    }),
                    path);
  }

  // The lattice points strictly inside the shape; one outside every tank (where there are tanks) or inside a slide is
  // an error naming the region.
  void shape(const YAML::Node& rn, std::size_t ph, const std::string& path) {
    const SolidShape s = region_solid_shape(rn["shape"], path, b.dp, b.scene_dir);
    Vec<3> lo = s.surface.vertices[0], hi = lo;
    for (const auto& v : s.surface.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    refuse_if_empty(fill(lo, hi, ph, path, [&](const Vec<3>& p) {
                      if (s.signed_distance(p) >= 0.0) return false;
                      refuse_misplaced(p, path, path + ".shape");
                      return true;
                    }),
                    path);
  }

  void below_level(const YAML::Node& rn, std::size_t ph, const std::string& path) {
    if (b.tanks.empty()) throw SceneError(path, "a below_level region needs a tank around it");
    const double level = rn["level"].as<double>();
    b.still_level = std::max(b.still_level, level);
    std::size_t added = 0;
    for (std::size_t t = 0; t < b.tanks.size(); ++t) {
      const auto& [lo, hi] = b.tanks[t];
      Vec<3> top = hi;
      top[2] = std::min(hi[2], level);
      const auto inside = [&](const Vec<3>& p) {
        bool earlier = false;  // inside a tank already filled (tanks that overlap)
        for (std::size_t u = 0; u < t; ++u) earlier = earlier || in_tank(p, u);
        // below the level and the tank's top, outside the slides
        return p[2] < top[2] && in_tank(p, t) && !earlier && slide_holding(b, p) < 0;
      };
      added += fill(lo, top, ph, path, inside);
    }
    refuse_if_empty(added, path);
  }
};

}  // namespace

void fill_fluid_regions(SceneBuild<3>& b) {
  Particles<3>& P = b.particles();
  b.boundary_count = P.size();
  if (b.r["fluid"]["regions"].size() == 0 && b.slides.empty())
    throw SceneError("fluid.regions", "expected at least 1 item (a scene without water needs a deformable slide)");
  RegionFill fill(b);
  for (std::size_t k = 0; k < b.slides.size(); ++k) fill.slide(k);
  for (std::size_t k = 0; k < b.r["fluid"]["regions"].size(); ++k) {
    const auto rn = b.r["fluid"]["regions"][k];
    const std::string path = fmt::format("fluid.regions[{}]", k);
    const std::size_t ph = b.phases.find(rn["phase"].as<std::string>(), path + ".phase");
    const std::string type = rn["type"].as<std::string>();
    if (type == "box") fill.box(rn, ph, path);
    else if (type == "shape") fill.shape(rn, ph, path);
    else fill.below_level(rn, ph, path);
  }
  if (b.counted) {  // (built in parts: the whole scene's box, as counted)
    b.lo = b.counted->lo;
    b.hi = b.counted->hi;
    return;
  }
  if (P.size() == 0) return;  // (the counting pass)
  b.lo = b.hi = P.position[0];
  for (const auto& x : P.position) b.lo = b.lo.cwiseMin(x), b.hi = b.hi.cwiseMax(x);
}

namespace {

// The volume below `level` inside the tank [lo, hi] and above the terrains: the midpoint rule on squares of dp over its
// floor, each square's column from the highest terrain there (the tank's floor where none is) up to the level.
double water_volume_below(double level, const Vec<3>& lo, const Vec<3>& hi, const std::vector<HeightGrid>& terrains,
                          double dp) {
  const double top = std::min(level, hi[2]);
  if (!(top > lo[2])) return 0.0;
  const long nx = std::max(1L, std::lround((hi[0] - lo[0]) / dp)), ny = std::max(1L, std::lround((hi[1] - lo[1]) / dp));
  const double ax = (hi[0] - lo[0]) / double(nx), ay = (hi[1] - lo[1]) / double(ny);
  double volume = 0.0;
  for (long i = 0; i < nx; ++i)
    for (long j = 0; j < ny; ++j) {
      double ground = lo[2];
      for (const auto& g : terrains) {
        const double h = terrain_height(g, lo[0] + (double(i) + 0.5) * ax, lo[1] + (double(j) + 0.5) * ay);
        if (std::isfinite(h)) ground = std::max(ground, h);
      }
      volume += ax * ay * std::max(0.0, top - ground);
    }
  return volume;
}

}  // namespace

// Regions: their volume; below_level water: the volume below the level inside each tank and above its terrains;
// tanks: their floor and sides' area times their layers' thickness; terrains: their area times their layers' reach.
double estimated_particles(const SceneBuild<3>& b) {
  const double dp = b.dp, cell = dp * dp * dp;
  double n = 0.0, level = -INFINITY;
  for (std::size_t k = 0; k < b.r["fluid"]["regions"].size(); ++k) {
    const auto rn = b.r["fluid"]["regions"][k];
    const std::string type = rn["type"].as<std::string>();
    if (type == "box") {
      const Vec<3> size = (vec_of<3>(rn["max"]) - vec_of<3>(rn["min"])).cwiseMax(0.0);
      n += size.prod() / cell;
    } else if (type == "shape") {
      n += region_solid_shape(rn["shape"], fmt::format("fluid.regions[{}]", k), dp, b.scene_dir).whole_volume / cell;
    } else {
      level = std::max(level, rn["level"].as<double>());
    }
  }
  std::vector<HeightGrid> terrains;
  for (std::size_t w = 0; w < b.r["walls"].size(); ++w) {
    const auto wn = b.r["walls"][w];
    if (wn["type"].as<std::string>() != "terrain") continue;
    terrains.push_back(terrain_grid(b, wn, w));
    const rigid::TriangleSurface s = terrain_surface(terrains.back());
    double area = 0.0;
    for (const auto& t : s.triangles)
      area += 0.5 * (s.vertices[t[1]] - s.vertices[t[0]]).cross(s.vertices[t[2]] - s.vertices[t[0]]).norm();
    n += area * terrain_reach(b) / cell;
  }
  for (const auto& wn : b.r["walls"]) {
    if (wn["type"].as<std::string>() != "tank") continue;
    const Vec<3> size = (vec_of<3>(wn["max"]) - vec_of<3>(wn["min"])).cwiseMax(0.0);
    const long layers_key = wn["layers"].as<long>();
    const double t = dp * (layers_key == 0 ? boundary_layers(b.sim->options.re_over_dp) : layers_key);
    const double floor = (size[0] + 2 * t) * (size[1] + 2 * t) * t;
    const double sides = 2.0 * (size[0] + size[1] + 4 * t) * t * size[2];
    n += (floor + sides) / cell;
    if (std::isfinite(level))
      n += water_volume_below(level, vec_of<3>(wn["min"]), vec_of<3>(wn["max"]), terrains, dp) / cell;
  }
  return n;
}

}  // namespace slide::cases
