// The scene format: every key with its documentation, unit, default and range. Its document() is cases/SCHEMA.md
// (`slide schema`).
#include <limits>

#include "cases/body_choices.hpp"
#include "cases/body_model.hpp"
#include "cases/initial_state.hpp"
#include "cases/rheology_keys.hpp"
#include "cases/scene.hpp"
#include "cases/snapshot_field_names.hpp"
#include "cases/viscous_scheme_choice.hpp"
#include "cases/wall_side.hpp"
#include "coupling/rigid_bodies.hpp"
#include "fluid/fluid_options.hpp"

namespace slide::cases {
namespace {

using S = Schema;

Schema point_list(std::string doc, std::size_t min_points) {
  return S::list(std::move(doc), S::vector("a point [x, y]", "m", 2, std::nullopt), min_points);
}

// One key for a phase's and a deformable slide's basal condition (fluid/basal_friction.hpp).
Schema basal_friction_angle_schema(const std::string& extra = "") {
  return S::number(std::string("Coulomb friction angle phi_b against walls: the wall shear stress on this material is at most tan(phi_b) times its pressure, so it slides on a wall rather than sticking (fluid/basal_friction.hpp); 90 = no bound, the no-slip wall of method.wall_slip (the default; free_slip leaves walls out whatever this says)") + extra, "deg", 90.0, 0.0, 90.0);
}

Schema phase_schema() {
  return S::map("one phase of fluid particles",
                {{"name", S::text("name that regions refer to", std::nullopt)},
                 {"density", S::number("reference density", "kg/m^3", 1000.0, 0.0, S::inf, true)},
                 {"rheology", rheology_schema()},
                 {"basal_friction_angle", basal_friction_angle_schema()}});
}

Schema region_schema() {
  return S::variant(
      "a region filled with fluid particles on the lattice (square: x = (i + 1/2) dp, y = (j + 1/2) dp; hexagonal: "
      "fluid/lattice.hpp)",
      "type",
      {{"rectangle", S::map("the particles whose cell lies inside [min, max]",
                            {{"phase", S::text("phase name (default: the first phase)", "")},
                             {"min", S::vector("lower-left corner", "m", 2, std::nullopt)},
                             {"max", S::vector("upper-right corner", "m", 2, std::nullopt)}})},
       {"polygon", S::map("the particles whose centre lies inside a closed polygon",
                          {{"phase", S::text("phase name (default: the first phase)", "")},
                           {"points", point_list("polygon vertices (closed automatically)", 3)}})},
       {"below_level", S::map("water below a level inside the walls: every lattice point below the level, "
                              "inside the walls' bounding box, on the fluid side of the nearest wall face and at "
                              "least dp/2 from it (hexagonal lattice: any distance in front of it; the points on or "
                              "behind it are the walls')",
                              {{"phase", S::text("phase name (default: the first phase)", "")},
                               {"level", S::number("still-water level", "m", std::nullopt)}})}});
}

Schema wall_schema() {
  return S::map(
      "a wall given by its face (the surface the fluid touches); wall and dummy particle layers are placed "
      "behind it at (k + 1/2) dp",
      {{"name", S::text("name used in messages", "")},
       {"points", point_list("vertices of the face polyline", 2)},
       {"fluid_side", S::choice("side of the polyline (walking from the first vertex) where the fluid is",
                                fluid_side_names.names(), std::string(to_string(FluidSide::left)))},
       {"layers",
        S::integer("boundary layers (wall + dummies); 0 = ceil(re / dp), enough to cover the kernel", 0L, 0L, 10L)},
       {"gate", S::boolean("a gate: it holds the water while it settles (needs method.initial_state: settled) and "
                           "is taken away at t = 0, as a dam break's gate is lifted; bodies do not collide with it, "
                           "and water beside it is laid by rectangle or polygon regions (below_level ignores it)",
                           false)}});
}

// A body's motion and its rail, the same keys in 2-D and 3-D (a rail's direction has the scene's dimension; 2-D's
// masses and forces are per unit width).
Schema motion_schema() {
  return S::choice("free: moved by gravity, the fluid and contacts (two-way coupled); prescribed: follows the law in "
                   "`prescribed` (the fluid's force on it is still reported); rail: moves along `rail.direction` "
                   "only, without turning, under gravity and the fluid (two-way coupled), the rail taking the force "
                   "across it and its friction opposing the motion (rigid/rail_motion.hpp); it passes through walls "
                   "(the rail keeps it off them)",
                   BodyMotion::mode_names.names(), std::string(BodyMotion::mode_names.name(BodyMotion::Mode::free)));
}

Schema rail_schema(int dimension) {
  return S::map("a rail the body runs on (motion: rail), from where it is put; held there until release_time",
                {{"direction", S::vector("direction of the rail (made unit)", "", dimension, std::nullopt)},
                 {"friction", S::number("Coulomb coefficient of the rail: the friction force is this times the force "
                                        "the rail takes across it",
                                        "", 0.0, 0.0, 10.0)}},
                false);
}

Schema body_schema() {
  return S::map(
      "a slide or floating body; model rigid makes it a Bullet rigid body whose boundary particles (wall layer + "
      "dummies inside its outline) exchange forces with the fluid; any other model fills the same outline with "
      "sediment particles of that rheology (a phase named after the body, of its density), so that one key switches a "
      "slide between rigid and deformable",
      {{"name", S::text("name used in bodies.csv and messages", std::nullopt)},
       {"model",
        S::choice("what the body is made of", body_model_names.names(), std::string(to_string(BodyModel::rigid)))},
       {"shape",
        S::variant(
            "outline of the body (convex)", "type",
            {{"box",
              S::map("a rectangle", {{"center", S::vector("centre", "m", 2, std::nullopt)},
                                     {"size", S::vector("width and height", "m", 2, std::nullopt, 0.0)},
                                     {"angle", S::number("rotation, counter-clockwise", "deg", 0.0, -360.0, 360.0)}})},
             {"polygon", S::map("a convex polygon", {{"points", point_list("vertices (closed automatically)", 3)}})},
             {"wedge", S::map("a right isosceles wedge resting on a 45 degree slope (Heinrich, Rzadkiewicz): horizontal top "
                              "from the apex, vertical face at its far end, hypotenuse on the slope; vertices apex, "
                              "apex + (s leg, 0), apex + (s leg, -leg), s = +1 for a slope descending towards +x",
                              {{"apex", S::vector("the upper vertex on the slope", "m", 2, std::nullopt)},
                               {"leg", S::number("length of the horizontal and vertical legs", "m", std::nullopt, 0.0,
                                                 S::inf, true)},
                               {"toward", S::choice("the way the slope descends", {"+x", "-x"}, "+x")}})}})},
       {"density", S::number("density of the body; 0 = give mass instead", "kg/m^3", 0.0, 0.0, S::inf)},
       {"mass", S::number("mass per unit width; 0 = density times area", "kg/m", 0.0, 0.0, S::inf)},
       {"friction", S::number("Coulomb friction coefficient against walls", "", 0.0, 0.0, 10.0)},
       {"restitution", S::number("restitution coefficient against walls", "", 0.0, 0.0, 1.0)},
       {"rheology", rheology_parameters_schema()},
       {"basal_friction_angle",
        basal_friction_angle_schema("; deformable slides only (a rigid body's Coulomb coefficient against walls is "
                                    "`friction`, which a deformable slide ignores: its default 0 would be frictionless)")},
       {"front_direction", S::vector("deformable slides: slide_front.csv's front is the particle furthest along this "
                                     "direction", "", 2, std::vector<double>{1.0, 0.0})},
       {"motion", motion_schema()},
       {"rail", rail_schema(2)},
       {"locked", S::list("components held fixed (free motion)",
                          S::choice("component", locked_component_names.names(), std::nullopt))},
       {"release_time",
        S::number("a free or rail body is held in place until this time", "s", 0.0, 0.0, S::inf)},
       {"during_settling", S::choice("settled start (method.initial_state: settled): held keeps the body where it is "
                                     "put while the water settles; free first moves a rigid body lighter than water "
                                     "up or down to its draft below the still-water level (Archimedes on its outline, "
                                     "heave only; the highest below_level region's level, gravity along -y), lays the "
                                     "water around it there, and lets it float with the water under the same damping",
                                     during_settling_names.names(), std::string(to_string(DuringSettling::held)))},
       {"prescribed",
        S::map(
            "prescribed motion (motion: prescribed)",
            {{"type",
              S::choice("series: a CSV time series (time,x,y,angle[,vx,vy,omega] of the centre of mass, as in "
                        "bodies.csv) interpolated by cubic Hermite; ln_cosh: s(t) = s0 ln cosh((t - start_time) / t0) "
                        "along `direction`",
                        prescribed_law_names.names(), std::string(to_string(PrescribedLaw::series)))},
             {"file", S::text("series: CSV file, relative to the scene file", "")},
             {"body", S::text("series: rows whose body column equals this (default: this body's name)", "")},
             {"direction", S::vector("ln_cosh: direction of travel", "", 2, std::vector<double>{1.0, -1.0})},
             {"s0", S::number("ln_cosh: length scale s0 = u_t^2 / a0", "m", 1.0, 0.0, S::inf, true)},
             {"t0", S::number("ln_cosh: time scale t0 = u_t / a0", "s", 1.0, 0.0, S::inf, true)},
             {"start_time", S::number("ln_cosh: time the motion starts", "s", 0.0, 0.0, S::inf)}},
            false)}});
}

Schema rigid_schema() {
  return S::map(
      "rigid-body settings (rigid/: Bullet in double precision)",
      {{"collision_margin", S::number("Bullet collision margin, kept inside each outline", "dp", 0.1, 0.0, 1.0, true)},
       {"wall_contact",
        S::boolean("bodies collide with the walls (the walls have friction 1, so a body's friction is the "
                   "Coulomb coefficient of the pair)",
                   true)}},
      false);
}

// dimension: the scene's; the sound speed's default factor differs (3-D still water needs more, docs/three-d.md).
Schema method_schema(int dimension) {
  return S::map(
      "numerical method (weakly compressible MPS, seed eqs. 1-7)",
      {{"kernel_radius", S::number("kernel radius re in particle spacings", "dp", 2.1, 1.5, 5.0)},
       {"gradient", S::choice("pressure-gradient model (fluid/gradient.hpp)", gradient_model_names.names(),
                              std::string(to_string(MethodOptions{}.gradient)))},
       {"gamma", S::number("exponent of the equation of state (seed eq. 7)", "", 7.0, 1.0, 10.0)},
       {"sound_speed", S::number("numerical sound speed c0; 0 = sound_speed_factor sqrt(g H) of the deepest water",
                                 "m/s", 0.0, 0.0, S::inf)},
       {"sound_speed_factor",
        S::number(dimension == 3
                      ? "c0 as a multiple of sqrt(g H) of the deepest water, where sound_speed is 0 (20 in 3-D: at 10, "
                        "still water on the fcc lattice rings in its vertical acoustic mode, 6.3 % of sqrt(g H) "
                        "within 1 s in a 0.2 m x 0.2 m tank; at 20 the largest of five still tanks 0.15-0.25 m deep "
                        "is 0.16 %, at 15 one reaches 5 %; twice the steps of 10: docs/three-d.md)"
                      : "c0 as a multiple of sqrt(g H) of the deepest water, where sound_speed is 0 (10: still water "
                        "compressed g H / c0^2 = 1 % at its bottom, the dam break's largest compression 3.6 %: "
                        "cases/sweeps/dam_break_compression.yaml)",
                  "", dimension == 3 ? 20.0 : 10.0, 1.0, 100.0)},
       {"free_surface_beta",
        S::number("free-surface threshold: n < beta n0 is a free-surface particle (its pressure: method.surface_pressure)", "", 0.97, 0.0, 1.0, true, false)},
       {"clamp_negative_pressure", S::boolean("set negative pressures to zero", true)},
       {"surface_pressure", S::choice("pressure of free-surface particles (n < beta n0): zero; half_layer, the head of "
                                      "the half layer above them (still water, floating bodies); or extrapolated from "
                                      "the bulk neighbours with the hydrostatic head, which drives the water column's "
                                      "acoustic mode (fluid/free_surface_pressure.hpp)",
                                      surface_pressure_names.names(), std::string(to_string(MethodOptions{}.surface_pressure)))},
       {"wall_slip", S::choice("wall condition for viscosity: no_slip mirrors the fluid velocity into the wall "
                               "(Morris et al. 1997), free_slip leaves walls out of the viscous term",
                               wall_slip_names.names(), std::string(to_string(WallSlip::no_slip)))},
       {"wall_pressure", S::choice("pressure of boundary particles: mirror takes the fluid's pressure at the "
                                   "particle's mirror image plus the hydrostatic head (square lattice only); "
                                   "extrapolated continues the fluid's pressure into wall and dummy particles (Adami "
                                   "et al. 2012) (fluid/wall_pressure.hpp)",
                                   wall_pressure_names.names(), std::string(to_string(MethodOptions{}.wall_pressure)))},
       {"pore_pressure", S::choice("pore water pressure p_w under water: the Mohr-Coulomb and mu(I) strengths and "
                                   "the basal friction act on the effective pressure p - p_w, and the faces of a rigid "
                                   "body that rest on a wall carry p_w (coupling/dry_face_pressure.hpp); hydrostatic: "
                                   "p_w = rho_w g times the depth below the water's local surface, 0 above it (the "
                                   "drained limit; the water is the first phase); none: on the total pressure p, and "
                                   "no water under a resting body (fluid/pore_pressure.hpp)",
                                   pore_pressure_names.names(), std::string(to_string(MethodOptions{}.pore_pressure)))},
       {"artificial_viscosity", S::number("Monaghan artificial viscosity alpha between fluid particles; 0 = off "
                                          "(fluid/artificial_viscosity.hpp)",
                                          "", 0.0, 0.0, 1.0)},
       {"collision_distance", S::number("collision model (fluid/collision.hpp): fluid particles closer than this "
                                        "approaching each other or a wall collide inelastically; 0 = off",
                                        "dp", 0.5, 0.0, 1.0)},
       {"collision_restitution", S::number("restitution coefficient of the collision model", "", 0.2, 0.0, 1.0)},
       {"initial_state", S::choice("hydrostatic compresses the water so it starts at rest under gravity; settled "
                                   "does that and then lets water at rest settle with damping for settling_time "
                                   "(coupling/relaxation.hpp), for scenes whose water starts at rest (sediment "
                                   "regions settle as a fluid, their rheology starting at t = 0; deformable slides are "
                                   "held); lattice starts from the uncompressed lattice",
                                   initial_state_names.names(), std::string(to_string(default_initial_state)))},
       {"settling_time", S::number("settled start: damped settling time before t = 0", "s", 1.0, 0.0, S::inf, true)},
       {"settling_damping",
        S::number("settled start: velocity damping rate while settling", "1/s", 30.0, 0.0, S::inf, true)},
       {"neighbor_skin",
        S::number("neighbour-list skin; the list is rebuilt when a particle moved half of it", "dp", 0.3, 0.0, 1.0)},
       {"viscous_scheme",
        S::choice("integration of the viscous term: explicit (its own time-step limit), implicit (semi-implicit, "
                  "viscosity lagged, one conjugate-gradient solve per step: fluid/implicit_viscosity.hpp), or auto: "
                  "implicit when some phase or deformable slide is non-Newtonian, explicit otherwise",
                  viscous_scheme_choice_names.names(), "auto")},
       {"implicit_tolerance",
        S::number("semi-implicit viscous solve: relative residual; particles whose viscous step number is below its "
                  "square root are taken explicitly (fluid/implicit_viscosity.hpp)",
                  "", 1.0e-8, 0.0, 1.0, true, true)}},
      false);
}

Schema time_step_schema() {
  return S::map(
      "adaptive time step: dt = min(cfl dp / (c0 + |u|max), viscous_number dp^2 / nu_max, "
      "force_number sqrt(dp / |a|max), max)",
      {{"cfl", S::number("acoustic Courant number", "", 0.2, 0.0, 1.0, true, false)},
       {"viscous_number", S::number("viscous diffusion number", "", 0.1, 0.0, 0.5, true, false)},
       {"force_number", S::number("force (acceleration) number", "", 0.25, 0.0, 1.0, true, false)},
       {"max", S::number("largest time step", "s", 1.0e-3, 0.0, S::inf, true, false)}},
      false);
}

Schema checks_schema() {
  return S::map("stability checks after every step; a failed check stops the run with exit 3",
                {{"max_number_density_ratio",
                  S::number("n / n0 above this is a number-density collapse", "", 1.5, 1.0, S::inf, true, false)},
                 {"max_speed_over_c0",
                  S::number("a fluid speed above this many c0 is a blow-up", "", 1.0, 0.0, S::inf, true, false)},
                 {"allow_uncontained_fluid",
                  S::boolean("accept fluid with no wall or body below it along gravity (it falls out of the domain "
                             "and is taken out of the run); without it such a scene is refused on its region",
                             false)}},
                false);
}

Schema output_schema() {
  return S::map(
      "what is written to the output folder",
      {{"snapshots", S::boolean("write particle snapshots (particles.h5, particles.xdmf)", true)},
       {"snapshot_interval", S::number("time between snapshots; 0 = first and last only", "s", 0.0, 0.0, S::inf)},
       {"snapshot_fields",
        S::list("what a snapshot holds besides position, kind and id; [] (the default) all of them",
                S::choice("field", snapshot_field_names(), std::nullopt))},
       {"snapshot_precision",
        S::choice("double: 64-bit floats; single: 32-bit positions, velocities and scalars (half the bytes)",
                  {"double", "single"}, std::string("double"))},
       {"snapshot_compression",
        S::choice("deflate: lossless, HDF5's byte shuffle and deflate level 1 in chunks (a snapshot of 96 k "
                  "particles 82 -> 37 B a particle; docs/outputs.md); none: contiguous datasets",
                  {"deflate", "none"}, std::string("deflate"))},
       {"gauge_interval", S::number("time between gauge and diagnostic samples (gauges.csv, surge_front.csv, "
                                    "slide_front.csv, velocity_profile.csv)", "s", 0.005, 0.0, S::inf, true, false)},
       {"slide_outline_times", S::vector("times of the deformable slides' upper surfaces in slide_outline.csv, each "
                                         "taken at the first step at or after it", "s", -1, std::vector<double>{}, 0.0)},
       {"body_interval", S::number("time between bodies.csv rows", "s", 0.001, 0.0, S::inf, true, false)},
       {"checkpoint_interval",
        S::number("simulated time between checkpoints (checkpoint.bin, which slide run --resume DIR continues, bit for "
                  "bit); 0 = none at an interval (an interrupted run, SIGINT or SIGTERM, always writes one)",
                  "s", 0.0, 0.0, S::inf)}},
      false);
}

Schema gauge_schema() {
  return S::map("a wave gauge: free-surface elevation by a vertical scan of the fluid number density",
                {{"name", S::text("column name in gauges.csv", std::nullopt)},
                 {"x", S::number("gauge position", "m", std::nullopt)}});
}

Schema profiles_schema() {
  return S::map(
      "free-surface profiles (profiles.csv: time,x,eta), each taken at the first step at or after "
      "its time, by the gauges' vertical scan",
      {{"times", S::vector("times of the profiles", "s", -1, std::vector<double>{}, 0.0)},
       {"x_min", S::number("first x", "m", 0.0)},
       {"x_max", S::number("last x", "m", 0.0)},
       {"spacing", S::number("distance between points; 0 = dp", "m", 0.0, 0.0, S::inf)}},
      false);
}

Schema profiles_schema_3d() {
  return S::map(
      "free-surface profiles along a horizontal line (profiles.csv: time,x,y,eta), each taken at the first step at or "
      "after its time, by the gauges' vertical scan",
      {{"times", S::vector("times of the profiles", "s", -1, std::vector<double>{}, 0.0)},
       {"from", S::vector("first point (x, y)", "m", 2, std::vector<double>{0.0, 0.0})},
       {"to", S::vector("last point (x, y)", "m", 2, std::vector<double>{0.0, 0.0})},
       {"spacing", S::number("distance between points (rounded to divide the line); 0 = dp", "m", 0.0, 0.0, S::inf)}},
      false);
}

Schema slide_shapes_schema() {
  return S::map(
      "a slide's measured upper surfaces (slide_shapes.csv: the front's error in per cent of its measured travel and "
      "the rms vertical distance between the surfaces, coupling/slide_shape_error.hpp) for the first deformable slide, "
      "or the first body where there is none",
      {{"file", S::text("CSV of the measured surfaces, relative to the scene file, with the columns t_exp_s, x_m and "
                        "y_m (the measured time and the digitized points); its first time is the start, the origin of "
                        "the front's travel; empty: off",
                        "")},
       {"time_offset", S::number("model time = measured time + time_offset", "s", 0.0)}},
      false);
}

Schema gauge_records_schema() {
  return S::map(
      "measured free-surface elevations at the scene's gauges (gauge_records.csv: for each gauge the rms difference "
      "over the time both cover, the measured height, and the deepest trough and highest crest of the run and the "
      "record; tools/measures/gauge_records.hpp); the run's elevation counts from its gauge's first value",
      {{"file", S::text("CSV of the records, relative to the scene file: a column time_s, then one column per gauge "
                        "named as in gauges, the elevation from the still water level in m; empty: off",
                        "")},
       {"time_offset", S::number("model time = measured time + time_offset", "s", 0.0)},
       {"until", S::number("compare up to this model time (before what a tank cut short reflects reaches the "
                           "gauges); 0 = to the run's end",
                           "s", 0.0, 0.0, S::inf)}},
      false);
}

Schema surge_schema() {
  return S::map(
      "dam-break diagnostics (surge_front.csv): front of the largest connected body of water (particles closer "
      "than 2 dp linked) measured from the wall face, and the water height at that wall (the water's edge fitted over "
      "re to re + a/4 from the wall, read at the wall; coupling/surge_front.hpp)",
      {{"enabled", S::boolean("write surge_front.csv", false)},
       {"wall_face_x", S::number("x of the wall face the column stands against", "m", 0.0)},
       {"floor_y", S::number("y of the floor face", "m", 0.0)},
       {"column_width",
        S::number("initial column width a for Z = front / a and T = t sqrt(2 g / a); 0 = omit", "m", 0.0, 0.0, S::inf)}},
      false);
}

Schema velocity_profile_schema() {
  return S::map(
      "the fluid's mean velocity across the flow (velocity_profile.csv: time,y,u,v,particles; y the particles' mean "
      "height), in bins of height bin from y_origin, sampled with the gauges; for a channel periodic in x, the mean "
      "over the period (coupling/velocity_profile.hpp)",
      {{"enabled", S::boolean("write velocity_profile.csv", false)},
       {"y_origin", S::number("y of one bin edge", "m", 0.0)},
       {"bin", S::number("bin height; 0 = the lattice's row spacing (dp, or 0.9306 dp on the hexagonal lattice)",
                         "m", 0.0, 0.0, S::inf)}},
      false);
}

Schema domain_schema(int dim) {
  const std::string period =
      dim == 2 ? "periodic in x with the period [min.x, max.x) (fluid/periodic.hpp), which must hold a whole number of "
                 "lattice columns (dp apart, or 1.0746 dp on the hexagonal lattice, to within 0.1 % of one); walls "
                 "and regions may run past its ends (their points in the period are kept); no rigid bodies"
               : "periodic in x with the period [min.x, max.x) (fluid/periodic.hpp), which must hold a whole number "
                 "of lattice columns";
  return S::map(
      "box a fluid particle may leave only through an open side (no wall): it is then taken out of the run and "
      "counted in run.json's left_the_domain; one that passes through a wall (past the back of its particle layers) is "
      "an instability; default: the particles' bounding box enlarged by 4 re on every side and by half its height "
      "upwards",
      {{"min", S::vector("lower corner", "m", dim, std::nullopt)},
       {"max", S::vector("upper corner", "m", dim, std::nullopt)},
       {"periodic_x", S::boolean(period, false)}},
      false);
}

Schema processes_schema() {
  return S::map("a run on several processes (mpirun; docs/using.md): ignored on one",
                {{"rebalance_imbalance",
                  S::number("the processes' shares of the neighbour grid's cells are made anew when the largest "
                            "share of the particles exceeds the mean by this factor (run.json's partition reports "
                            "the repartitions and the final imbalance); the results do not depend on it",
                            "", DomainOptions{}.rebalance_imbalance, 1.0, S::inf, true)}},
                false);
}

Schema dimension_schema() {
  return S::integer("spatial dimension: 2 (x along the flume, y up) or 3 (x, y horizontal, z up; the keys of 3-D "
                    "scenes are listed in their own table below)",
                    2L, 2L, 3L);
}

// A 3-D shape (a body's, a water region's): box, sphere, cylinder, prism or a closed mesh from a file
// (cases/solid_shape.hpp).
Schema shape_schema_3d(const std::string& description) {
  return S::variant(description, "type",
                   {{"box", S::map("a box", {{"center", S::vector("centre", "m", 3, std::nullopt)},
                                             {"size", S::vector("edge lengths along its own x, y, z", "m", 3,
                                                                std::nullopt, 0.0)},
                                             {"angles", S::vector("orientation as roll, pitch, yaw (Tait-Bryan z-y'-x'': "
                                                                  "R = Rz(yaw) Ry(pitch) Rx(roll), as bodies.csv)",
                                                                  "deg", 3, std::vector<double>{0.0, 0.0, 0.0})}})},
                    {"sphere", S::map("a sphere", {{"center", S::vector("centre", "m", 3, std::nullopt)},
                                                   {"radius", S::number("radius", "m", std::nullopt, 0.0, S::inf, true,
                                                                        false)}})},
                    {"cylinder",
                     S::map("a circular cylinder about its own z axis",
                            {{"center", S::vector("centre (half way along its axis)", "m", 3, std::nullopt)},
                             {"radius", S::number("radius", "m", std::nullopt, 0.0, S::inf, true, false)},
                             {"height", S::number("length along its axis", "m", std::nullopt, 0.0, S::inf, true, false)},
                             {"angles", S::vector("orientation as roll, pitch, yaw (Tait-Bryan z-y'-x'': "
                                                  "R = Rz(yaw) Ry(pitch) Rx(roll), as bodies.csv); 0: axis along z",
                                                  "deg", 3, std::vector<double>{0.0, 0.0, 0.0})}})},
                    {"prism",
                     S::map("a right prism: a convex polygon in the body frame's x-y plane swept along the frame's z "
                            "(a 2-D slide's cross-section extruded: with angles [90, 0, 0] the outline's (x, y) lie "
                            "in the scene's (x, z) and the prism runs across y)",
                            {{"center", S::vector("where the frame's origin goes (half way along the prism)", "m", 3,
                                                  std::nullopt)},
                             {"outline", point_list("vertices in the frame's x-y plane, either way round (closed "
                                                    "automatically; convex)",
                                                    3)},
                             {"length", S::number("length along the frame's z", "m", std::nullopt, 0.0, S::inf, true,
                                                  false)},
                             {"angles", S::vector("orientation as roll, pitch, yaw (Tait-Bryan z-y'-x'': "
                                                  "R = Rz(yaw) Ry(pitch) Rx(roll), as bodies.csv)",
                                                  "deg", 3, std::vector<double>{0.0, 0.0, 0.0})}})},
                    {"mesh",
                     S::map("a closed triangle mesh from a file, checked before anything runs: closed, its faces "
                            "consistently and outward oriented, a positive volume, no face cutting another "
                            "(mesh/closed_mesh.hpp); a point x of the file goes to position + R (scale x). It may be "
                            "concave (a rigid body then collides with walls as its convex pieces: HACD, "
                            "mesh/convex_decomposition.hpp), but a body's concave mesh may not be cut by a plane of "
                            "symmetry yet",
                            {{"file", S::text("an .stl (binary or ASCII) or .obj file, relative to the scene's folder",
                                              std::nullopt)},
                             {"scale", S::number("factor on the file's coordinates (e.g. 0.001 for millimetres)", "",
                                                 1.0, 0.0, S::inf, true, false)},
                             {"position", S::vector("where the file's origin goes", "m", 3,
                                                    std::vector<double>{0.0, 0.0, 0.0})},
                             {"angles", S::vector("orientation as roll, pitch, yaw (Tait-Bryan z-y'-x'': "
                                                  "R = Rz(yaw) Ry(pitch) Rx(roll), as bodies.csv), about the file's "
                                                  "origin", "deg", 3, std::vector<double>{0.0, 0.0, 0.0})}})}});
}

// 3-D scenes (dimension: 3): the keys that exist in 3-D so far (issue 31 grows them: meshes, terrain).
Schema region_schema_3d() {
  return S::variant(
      "a region filled with fluid particles on the scene's lattice (fluid/lattice.hpp)",
      "type",
      {{"box", S::map("the lattice points of [min, max]: on the square lattice those whose cell lies inside, on the "
                      "fcc lattice those whose centre lies strictly inside",
                      {{"phase", S::text("phase name (default: the first phase)", "")},
                       {"min", S::vector("lower corner", "m", 3, std::nullopt)},
                       {"max", S::vector("upper corner", "m", 3, std::nullopt)}})},
       {"below_level", S::map("water below a level inside the tanks: every lattice point of a tank's inside (by the "
                              "box rule) below the level and the tank's top",
                              {{"phase", S::text("phase name (default: the first phase)", "")},
                               {"level", S::number("still-water level (z)", "m", std::nullopt)}})},
       {"shape", S::map("the lattice points strictly inside a shape (a mesh may be concave: a pond, a reservoir's "
                        "basin); its points must lie inside the tanks where the scene has any, and outside the "
                        "deformable slides",
                        {{"phase", S::text("phase name (default: the first phase)", "")},
                         {"shape", shape_schema_3d("the region's shape")}})}});
}

Schema wall_schema_3d() {
  return S::variant(
      "a wall given by its faces (the surfaces the fluid touches); wall and dummy particle layers are placed behind "
      "them at (k + 1/2) dp",
      "type",
      {{"tank", S::map("the inside of an axis-aligned box, open at the top: its floor at min.z and four sides up to "
                       "max.z hold the fluid (fluid/box_walls.hpp); on the square lattice its faces (all but the top) "
                       "lie on multiples of particle_spacing; tanks must not overlap",
                       {{"name", S::text("name used in messages", "")},
                        {"min", S::vector("lower corner of the inside", "m", 3, std::nullopt)},
                        {"max", S::vector("upper corner of the inside (max.z: the sides' top)", "m", 3, std::nullopt)},
                        {"layers", S::integer("boundary layers (wall + dummies); 0 = ceil(re / dp), enough to cover "
                                              "the kernel", 0L, 0L, 10L)},
                        {"symmetry", S::list("sides that are planes of symmetry: the scene is the half (or quarter) of a "
                                             "symmetric one on this side of them. What stands within the kernel's "
                                             "reach of them gets its mirror image beyond (fluid/ghosts.hpp), which "
                                             "makes them free-slip; on the fcc lattice the lattice is moved to put one "
                                             "of its planes on each (its particles there are their own images; two on "
                                             "one axis a whole number of plane spacings apart); a body they cut is its "
                                             "part on this side, and moves along them without turning",
                                             S::choice("side", {"x_min", "x_max", "y_min", "y_max"}, std::nullopt))}})},
       {"terrain",
        S::map("a terrain or bathymetry: a surface z = h(x, y) from a grid of elevations, each cell two triangles split "
               "along its diagonal from (x_i, y_j) to (x_i+1, y_j+1) (cases/height_grid.hpp), with wall and dummy "
               "particles below it to the kernel's reach, the water's own lattice cut by its surface (cases/terrain_layers.hpp: "
               "a flat terrain is a tank's floor, a slope a staircase of the lattice's planes whose particles carry the "
               "true surface's depth and normal), kept inside the tanks and on the scene's side of its symmetry planes; "
               "water (below_level, box) takes the lattice's points above it; bodies collide with its true surface. Put "
               "it inside a tank, whose sides hold the water around it",
               {{"name", S::text("name used in messages", "")},
                {"file", S::text("the grid, relative to the scene's folder: a .csv (header y\\x,x_0,x_1,..., then a "
                                 "row y_j,z_0j,z_1j,... per y) or an ESRI ASCII grid (.asc)",
                                 std::nullopt)}})}});
}

Schema gauge_schema_3d() {
  return S::map("a wave gauge: free-surface elevation by a vertical scan of the fluid number density",
                {{"name", S::text("column name in gauges.csv", std::nullopt)},
                 {"x", S::number("gauge position, x", "m", std::nullopt)},
                 {"y", S::number("gauge position, y", "m", std::nullopt)}});
}


// Rigid bodies in 3-D: Bullet solids in six degrees of freedom (coupling/rigid_bodies.hpp).
Schema body_schema_3d() {
  return S::map(
      "a floating or sliding rigid body: a Bullet solid (mass, centre of mass and inertia tensor from its closed "
      "surface) whose boundary particles (a wall layer on its surface and dummies inside, at the scene's spacing along "
      "its faces) exchange forces with the fluid; any other model fills the same shape with sediment particles of "
      "that rheology (a deformable slide: a phase named after the body, of its density), so that one key switches a "
      "slide between rigid and deformable. 3-D so far: boxes, spheres, cylinders, convex prisms and closed meshes, "
      "free, on a rail, moved by the ln cosh law or by a series of poses; a tank's symmetry sides cut it "
      "(walls[].symmetry)",
      {{"name", S::text("name used in bodies.csv and messages", std::nullopt)},
       {"model",
        S::choice("what the body is made of", body_model_names.names(), std::string(to_string(BodyModel::rigid)))},
       {"shape", shape_schema_3d("the body's shape")},
       {"density", S::number("density of the body; 0 = give mass instead", "kg/m^3", 0.0, 0.0, S::inf)},
       {"mass", S::number("mass (the whole body's where a symmetry side cuts it); 0 = density times volume", "kg",
                          0.0, 0.0, S::inf)},
       {"friction", S::number("Coulomb friction coefficient against walls", "", 0.0, 0.0, 10.0)},
       {"restitution", S::number("restitution coefficient against walls", "", 0.0, 0.0, 1.0)},
       {"rheology", rheology_parameters_schema()},
       {"basal_friction_angle",
        basal_friction_angle_schema("; deformable slides only (a rigid body's Coulomb coefficient against walls is "
                                    "`friction`, which a deformable slide ignores: its default 0 would be "
                                    "frictionless)")},
       {"front_direction", S::vector("deformable slides: slide_front.csv's front is the particle furthest along this "
                                     "direction", "", 3, std::vector<double>{1.0, 0.0, 0.0})},
       {"locked", S::list("components held fixed: x, y, z (translations), rx, ry, rz (rotations about the axes)",
                          S::choice("component", {"x", "y", "z", "rx", "ry", "rz"}, std::nullopt))},
       {"motion", motion_schema()},
       {"rail", rail_schema(3)},
       {"prescribed",
        S::variant(
            "prescribed motion (motion: prescribed)", "type",
            {{"ln_cosh", S::map("s(t) = s0 ln cosh((t - start_time) / t0) along `direction` (rigid/ln_cosh_law.hpp), "
                                "the body not turning",
                                {{"direction", S::vector("direction of travel (made unit)", "", 3, std::nullopt)},
                                 {"s0", S::number("length scale s0 = u_t^2 / a0", "m", std::nullopt, 0.0, S::inf, true,
                                                  false)},
                                 {"t0", S::number("time scale t0 = u_t / a0", "s", std::nullopt, 0.0, S::inf, true,
                                                  false)},
                                 {"start_time", S::number("time the motion starts", "s", 0.0, 0.0, S::inf)}})},
             {"series",
              S::map("a CSV time series of poses (time,x,y,z,qw,qx,qy,qz[,vx,vy,vz] of the centre of mass and the "
                     "orientation as the scene states it, as in bodies.csv, whose rows it replays): the centre of "
                     "mass by cubic Hermite (slopes vx, vy, vz where given, else centred differences), the orientation "
                     "by spherical linear interpolation between rows (rigid/spatial_prescribed_motion.hpp); it must "
                     "cover [0, end_time] and start where the body is put",
                     {{"file", S::text("CSV file, relative to the scene file", std::nullopt)},
                      {"body", S::text("rows whose body column equals this (default: this body's name)", "")}})}},
            std::string(to_string(PrescribedLaw::ln_cosh)))},
       {"release_time",
        S::number("the body is held in place until this time while the water settles", "s", 0.0, 0.0, S::inf)},
       {"during_settling", S::choice("settled start (method.initial_state: settled): held keeps the body where it is "
                                     "put while the water settles; free first moves a body lighter than water up or "
                                     "down to its draft below the still-water level (Archimedes on its surface, heave "
                                     "only; the highest below_level region's level, gravity along -z), lays the water "
                                     "around it there, and lets it float with the water under the same damping",
                                     during_settling_names.names(), std::string(to_string(DuringSettling::held)))}});
}

Schema make_schema_3d() {
  return S::map(
      "a 3-D slide scene (dimension: 3): x and y horizontal, z up",
      {{"name", S::text("case name; default: the file name without extension", "")},
       {"description", S::text("free text", "")},
       {"dimension", S::integer("spatial dimension: 3 here", std::nullopt, 3L, 3L)},
       {"particle_spacing", S::number("initial particle spacing dp", "m", std::nullopt, 0.0, S::inf, true, false)},
       {"lattice", S::choice("lattice the particles start on, one particle per dp^3 either way: fcc (face-centred cubic: "
                             "planes s = 0.7937 dp apart along each axis, nearest spacing 1.1225 dp), the close packing "
                             "that still water needs to stay at rest, whose walls are cut from the same lattice to the "
                             "depth re (layers unused; a tank's water is the lattice points inside it, so a side of a "
                             "whole number of planes s holds exactly its volume); or square (simple cubic), on which a "
                             "still tank stirs itself (1 s of the 0.2 m tank: largest speed 7.87 % of sqrt(g H) "
                             "against 2.92 % on fcc with the same settling, docs/three-d.md)",
                             {std::string(to_string(LatticeKind::square)), std::string(to_string(LatticeKind::fcc))},
                             std::string(to_string(LatticeKind::fcc)))},
       {"end_time", S::number("simulated time", "s", std::nullopt, 0.0, S::inf, true, false)},
       {"gravity", S::vector("gravitational acceleration", "m/s^2", 3, std::vector<double>{0.0, 0.0, -9.81})},
       {"domain", domain_schema(3)},
       {"fluid", S::map("the fluid", {{"phases", S::list("fluid phases", phase_schema(), 1)},
                                      {"regions", S::list("regions filled with fluid (none: a dry scene, whose only fluid "
                                                          "is its deformable slides)",
                                                          region_schema_3d(), 0)}})},
       {"walls", S::list("walls", wall_schema_3d())},
       {"bodies", S::list("slides and floating bodies, rigid or deformable", body_schema_3d())},
       {"rigid", rigid_schema()},
       {"processes", processes_schema()},
       {"method", method_schema(3)},
       {"time_step", time_step_schema()},
       {"checks", checks_schema()},
       {"output", output_schema()},
       {"gauges", S::list("wave gauges", gauge_schema_3d())},
       {"profiles", profiles_schema_3d()},
       {"diagnostics", S::map("case-specific diagnostics", {{"gauge_records", gauge_records_schema()}}, false)}});
}

Schema make_schema() {
  return S::map(
      "a slide scene",
      {{"name", S::text("case name; default: the file name without extension", "")},
       {"description", S::text("free text", "")},
       {"dimension", dimension_schema()},
       {"particle_spacing", S::number("initial particle spacing dp", "m", std::nullopt, 0.0, S::inf, true, false)},
       {"lattice", S::choice("lattice the particles start on, one particle per dp^2 either way: square, or "
                             "hexagonal (nearest spacing 1.0746 dp), the stable packing that still water needs to "
                             "stay at rest; with hexagonal, walls are cut from the same lattice (layers unused), "
                             "the wall pressure must be extrapolated, the initial state lattice or "
                             "settled, and with bodies the rows are moved (less than half a row spacing) so that one "
                             "lies dp/2 below the lowest point of the first body",
                             {std::string(to_string(LatticeKind::square)), std::string(to_string(LatticeKind::hexagonal))},
                             std::string(to_string(MethodOptions{}.lattice)))},
       {"end_time", S::number("simulated time", "s", std::nullopt, 0.0, S::inf, true, false)},
       {"gravity", S::vector("gravitational acceleration", "m/s^2", 2, std::vector<double>{0.0, -9.81})},
       {"domain", domain_schema(2)},
       {"fluid", S::map("the fluid", {{"phases", S::list("fluid phases", phase_schema(), 1)},
                                      {"regions", S::list("regions filled with fluid (none: a dry scene, whose only fluid is its deformable slides)", region_schema(), 0)}})},
       {"walls", S::list("walls", wall_schema())},
       {"bodies", S::list("rigid bodies (slides, floating blocks)", body_schema())},
       {"rigid", rigid_schema()},
       {"processes", processes_schema()},
       {"method", method_schema(2)},
       {"time_step", time_step_schema()},
       {"checks", checks_schema()},
       {"output", output_schema()},
       {"gauges", S::list("wave gauges", gauge_schema())},
       {"profiles", profiles_schema()},
       {"diagnostics", S::map("case-specific diagnostics", {{"surge_front", surge_schema()},
                                                              {"velocity_profile", velocity_profile_schema()},
                                                              {"slide_shapes", slide_shapes_schema()},
                                                              {"gauge_records", gauge_records_schema()}},
                               false)}});
}

}  // namespace

const Schema& scene_schema(int dimension) {
  static const Schema schema_2d = make_schema(), schema_3d = make_schema_3d();
  return dimension == 3 ? schema_3d : schema_2d;
}

std::string scene_reference() {
  return scene_schema(2).document("slide scene reference") + "\n" +
         scene_schema(3).document("3-D scenes (dimension: 3)", 2);
}

}  // namespace slide::cases
