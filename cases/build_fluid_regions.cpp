// Step: the fluid regions (fluid.regions[]): rectangle, polygon and below_level, each filled with particles of its
// phase on the lattice; then the overlap checks (water on a boundary particle, or two regions on each other).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include "cases/scene_build.hpp"
#include "coupling/position_text.hpp"
#include "fluid/neighbor_grid.hpp"
#include "fluid/walls.hpp"

namespace slide::cases {
namespace {

// The lattice points a region takes: those in [lo, hi] for which `inside` holds; of the fluid's lattice, or of the
// lattice laid along a wall face (fluid/lattice.hpp, face_lattice_point) where `along` is set.
struct RegionShape {
  Vec<2> lo, hi;
  std::function<bool(const Vec<2>&)> inside;
  std::optional<FaceSegment> along = std::nullopt;
};

// The particles of the deformable slides, to keep the water a spacing clear of them (fill_region).
struct SlidePoints {
  std::vector<Vec<2>> position;
  NeighborGrid<2> grid;
  bool near(const Vec<2>& p, double distance) const {
    bool found = false;
    if (!position.empty())
      grid.for_each_near(p, distance, position, [&](std::uint32_t, double) { found = true; });
    return found;
  }
};

// The deformable slide whose outline holds p; -1 when none does. (Slide and water particles sit on the same lattice,
// so the outline alone divides them, with no gap.)
int slide_holding(const SceneBuild<2>& b, const Vec<2>& p) {
  for (std::size_t k = 0; k < b.slides.size(); ++k)
    if (rigid::contains(b.slides[k].outline, rigid::Vec2(p[0], p[1]))) return static_cast<int>(k);
  return -1;
}

// The body whose outline holds p or lies within dp/2 of it; -1 when p is clear of every body.
int body_near(const SceneBuild<2>& b, const Vec<2>& p) {
  for (std::size_t k = 0; k < b.outlines.size(); ++k) {
    const rigid::Vec2 q(p[0], p[1]);
    if (rigid::contains(b.outlines[k], q) || rigid::distance_to_outline(b.outlines[k], q) < 0.5 * b.dp - 1e-9 * b.dp)
      return static_cast<int>(k);
  }
  return -1;
}

// The particles of [min, max]: on the square lattice those whose cell (dp / 2 each way) lies inside; on the hexagonal
// lattice those whose centre lies inside, as for polygons: its walls are cut from the same lattice, so a wall face
// splits the lattice and the water fills it up to the wall, and a free side loses or gains half a cell on average.
// (Whole cells on the hexagonal lattice lost up to a cell layer on two sides: 5.5 % of the gated dam break's water.)
// A rectangle that spans a periodic domain's period takes the period's points in x (SceneBuild::in_period).
RegionShape rectangle(const SceneBuild<2>& b, const YAML::Node& rn, const std::string& path) {
  const Vec<2> lo = vec2(rn["min"]), hi = vec2(rn["max"]);
  if (!(lo[0] < hi[0] && lo[1] < hi[1])) throw SceneError(path + ".max", "must exceed min in x and y");
  const bool whole_cells = b.sim->options.lattice == LatticeKind::square;
  // Whole cells: a cell edge on the rectangle's side counts as inside (e > 0); centres: a centre on a side, where a
  // wall cut from the lattice puts its own particle, does not (e < 0).
  const double half = whole_cells ? 0.5 * b.dp : 0.0;
  const double e = (whole_cells ? 1e-9 : -1e-9) * b.dp;
  const bool spans_period = b.period_x && lo[0] <= b.period_x->x_min + 1e-9 * b.dp &&
                            hi[0] >= b.period_x->x_max - 1e-9 * b.dp;
  return {lo, hi, [lo, hi, half, e, spans_period](const Vec<2>& p) {
            const bool in_x = spans_period || (p[0] - half >= lo[0] - e && p[0] + half <= hi[0] + e);
            return in_x && p[1] - half >= lo[1] - e && p[1] + half <= hi[1] + e;
          }};
}

// The particles whose centre lies inside the polygon.
RegionShape polygon(const YAML::Node& rn) {
  const std::vector<Vec<2>> poly = points_of(rn["points"]);
  Vec<2> lo = poly[0], hi = poly[0];
  for (const auto& q : poly) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  return {lo, hi, [poly](const Vec<2>& p) { return inside_polygon(poly, p); }};
}

// Water below a level inside the walls, clear of the bodies, from each face's clearance on (fluid/walls.hpp,
// water_clearance: on the hexagonal lattice a wall along its rows or columns holds every lattice point on or behind
// the face and the water every one in front of it; elsewhere the water starts half a row or a spacing in front).
// Raises the still-water level to this one.
RegionShape below_level(SceneBuild<2>& b, const YAML::Node& rn, const std::string& path) {
  if (b.faces.empty()) throw SceneError(path, "a below_level region needs walls around it");
  const double level = rn["level"].as<double>();
  Vec<2> face_lo, face_hi;
  face_bounds(b.faces, face_lo, face_hi);
  b.still_level = std::max(b.still_level, level);
  return {face_lo, Vec<2>(face_hi[0], std::min(level, face_hi[1])), [&b, level](const Vec<2>& p) {
            return p[1] < level && clear_of_faces(b.faces, p, 1e-9 * b.dp) && body_near(b, p) < 0 &&
                   slide_holding(b, p) < 0;
          }};
}

// A deformable slide: the lattice points inside its outline and in front of the walls (as water is placed). A slide
// resting on a face along neither of the lattice's axes (fluid/walls.hpp, along_lattice_axes) is laid on rows along
// that face (fluid/lattice.hpp, face_lattice_point; on the hexagonal lattice they continue the wall's rows): its base
// is then one flat row on the wall's flat row. Why: cut from the fluid's lattice, the base is a staircase, and a stiff
// sediment block on a frictionless 20 degree slope accelerated 6.1 % below g sin(beta) on the hexagonal lattice (the
// wall's rows along the face), and 3.2 % below at 35 degrees on the square lattice, pressed onto its face while it
// settled (coupling/relaxation.hpp); on rows along the face, -0.9 % and -0.8 % (issue 29, item 3).
RegionShape slide_shape(const SceneBuild<2>& b, const SceneBuild<2>::Slide& slide) {
  Vec<2> lo = from_rigid(slide.outline[0]), hi = lo;
  for (const auto& v : slide.outline) lo = lo.cwiseMin(from_rigid(v)), hi = hi.cwiseMax(from_rigid(v));
  const auto outline = slide.outline;
  RegionShape shape{lo, hi, [&b, outline](const Vec<2>& p) {
                      return rigid::contains(outline, rigid::Vec2(p[0], p[1])) &&
                             (b.faces.empty() || clear_of_faces(b.faces, p, 1e-9 * b.dp));
                    },
                    std::nullopt};
  const Vec<2>& g = b.sim->options.gravity;
  const Vec<2> down = g.norm() > 0.0 ? Vec<2>(g.normalized()) : Vec<2>(0.0, -1.0);
  if (const auto face = resting_face(b.faces, slide.outline, b.dp, down);
      face && !along_lattice_axes(face->a, face->b))
    shape.along = face;
  return shape;
}

RegionShape region_shape(SceneBuild<2>& b, const YAML::Node& rn, const std::string& path) {
  const std::string type = rn["type"].as<std::string>();
  if (type == "rectangle") return rectangle(b, rn, path);
  if (type == "polygon") return polygon(rn);
  return below_level(b, rn, path);
}

// Fills region k with fluid particles of phase `ph` (in a periodic domain, its points in the period:
// SceneBuild::in_period); a lattice point on or near a body is an error. Water leaves out a point closer than a
// spacing to a slide's particle: none on the slide's own lattice (its nearest neighbours are a spacing or more
// apart), some beside a slide laid on a face's rows (slide_shape).
void fill_region(SceneBuild<2>& b, const RegionShape& shape, std::size_t ph, const std::string& path, bool slide_itself,
                 const SlidePoints& slides) {
  Particles<2>& P = b.particles();
  const auto& phase = b.phases.phases[ph];
  std::size_t added = 0;
  auto take = [&](const Vec<2>& p) {
    if (!b.in_period(p[0]) || !shape.inside(p)) return;
    if (const int body = body_near(b, p); body >= 0)
      throw SceneError(path, fmt::format("water at ({:.6g}, {:.6g}) lies inside body bodies[{}] or within dp/2 of "
                                         "its outline",
                                         p[0], p[1], body));
    if (const int slide = slide_itself ? -1 : slide_holding(b, p); slide >= 0)
      throw SceneError(path, fmt::format("water at ({:.6g}, {:.6g}) lies inside the deformable slide {}", p[0], p[1],
                                         b.slides[slide].path));
    if (!slide_itself && slides.near(p, b.dp * (1.0 - 1e-9))) return;
    P.add(p, Kind::fluid, static_cast<std::uint8_t>(ph), phase.density, phase.viscosity);
    b.fluid_owner.push_back(path);
    ++added;
  };
  const LatticeKind kind = b.sim->options.lattice;
  if (shape.along)
    for_each_face_lattice_point(kind, b.dp, shape.along->a, (shape.along->b - shape.along->a).normalized(),
                                shape.along->inward, shape.lo, shape.hi, take);
  else
    for_each_lattice_point(kind, b.dp, shape.lo, shape.hi, take, b.scene->lattice_offset);
  if (added == 0) throw SceneError(path, fmt::format("the region holds no particle at spacing dp = {} m", b.dp));
}

}  // namespace

void fill_fluid_regions(SceneBuild<2>& b) {
  if (b.r["fluid"]["regions"].size() == 0 && b.slides.empty())
    throw SceneError("fluid.regions", "expected at least 1 item (a scene without water needs a deformable slide)");
  b.boundary_count = b.particles().size();
  SlidePoints slides;
  for (const auto& slide : b.slides) fill_region(b, slide_shape(b, slide), slide.phase, slide.path, true, slides);
  const Particles<2>& placed = b.particles();
  slides.position.assign(placed.position.begin() + static_cast<std::ptrdiff_t>(b.boundary_count),
                         placed.position.end());
  if (!slides.position.empty()) {
    Vec<2> lo = slides.position[0], hi = lo;
    for (const auto& x : slides.position) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    slides.grid = NeighborGrid<2>(lo - Vec<2>::Constant(b.dp), hi + Vec<2>::Constant(b.dp), b.dp);
    slides.grid.bin(slides.position);
  }
  for (std::size_t k = 0; k < b.r["fluid"]["regions"].size(); ++k) {
    const auto rn = b.r["fluid"]["regions"][k];
    const std::string path = fmt::format("fluid.regions[{}]", k);
    const std::size_t ph = b.phases.find(rn["phase"].as<std::string>(), path + ".phase");
    fill_region(b, region_shape(b, rn, path), ph, path, false, slides);
  }
  // The bounding box of the particles as placed (before the hydrostatic start moves them).
  const Particles<2>& P = b.particles();
  b.lo = b.hi = P.position[0];
  for (const auto& x : P.position) b.lo = b.lo.cwiseMin(x), b.hi = b.hi.cwiseMax(x);
}

// Fluid particles closer than 0.75 dp to a boundary particle or to a particle of an earlier region.
template <int D>
void check_overlaps(SceneBuild<D>& b) {
  const Particles<D>& P = b.particles();
  const double dp = b.dp;
  const std::size_t n_boundary = b.boundary_count;
  if (P.size() == 0) return;  // (a part of a scene built in parts may hold none)
  // Over the particles made here (a scene built in parts, cases/build_share.hpp: its own columns and a margin wider
  // than 0.75 dp), in the order made: boundary particles first, then fluid by id.
  Vec<D> lo = P.position[0], hi = P.position[0];
  for (const auto& x : P.position) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
  NeighborGrid<D> g(lo - Vec<D>::Constant(dp), hi + Vec<D>::Constant(dp), dp);
  g.bin(P.position);
  for (std::size_t i = n_boundary; i < P.size(); ++i) {
    const std::string& path = b.fluid_owner[i - n_boundary];
    g.for_each_near(P.position[i], 0.75 * dp, P.position, [&](std::uint32_t j, double r2) {
      if (j == i) return;
      if (j < n_boundary)
        throw SceneError(path, fmt::format("water overlaps {}: a particle at {} is {:.3g} dp "
                                           "from one of its boundary particles (at least 0.75 dp needed)",
                                           b.boundary_owner[j], position_text<D>(P.position[i]), std::sqrt(r2) / dp));
      if (j < i)
        throw SceneError(path, fmt::format("overlaps {} at {}", b.fluid_owner[j - n_boundary],
                                           position_text<D>(P.position[i])));
    });
  }
}

template void check_overlaps(SceneBuild<2>&);
template void check_overlaps(SceneBuild<3>&);

}  // namespace slide::cases
