// Step: fluid that nothing holds. A fluid particle with no wall face and no body below it, along gravity, would fall
// out of the domain and be taken out of the run (coupling/simulation.hpp): that is almost always a scene without the
// floor it meant to have, so the scene is refused on the region that made the particles, unless
// checks.allow_uncontained_fluid says the water is meant to fall (a jet, a waterfall off an edge).
#include <fmt/format.h>

#include <map>

#include "cases/scene_build.hpp"
#include "cases/scene_geometry.hpp"

namespace slide::cases {

namespace {

// Whether the ray from p along gravity meets a wall face or a body's outline.
bool held(const SceneBuild<2>& b, const Vec<2>& p, const Vec<2>& down) {
  for (const auto& f : b.faces)
    if (ray_meets_segment(p, down, f.a, f.b)) return true;
  for (const auto& outline : b.outlines)
    for (std::size_t k = 0; k < outline.size(); ++k)
      if (ray_meets_segment(p, down, from_rigid(outline[k]), from_rigid(outline[(k + 1) % outline.size()])))
        return true;
  return false;
}

}  // namespace

void check_fluid_contained(SceneBuild<2>& b) {
  // Along a periodic x the water cannot leave sideways: only gravity across it can take it out.
  const Vec<2> g = b.period_x ? Vec<2>(0.0, b.options().gravity[1]) : b.options().gravity;
  if (g.norm() == 0.0 || b.r["checks"]["allow_uncontained_fluid"].as<bool>()) return;
  const Particles<2>& P = b.particles();
  std::map<std::string, std::size_t> loose;  // by the key that made them
  std::map<std::string, Vec<2>> first;
  for (std::size_t i = b.boundary_count; i < P.size(); ++i) {
    if (P.kind[i] != Kind::fluid || held(b, P.position[i], g)) continue;
    const std::string& owner = b.fluid_owner[i - b.boundary_count];
    if (loose[owner]++ == 0) first[owner] = P.position[i];
  }
  if (loose.empty()) return;
  const auto& [owner, count] = *loose.begin();
  throw SceneError(owner, fmt::format("{} of its particles (the first at ({:.6g}, {:.6g})) have no wall or body below "
                                      "them along gravity: they would fall out of the domain; add the wall that "
                                      "holds them, or set checks.allow_uncontained_fluid: true if they are meant to",
                                      count, first[owner][0], first[owner][1]));
}

}  // namespace slide::cases
