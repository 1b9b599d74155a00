#pragma once
// Private to cases/: what the steps of build_scene (cases/scene.cpp) share while a scene is built. Each step reads
// the resolved scene and adds to the simulation; what a later step needs from an earlier one is kept here.
#include <yaml-cpp/yaml.h>

#include <array>
#include <filesystem>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cases/build_share.hpp"
#include "cases/height_grid.hpp"
#include "cases/initial_state.hpp"
#include "cases/rheology_keys.hpp"
#include "cases/scene.hpp"
#include "cases/same_machine.hpp"
#include "cases/scene_geometry.hpp"
#include "coupling/rigid_bodies.hpp"
#include "fluid/periodic.hpp"
#include "mesh/mesh_distance.hpp"

namespace slide::cases {

// The fluid phases, by name and index (fluid.phases).
struct ScenePhases {
  struct Properties {
    std::string name;
    double density = 0.0;    // kg/m^3
    double viscosity = 0.0;  // Pa s, the particles' viscosity as made (a non-Newtonian model's at rest)
    Rheology rheology = Newtonian{1e-3};
    double basal_friction = std::numeric_limits<double>::infinity();  // mu_b; infinity: no-slip
  };
  std::map<std::string, std::size_t> index;  // name -> index into `phases` (Particles::phase)
  std::vector<Properties> phases;

  // The phase a region names; the empty name is the first phase. Throws SceneError at `key` for an unknown name.
  std::size_t find(const std::string& name, const std::string& key) const;
  // Adds a phase (a deformable slide's); throws SceneError at `key` if the name is taken or there are too many.
  std::size_t add(const std::string& name, double density, const Rheology& rheology, double basal_friction,
                  const std::string& key);
};

// D: the scene's dimension. The 2-D-only parts (faces, bodies, slides) stay empty in 3-D.
template <int D>
struct SceneBuild {
  SceneBuild(const YAML::Node& resolved, const std::filesystem::path& dir) : r(resolved), scene_dir(dir) {}

  const YAML::Node r;  // the resolved scene
  std::filesystem::path scene_dir;  // where files named by the scene are looked up
  std::unique_ptr<Scene<D>> scene = std::make_unique<Scene<D>>();
  std::unique_ptr<Simulation<D>> sim = std::make_unique<Simulation<D>>();

  // Set by build_scene on several processes: those on this machine, which share its memory (cases/same_machine.hpp).
  SameMachine machine{{1}};
  // Set by build_scene on several processes that build a 3-D scene in parts (cases/build_share.hpp): the processes
  // (the steps that need every particle reduce across them), the counting pass's tally, and this process's part.
  // The counting pass's own build has `counting` instead: it makes no particle, it counts them.
  const Communicator* processes = nullptr;
  std::unique_ptr<const BuildCount> counted;
  std::optional<BuildShare> share;
  BuildCount* counting = nullptr;
  ParticleId made = 0;  // the particles the whole scene has made so far: the next one's id
  // A particle made as the whole build makes it (its id: its place in that order), kept where this process holds its
  // position; its index, or none (not held here, or counted only).
  std::optional<std::size_t> add(const Vec<D>& x, Kind kind, std::uint8_t phase, double density, double viscosity) {
    const ParticleId id = made++;
    if constexpr (D == 3) {
      if (counting) {
        counting->add(x, dp);
        return std::nullopt;
      }
      if (share && !share->holds(x)) return std::nullopt;
    }
    const std::size_t i = particles().add(x, kind, phase, density, viscosity);
    particles().id[i] = id;
    return i;
  }
  // Set by read_fluid_options.
  double dp = 0.0;
  bool close_packed = false;  // hexagonal (2-D) or fcc (3-D): walls cut from the lattice, compressed by settling alone
  InitialState initial_state = default_initial_state;
  // Set by check_period: the period [x_min, x_max) of a domain periodic in x; unset otherwise.
  std::optional<PeriodicX> period_x;
  // Whether a lattice point at x belongs to the period (always, without one): x in [x_min, x_max) with a margin of a
  // quarter column either side, so a point on x_min is in and its image on x_max is out however the period's ends
  // round. Walls and regions keep only these points: along a periodic x, the periodic images supply the rest.
  bool in_period(double x) const {
    if (!period_x) return true;
    const double quarter = 0.25 * nearest_spacing(sim->options.lattice, dp);
    return x >= period_x->x_min - quarter && x < period_x->x_max - quarter;
  }
  // Set by read_phases.
  ScenePhases phases;
  // Set by place_floating_bodies: each body moved to its draft (its key path) and by how much, m (up > 0).
  std::vector<std::pair<std::string, double>> moved_to_draft;
  // Set by build_walls: the wall faces, and the owner (a key path) of every boundary particle, for messages.
  std::vector<FaceSegment> faces;
  std::vector<std::string> boundary_owner;
  std::vector<std::array<Vec<D>, 2>> tanks;  // 3-D: the tanks' insides (min, max), for below_level regions
  // 3-D: the terrains (walls[].type: terrain): their grid, surface (facing up) and distance.
  struct Terrain {
    HeightGrid grid;
    rigid::TriangleSurface surface;
    std::shared_ptr<const mesh::MeshDistance> distance;
  };
  std::vector<Terrain> terrains;
  std::vector<ParticleId> gate_ids;  // the particles of gates (walls[].gate), taken away at t = 0
  // Set by build_slides_and_bodies: the rigid bodies and their outlines (counter-clockwise, world, t = 0), and the
  // deformable slides (filled with their phase's particles by fill_fluid_regions).
  std::shared_ptr<RigidBodies<D>> bodies;
  std::vector<std::vector<rigid::Vec2>> outlines;
  std::vector<rigid::TriangleSurface> solids;  // 3-D: each rigid body's surface (world, t = 0)
  std::vector<std::function<double(const Vec<3>&)>> solid_distance;  // 3-D: each one's signed distance, m
  struct Slide {
    std::string path;  // bodies[k]
    std::vector<rigid::Vec2> outline;  // 2-D
    std::size_t phase = 0;
    std::vector<Vec<D>> vertices;  // its outline's (2-D) or surface's (3-D), m
    Vec<D> centroid = Vec<D>::Zero();  // of its shape, m
    std::function<double(const Vec<3>&)> signed_distance;  // 3-D: m from its surface, < 0 inside
    Vec<D> lo = Vec<D>::Zero(), hi = Vec<D>::Zero();       // 3-D: its surface's bounding box, m
  };
  std::vector<Slide> slides;
  std::size_t boundary_count = 0;  // particles before the first fluid particle
  // Set by fill_fluid_regions.
  double still_level = -std::numeric_limits<double>::infinity();  // highest below_level level
  std::vector<std::string> fluid_owner;  // the key (fluid.regions[k], bodies[k]) of fluid particle i - boundary_count (freed after the checks that name particles)
  Vec<D> lo = Vec<D>::Zero(), hi = Vec<D>::Zero();  // bounding box of every particle as placed on the lattice

  FluidOptions<D>& options() { return sim->options; }
  Particles<D>& particles() { return sim->particles(); }
};

// The steps, in the order build_scene runs them. Each throws SceneError naming the key at fault. Templates are
// instantiated for 2 and 3; the others are the dimension's own geometry (2-D: polylines and outlines; 3-D: boxes).
template <int D> void read_fluid_options(SceneBuild<D>& b);     // build_options.cpp
template <int D> void check_lattice_choices(SceneBuild<D>& b);  // build_options.cpp
template <int D> void check_period(SceneBuild<D>& b);           // build_options.cpp
template <int D> void check_particle_budget(SceneBuild<D>& b);  // build_particle_budget.cpp
template <int D> void check_run_memory(SceneBuild<D>& b);       // build_particle_budget.cpp: Scene::memory_estimate_bytes
double estimated_particles(const SceneBuild<2>& b);             // build_particle_budget.cpp
double estimated_particles(const SceneBuild<3>& b);             // build_geometry_3d.cpp
ScenePhases read_phases(const YAML::Node& phases);  // build_phases.cpp
double stated_still_level(const YAML::Node& r);  // build_bodies.cpp: the highest below_level level, or -inf
// build_bodies.cpp: bodies[k]'s name, refused (naming bodies[k].name) when an earlier body has it; `names` collects them.
std::string unique_body_name(std::map<std::string, std::size_t>& names, const YAML::Node& body, std::size_t k);
void place_floating_bodies(SceneBuild<2>& b);     // build_bodies.cpp: bodies that float while settling, to their draft
void place_floating_bodies(SceneBuild<3>& b);     // build_bodies_3d.cpp
void build_walls(SceneBuild<2>& b);               // build_walls.cpp
void build_walls(SceneBuild<3>& b);               // build_geometry_3d.cpp
// The fixed walls' faces for telling a particle that passed through a wall (fluid/wall_crossing.hpp).
std::vector<WallFace<2>> crossing_faces(const SceneBuild<2>& b);  // build_walls.cpp
std::vector<WallFace<3>> crossing_faces(const SceneBuild<3>& b);  // build_geometry_3d.cpp
void build_slides_and_bodies(SceneBuild<2>& b);   // build_bodies.cpp
void build_slides_and_bodies(SceneBuild<3>& b);   // build_bodies_3d.cpp
// build_slides.cpp: a deformable slide's phase (named after bodies[k], of its density and rheology) and its report's
// first fields; the particles come with the water (fill_fluid_regions), the rest of the report with finish_bodies.
template <int D>
SlideReportOf<D> add_slide_phase(SceneBuild<D>& b, const YAML::Node& body, const std::string& path,
                                 RheologyModel model);
// Where a slide rests: the face's unit normal out of it, its angle to the plane normal to gravity, and the layer that
// the yield criterion at rest takes: its top (the slide's point furthest from the face) and its thickness there, m.
template <int D>
struct RestingFace {
  Vec<D> normal;
  double slope_angle_deg = 0.0;
  Vec<D> top;
  double thickness = 0.0;
};
// The face a slide rests on and the layer above it, or none (build_bodies.cpp: the steepest wall face its outline lies
// along; build_bodies_3d.cpp: the steepest terrain or tank floor within a spacing of it).
std::optional<RestingFace<2>> resting_face_of(const SceneBuild<2>& b, const SceneBuild<2>::Slide& slide);
std::optional<RestingFace<3>> resting_face_of(const SceneBuild<3>& b, const SceneBuild<3>::Slide& slide);
// build_slides.cpp: the report's particle count and mass, its warnings (lighter than the water it starts in; strong
// enough to stand rigid at rest) and its yield criterion at rest on the face it rests on (none: no criterion).
template <int D>
void finish_slide_report(const SceneBuild<D>& b, const typename SceneBuild<D>::Slide& slide,
                         const std::optional<RestingFace<D>>& face, SlideReportOf<D>& rep);
int body_near(const SceneBuild<3>& b, const Vec<3>& p);  // build_bodies_3d.cpp: the body p is in or near, or -1
void fill_fluid_regions(SceneBuild<2>& b);        // build_fluid_regions.cpp
void fill_fluid_regions(SceneBuild<3>& b);        // build_geometry_3d.cpp
template <int D> void check_overlaps(SceneBuild<D>& b);  // build_fluid_regions.cpp
void check_fluid_contained(SceneBuild<2>& b);     // check_fluid_contained.cpp
template <int D> void choose_sound_speed(SceneBuild<D>& b);  // build_initial_state.cpp
template <int D> void start_hydrostatic(SceneBuild<D>& b);   // build_initial_state.cpp
template <int D> void set_domain(SceneBuild<D>& b);          // build_initial_state.cpp
template <int D> void keep_own_columns(SceneBuild<D>& b);    // build_initial_state.cpp: a scene built in parts
template <int D> void count_particles(SceneBuild<D>& b);     // build_initial_state.cpp
template <int D> void read_outputs(SceneBuild<D>& b);        // build_outputs.cpp
void finish_bodies(SceneBuild<2>& b);             // build_bodies.cpp
void finish_bodies(SceneBuild<3>& b);             // build_bodies_3d.cpp
template <int D> void set_phases(SceneBuild<D>& b);          // build_phases.cpp
template <int D> void plan_settling(SceneBuild<D>& b);       // build_initial_state.cpp: Scene::pending_settling
template <int D> void settle_now(Scene<D>& scene);           // build_initial_state.cpp: settles it, then complete_start

// A body's outline from its shape, counter-clockwise in world coordinates at t = 0; it must be convex
// (build_bodies.cpp; the walls need the first body's to move the hexagonal lattice).
std::vector<rigid::Vec2> body_outline(const YAML::Node& body, const std::string& path);

}  // namespace slide::cases
