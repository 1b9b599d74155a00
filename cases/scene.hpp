#pragma once
// A scene: the YAML file's schema, and the simulation it builds.
#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "cases/same_machine.hpp"
#include "cases/gauge_records_spec.hpp"
#include "cases/schema.hpp"
#include "coupling/equilibrium_column.hpp"
#include "coupling/relaxation.hpp"
#include "coupling/simulation.hpp"

namespace slide::cases {

// A wave gauge: the free surface's elevation above a point of the plan, (x) in 2-D, (x, y) in 3-D.
struct GaugeSpec {
  std::string name;
  double x = 0.0;
  double y = 0.0;  // 3-D only
};

// Dam-break diagnostics: surge front and water height at the wall (see coupling/surge_front.hpp).
struct SurgeFrontSpec {
  bool enabled = false;
  double wall_face_x = 0.0;
  double floor_y = 0.0;
  double column_width = 0.0;  // a, for the dimensionless columns
};

// velocity_profile.csv (coupling/velocity_profile.hpp): the fluid's mean velocity in bins of height `bin` from
// y_origin, sampled with the gauges.
struct VelocityProfileSpec {
  bool enabled = false;
  double y_origin = 0.0;  // m
  double bin = 0.0;       // m
};

// diagnostics.slide_shapes (slide_shapes.csv, coupling/slide_shape_error.hpp): measured upper surfaces of a slide, each
// compared with the model's at the measured time plus time_offset (the first step at or after it).
struct MeasuredShape {
  double time_measured = 0.0;  // s, the measurement's clock
  std::vector<Vec<2>> points;  // m, digitized (x, y) of the upper surface
};
struct SlideShapesSpec {
  std::string file;          // as the scene names it
  double time_offset = 0.0;  // s, model time = measured time + time_offset
  std::vector<MeasuredShape> shapes;  // in increasing time; the first is the start (the front's travel origin)
};

// Free-surface profiles along the horizontal segment from `from` to `to` (2-D: x_min to x_max, y unused).
struct ProfileSpec {
  std::vector<double> times;  // s, increasing
  std::array<double, 2> from{}, to{};  // m, (x, y)
  double spacing = 0.0;  // m between points
};

struct OutputSpec {
  bool snapshots = true;
  double snapshot_interval = 0.0;  // s; 0 = first and last only
  double gauge_interval = 0.0;     // s
  double checkpoint_interval = 0.0;  // s of simulated time between checkpoints (tools/checkpoint.hpp); 0 = none
  std::vector<std::string> snapshot_fields;  // besides position, kind and id; all of them where the scene gives none
  bool snapshot_single_precision = false;
  bool snapshot_deflate = true;
};

// What `slide check` reports about a body: mass and inertia from the outline beside the same sums over a dp
// lattice filling it, and the buoyancy at the still-water level.
template <int D>
struct BodyReportOf {
  std::string name;
  std::string motion;
  double area = 0.0;             // its size: m^2 (per unit width) in 2-D, its volume in m^3 in 3-D
  double mass = 0.0;             // kg/m (2-D), kg (3-D)
  double inertia = 0.0;          // kg m, about the centre of mass (2-D; 3-D: the tensor's mean diagonal, kg m^2)
  double mass_particles = 0.0;   // the same from lattice points inside the outline
  double inertia_particles = 0.0;
  double displaced_area = 0.0;   // below the still-water level, m^2
  double buoyancy_ratio = 0.0;   // rho_water g displaced / (m g); NaN without a still-water level
  std::size_t particles = 0;     // boundary particles
  Vec<D> placed = Vec<D>::Zero();  // centre of mass where the scene puts it, m
  std::vector<Vec<2>> outline;     // where the scene puts it, counter-clockwise, m (2-D)
  bool free_while_settling = false;  // during_settling: free
  double moved_to_draft = 0.0;       // m up (< 0: down) from where the scene put it to its draft (place_floating_bodies)
};
using BodyReport = BodyReportOf<2>;

// A deformable slide (bodies[k] with a model other than rigid): sediment particles of its own phase.
template <int D>
struct SlideReportOf {
  std::string name;
  std::string model;             // herschel_bulkley, ...
  std::uint8_t phase = 0;        // Particles::phase of its particles
  std::size_t particles = 0;
  double volume = 0.0;           // of its shape: m^2 per unit width in 2-D (its outline's area), m^3 in 3-D
  double density = 0.0;          // kg/m^3
  double mass_particles = 0.0;   // particles x density x dp^D: kg/m in 2-D, kg in 3-D
  Vec<D> front_direction = Vec<D>::Unit(0);  // unit
  // The yield criterion at rest (infinite-slope estimate on the face it rests on): the basal shear stress of the
  // buoyant layer against what the material holds, and the verdict.
  double slope_angle_deg = 0.0;
  double basal_shear_stress = 0.0;  // Pa
  double strength = 0.0;            // Pa: yield stress, or friction x normal stress
  std::string criterion;            // one line for slide check
  // Set when the material's strength at zero normal stress (yield stress, cohesion) is at least its buoyant weight
  // per area over its height, rho' g H: then no stress its own weight makes at rest yields it, on any face or free
  // side, and it stays rigid until the water loads it (cases/build_bodies.cpp). slide check warns: model: rigid is
  // the cheaper model of such a slide.
  std::string rigid_at_rest_warning;
  // Set when the slide is lighter than the water it starts in: it floats up rather than slides (slide check and
  // slide run print it; the criterion then compares no stress, which would be negative).
  std::string floats_warning;
  std::string key;                  // bodies[k]
};
using SlideReport = SlideReportOf<2>;

template <int D>
struct Scene {
  std::string name;
  YAML::Node resolved;  // every key, defaults filled in
  double end_time = 0.0;
  std::unique_ptr<Simulation<D>> simulation;
  std::vector<GaugeSpec> gauges;
  SurgeFrontSpec surge_front;
  VelocityProfileSpec velocity_profile;
  ProfileSpec profiles;
  OutputSpec output;
  double deepest_water = 0.0;      // m, nominal
  // m, how far the start lattice was moved (2-D: its rows to meet a body's bottom; 3-D: one of its planes onto each
  // plane of symmetry)
  Vec<D> lattice_offset = Vec<D>::Zero();
  std::string sound_speed_source;  // how c0 was chosen
  std::size_t fluid_count = 0, wall_count = 0, dummy_count = 0;
  std::size_t gate_particles = 0;  // boundary particles of gates (walls[].gate), taken away at t = 0
  std::optional<EquilibriumColumn> equilibrium;  // the hydrostatic start's column, when used
  std::vector<BodyReportOf<D>> bodies;
  std::vector<SlideReportOf<D>> slides;
  std::vector<double> slide_outline_times;  // s, increasing
  std::optional<SlideShapesSpec> slide_shapes;
  std::optional<GaugeRecordsSpec> gauge_records;
  std::optional<Relaxation> settling;  // the settled start, when used
  double particle_spacing = 0.0;       // m
  double memory_estimate_bytes = 0.0;  // the run's peak resident memory, estimated (cases/particle_budget.hpp)
  double memory_list_growth_bytes = 0.0;  // the part of it the neighbour list may grow by over the run
  // The particles this process made while building: the whole scene's, or on several processes in 3-D its part of it
  // (its own columns and their margin, cases/build_share.hpp).
  std::size_t particles_made_here = 0;
  // Built with StartOfRun::left_to_caller: the settling still to run (with initial_state settled) and the gates still
  // to lift; complete_start finishes the start (build_scene does it otherwise).
  std::optional<SettlingPlan<D>> pending_settling;
  std::vector<ParticleId> pending_gate_ids;
  double body_sample_interval = 0.0;  // s, bodies.csv rows
};

// The scene format of a dimension (2 or 3; scene_dimension). scene_reference() is cases/SCHEMA.md: both documents.
const Schema& scene_schema(int dimension = 2);
std::string scene_reference();

// Reads a scene file, applies --set overrides and checks it. Throws SceneError (exit 2) on any problem.
YAML::Node load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides);
// The same from the file's text (cases/load_scene.cpp).
YAML::Node load_scene_text(const std::string& text, const std::vector<std::string>& overrides);

// Builds particles and options from a resolved scene. Throws SceneError for geometric problems (a region that
// holds no particle, water overlapping a wall).
// scene_dir: where files named by the scene (prescribed motion series) are looked up.
// start: settle_now (with initial_state settled; then the gates are lifted), left_to_caller (slide run, which settles in
// its own loop so that a signal can stop it: it calls complete_start after), already_settled (a run continuing from
// a checkpoint taken after settling: the water is not settled again; the gates are lifted).
// D: the scene's dimension (scene_dimension); a scene of the other dimension is refused naming `dimension`.
// for_processes: what the simulation serves on several processes (tools/run_driver.cpp; one process: the defaults).
//   share: this process's communicator, set before the first neighbour list: every process makes the particles of the
//     whole scene (2-D) or of its part of it (3-D: cases/build_share.hpp), then keeps and lists only its own cells'
//     (Simulation::initialise), so that none holds the whole scene's list; a count of processes the neighbour grid
//     cannot share is refused naming `processes`.
//   observers_copy: the first process's observers' copy (tools/observer_copy.hpp): the scene's particles without a
//     neighbour list (Simulation::make_observers_copy), one only where an output reads neighbours (the surge front).
//     With a share set (3-D), every process builds its part of the copy (a collective) and the first keeps it.
enum class StartOfRun { settle_now, left_to_caller, already_settled };
// What the processes that did not refuse a shared build throw: another said why (tools/run_driver.cpp lets it speak).
struct RefusedOnAnotherProcess : SceneError {
  using SceneError::SceneError;
};
struct ForProcesses {
  std::shared_ptr<const Communicator> share;
  bool observers_copy = false;
  // The run's processes on this machine, which share its memory (cases/same_machine.hpp): the memory guard's.
  SameMachine machine{{1}};
};
template <int D>
std::unique_ptr<Scene<D>> build_scene(const YAML::Node& resolved, const std::string& default_name,
                                      const std::filesystem::path& scene_dir = ".",
                                      StartOfRun start = StartOfRun::settle_now, const ForProcesses& for_processes = {});

// A resolved scene's dimension (2 or 3), which its caller dispatches on.
inline int scene_dimension(const YAML::Node& resolved) { return resolved["dimension"].as<int>(); }

// Finishes a start left to the caller: `settled` is what the settling of scene.pending_settling gave (none without
// one); the settled water is checked at rest (SceneError naming method.initial_state) and the gates are lifted.
template <int D>
void complete_start(Scene<D>& scene, const std::optional<Relaxation>& settled);

}  // namespace slide::cases
