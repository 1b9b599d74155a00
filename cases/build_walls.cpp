// Step: the walls (walls[]): their faces, and their wall and dummy particles (square lattice: layers behind the
// face polyline; hexagonal: the lattice points behind faces along its rows or columns, rows laid along any other
// face, to the depth re: fluid/walls.hpp), each owned by its wall for messages. On the hexagonal lattice with bodies,
// the lattice is first moved to meet the first body's bottom.
#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "cases/scene_build.hpp"
#include "cases/wall_side.hpp"
#include "fluid/walls.hpp"

namespace slide::cases {
namespace {

// With bodies on the hexagonal lattice, the lattice is moved up or down (by less than half a row spacing) so that
// a row lies dp/2 below the lowest point of the first body, where the fluid fill puts its nearest water. Why: the
// lattice's rows are 0.93 dp apart and fixed, so water under a body would otherwise start up to a row spacing
// further off than dp/2; the water cannot close such a gap under a held body (at rest, particles on a lattice
// resist shear like a solid), and on release a block of water density sank 6.5 mm onto it (issue 4's note).
Vec<2> lattice_offset_for_bodies(const SceneBuild<2>& b) {
  Vec<2> offset = Vec<2>::Zero();
  if (!b.close_packed || b.r["bodies"].size() == 0) return offset;
  double lowest = std::numeric_limits<double>::infinity();
  for (const auto& v : body_outline(b.r["bodies"][0], "bodies[0]")) lowest = std::min(lowest, v[1]);
  offset[1] = row_offset_to_meet(b.sim->options.lattice, b.dp, lowest - 0.5 * b.dp);
  return offset;
}

// The boundary points of one wall's face.
std::vector<BoundaryPoint> wall_points(const SceneBuild<2>& b, const YAML::Node& wn, std::size_t w,
                                       const std::vector<Vec<2>>& face, bool left) {
  const FluidOptions<2>& opt = b.sim->options;
  const long layers_key = wn["layers"].as<long>();
  const int layers = layers_key == 0 ? boundary_layers(opt.re_over_dp) : static_cast<int>(layers_key);
  std::vector<BoundaryPoint> pts;
  try {
    pts = b.close_packed ? lattice_boundary(face, left, b.dp, opt.re_over_dp * b.dp, opt.lattice, b.scene->lattice_offset)
                      : polyline_boundary(face, left, b.dp, layers);
  } catch (const std::invalid_argument& e) {
    throw SceneError(fmt::format("walls[{}].points", w), e.what());
  }
  // Along a periodic x the wall's points are those of one period (SceneBuild::in_period), so a wall may run past
  // the period's ends and joins itself across the seam; a wall with no point in the period is an error.
  std::erase_if(pts, [&](const BoundaryPoint& p) { return !b.in_period(p.position[0]); });
  if (pts.empty())
    throw SceneError(fmt::format("walls[{}].points", w), "the wall has no point inside the periodic domain's period "
                                                         "[domain.min.x, domain.max.x)");
  return pts;
}

// Boundary particles of the first phase's density; they carry no viscosity of their own. A point within dp/2 of a
// particle already placed is left out (overlapping layers at convex corners or where walls meet).
void add_wall_particles(SceneBuild<2>& b, const std::vector<BoundaryPoint>& pts, std::size_t w) {
  Particles<2>& P = b.particles();
  const double dp = b.dp;
  const auto& first_phase = b.phases.phases[0];
  for (const auto& bp : pts) {
    bool duplicate = false;
    for (std::size_t i = 0; i < P.size() && !duplicate; ++i)
      duplicate = distance_squared<2>(P.position[i], bp.position) < 0.25 * dp * dp;
    if (duplicate) continue;
    const std::size_t i =
        P.add(bp.position, bp.layer == 0 ? Kind::wall : Kind::dummy, 0, first_phase.density, first_phase.viscosity);
    P.wall_normal[i] = bp.normal;
    P.wall_depth[i] = bp.depth;
    b.boundary_owner.push_back(fmt::format("walls[{}]", w));
  }
}

// A gate is checked before anything runs: it needs the settled start, and a domain that is not periodic (the
// gate's particles are taken away from the real particles, which periodic ghosts copy).
void check_gate(const SceneBuild<2>& b, std::size_t w) {
  const std::string key = fmt::format("walls[{}].gate", w);
  if (b.initial_state != InitialState::settled)
    throw SceneError(key, "a gate needs method.initial_state: settled (it holds the water while it settles, and is "
                          "taken away at t = 0)");
  if (b.period_x)
    throw SceneError(key, "a gate cannot be used with a periodic domain (domain.periodic_x)");
}

}  // namespace

// Lasting walls first, then gates: a point within dp/2 of a particle already placed is left out, so a gate laid
// first would take the places of the floor's particles it crosses, and lifting it would leave a hole. A gate's face
// is not one of the scene's faces: bodies do not collide with it, and regions are not laid by it (water on either
// side of a gate is a rectangle or polygon region; a below_level region fills the tank as if there were no gate, and
// the overlap check then refuses water on the gate's particles).
void build_walls(SceneBuild<2>& b) {
  b.scene->lattice_offset = lattice_offset_for_bodies(b);
  for (const bool gates : {false, true})
    for (std::size_t w = 0; w < b.r["walls"].size(); ++w) {
      const auto wn = b.r["walls"][w];
      if (wn["gate"].as<bool>() != gates) continue;
      if (gates) check_gate(b, w);
      const auto face = points_of(wn["points"]);
      const bool left = fluid_side_names.parse(wn["fluid_side"].as<std::string>()) == FluidSide::left;
      const std::vector<BoundaryPoint> pts = wall_points(b, wn, w, face, left);
      const std::size_t first = b.particles().size();
      add_wall_particles(b, pts, w);
      if (gates)
        for (std::size_t i = first; i < b.particles().size(); ++i) b.gate_ids.push_back(b.particles().id[i]);
      else
        for (auto f : face_segments(face, left)) {
          f.clearance = water_clearance(b.sim->options.lattice, b.dp, f.a, f.b);
          b.faces.push_back(f);
        }
    }
}

// The fixed walls' faces, each as thick as its particle layers (fluid/wall_crossing.hpp); 3-D's: build_geometry_3d.cpp.
std::vector<WallFace<2>> crossing_faces(const SceneBuild<2>& b) {
  std::vector<WallFace<2>> faces;
  const double thickness = boundary_layers(b.sim->options.re_over_dp) * b.dp;
  for (const auto& f : b.faces) faces.push_back({{f.a, f.b}, f.inward, thickness});
  return faces;
}

}  // namespace slide::cases
