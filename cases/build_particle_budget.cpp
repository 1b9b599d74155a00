// Step: the scene's particle count, estimated from its geometry before any particle is made, against what slide
// indexes and what this machine's memory holds (cases/particle_budget.hpp). A scene over either is refused naming
// particle_spacing: made anyway, it would allocate until the machine swaps and the run appears to hang.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "cases/observed_particles.hpp"
#include "cases/particle_budget.hpp"
#include "cases/scene_build.hpp"
#include "fluid/process_halo.hpp"
#include "fluid/walls.hpp"

namespace slide::cases {
namespace {

// Area of a closed polygon given by its vertices (rigid/polygon.hpp's formula: scene_geometry.hpp).
double polygon_area(const std::vector<Vec<2>>& p) {
  std::vector<rigid::Vec2> v;
  for (const auto& q : p) v.push_back(to_rigid(q));
  return std::abs(rigid::signed_area(v));
}

double polyline_length(const std::vector<Vec<2>>& p) {
  double length = 0.0;
  for (std::size_t k = 1; k < p.size(); ++k) length += (p[k] - p[k - 1]).norm();
  return length;
}

std::string size_text(double bytes) {
  return bytes >= 1e9 ? fmt::format("{:.3g} GB", bytes / 1e9) : fmt::format("{:.3g} MB", bytes / 1e6);
}

// ", a quarter of it for each of the 4 processes on this machine": where a machine's limit is shared.
std::string shared_by(const MemoryLimit& limit, int here) {
  return limit.per_machine && here > 1 ? fmt::format(", shared by the {} processes of the run on this machine", here)
                                       : "";
}
std::string fewer_here(const MemoryLimit& limit, int here) {
  return limit.per_machine && here > 1 ? ", or fewer processes on each machine" : "";
}

std::optional<MemoryLimit> read_memory_limit() {
  try {
    return memory_limit();
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    throw SceneError(what.starts_with("SLIDE_MACHINE_MEMORY") ? "SLIDE_MACHINE_MEMORY" : "SLIDE_MEMORY_LIMIT", what);
  }
}

// " on process 1 of 4", or " on the 4 processes of the run on this machine together".
std::string where_needed(const Communicator* comm, const MemoryLimit& limit, int here) {
  if (!comm) return "";
  if (limit.per_machine && here > 1)
    return fmt::format(" on the {} processes of the run on this machine together (process {} of {} among them)", here,
                       comm->rank(), comm->size());
  return fmt::format(" on process {} of {}", comm->rank(), comm->size());
}

}  // namespace

// Both lattices hold one point per dp^2 (the hexagonal one's columns 1.0746 dp apart, rows 0.9306 dp). Regions and
// slides: their area; below_level water: the walls' width times its depth below the level (an upper bound); walls:
// their length times their layers; rigid bodies: the larger of their area and their perimeter times the layers.
double estimated_particles(const SceneBuild<2>& b) {
  const double dp = b.dp, cell = dp * dp;
  const int auto_layers = boundary_layers(b.sim->options.re_over_dp);
  double n = 0.0;
  Vec<2> wall_lo = Vec<2>::Constant(INFINITY), wall_hi = Vec<2>::Constant(-INFINITY);
  for (const auto& wn : b.r["walls"]) {
    const auto pts = points_of(wn["points"]);
    for (const auto& q : pts) wall_lo = wall_lo.cwiseMin(q), wall_hi = wall_hi.cwiseMax(q);
    const long layers = wn["layers"].as<long>();
    n += (polyline_length(pts) / dp + 1.0) * double(layers == 0 ? auto_layers : layers);
  }
  for (const auto& rn : b.r["fluid"]["regions"]) {
    const std::string type = rn["type"].as<std::string>();
    if (type == "rectangle") {
      const Vec<2> lo = vec2(rn["min"]), hi = vec2(rn["max"]);
      n += std::max(0.0, hi[0] - lo[0]) * std::max(0.0, hi[1] - lo[1]) / cell;
    } else if (type == "polygon") {
      n += polygon_area(points_of(rn["points"])) / cell;
    } else if (wall_lo[0] < wall_hi[0]) {  // below_level, inside the walls
      n += (wall_hi[0] - wall_lo[0]) * std::max(0.0, std::min(rn["level"].as<double>(), wall_hi[1]) - wall_lo[1]) / cell;
    }
  }
  for (std::size_t k = 0; k < b.r["bodies"].size(); ++k) {
    const auto outline = body_outline(b.r["bodies"][k], fmt::format("bodies[{}]", k));
    std::vector<Vec<2>> closed;
    for (const auto& v : outline) closed.push_back(from_rigid(v));
    closed.push_back(closed.front());
    n += std::max(std::abs(rigid::signed_area(outline)) / cell, polyline_length(closed) / dp * auto_layers);
  }
  return n;
}

// Before any particle is made: refused where slide cannot index the particles, or where their own arrays alone would
// not fit (so that a scene far too large for the machine is refused without allocating until it swaps). The run's
// estimate, which needs the particles' neighbour counts, follows once they are made (check_run_memory).
template <int D>
void check_particle_budget(SceneBuild<D>& b) {
  const double n = estimated_particles(b);
  if (n > 4294967295.0)
    throw SceneError("particle_spacing", fmt::format("the scene would make about {:.3g} particles at dp = {} m, more "
                                                     "than slide can index (2^32 - 1); use a larger particle_spacing",
                                                     n, b.dp));
  if (b.counting) return;  // (the counting pass makes none: cases/build_share.hpp)
  const auto limit = read_memory_limit();
  // Several processes on one machine each make the whole scene's particles (2-D), or their part of it (3-D, counted:
  // cases/build_share.hpp): each has its even part of a machine's memory.
  const double made = b.share ? double(b.share->held()) : n;
  const double bytes = program_resident_bytes() + particle_state_bytes(made, D);
  const int here = b.machine.count();
  if (limit && bytes > limit->even_share_bytes(here))
    throw SceneError("particle_spacing",
                     fmt::format("the scene would make about {:.3g} particles at dp = {} m{}, whose arrays alone "
                                 "need about {}, more than the {} available ({}{}); use a larger particle_spacing{}",
                                 made, b.dp, b.share ? " on this process (its part of the scene)" : "",
                                 size_text(bytes), size_text(limit->even_share_bytes(here)), limit->source,
                                 shared_by(*limit, here), fewer_here(*limit, here)));
}

// Once the particles are made and their neighbours listed: the run's peak memory (cases/particle_budget.hpp), what
// slide check prints and run.json records, refused where it exceeds what this machine or job has, before the run
// allocates the rest.
template <int D>
void check_run_memory(SceneBuild<D>& b) {
  const YAML::Node& r = b.r;  // (b is of a dependent type: r's .as<T>() needs no 'template')
  const Simulation<D>& sim = *b.sim;
  const double n = double(sim.particles().size());
  RunMemoryInputs in;
  in.dimension = D;
  in.particles = n;
  in.listed_per_particle = double(sim.neighbors().total()) / std::max(1.0, n);
  in.snapshots = b.scene->output.snapshots;
  in.snapshot_deflate = b.scene->output.snapshot_deflate;
  in.bodies_or_slides = !b.scene->bodies.empty() || !b.scene->slides.empty();
  for (const auto& phase : sim.phases) in.non_newtonian = in.non_newtonian || !std::holds_alternative<Newtonian>(phase.rheology);
  const double settling = b.initial_state == InitialState::settled ? r["method"]["settling_time"].as<double>() : 0.0;
  const double dt = sim.allowed_time_step().first;
  in.body_steps = dt > 0.0 ? double(b.scene->bodies.size()) * (settling + b.scene->end_time) / dt : 0.0;
  b.scene->memory_estimate_bytes = program_resident_bytes() + run_memory_bytes(in);
  // Several processes (cases::ForProcesses): this process's share, its part of the build and, on the first, the
  // observers' copy of the particles the outputs read; each holds its own against its limit (SLIDE_MEMORY_LIMIT is a
  // process's).
  const Communicator* comm = sim.domain().distributed() ? sim.domain().communicator() : nullptr;
  const ObservedParticles<D> observed(*b.scene, sim.domain().ghost_layout(), sim.re() + sim.options.dp);
  std::int64_t whole[3] = {static_cast<std::int64_t>(sim.particles().real_count()),
                           static_cast<std::int64_t>(sim.particles().size()), 0};
  if (comm) {
    for (std::size_t i = 0; i < sim.particles().real_count(); ++i) whole[2] += observed(sim.particles(), i) ? 1 : 0;
    // the particles made, with their images (and other processes' copies: an upper bound), and those the copy holds
    comm->sum(whole, 3);
    const double images = whole[0] > 0 ? double(whole[1]) / double(whole[0]) : 1.0;
    // A share grows as particles come into its cells until the imbalance passes the rebalance threshold (fluid/domain.hpp
    // redistribute), and its arrays keep the largest size they had: its run is counted at that size, its ghosts and
    // listed neighbours in the same ratio to its owned particles as now. Found at stop 60: over the 3-D bench run to
    // its end, a share of four peaked 15 % above its estimate taken at the start.
    const double owned = double(sim.particles().real_count());
    const double largest_owned = sim.domain().imbalance_before_rebalance() * double(whole[0]) / comm->size();
    const double growth = owned > 0.0 && largest_owned > owned ? largest_owned / owned : 1.0;
    in.particles = n * growth;
    // The build is its part (a 3-D scene's, cases/build_share.hpp; a 2-D scene's whole). Until stop 63 the estimate
    // counted the whole scene's build, which stood in for the ghosts' exchange (process_memory_bytes) and grew with the
    // scene however many processes shared it.
    ProcessMemoryInputs process{double(b.scene->particles_made_here), images * double(whole[2]),
                                comm->rank() == 0, b.scene->surge_front.enabled,
                                b.initial_state == InitialState::settled};
    process.ghosts = double(sim.particles().ghost_count()) * growth;
    process.ghost_entry_bytes = double(ProcessHalo<D>::ghost_entry_bytes(sim.particles()));
    b.scene->memory_estimate_bytes = program_resident_bytes() + process_memory_bytes(in, process);
  }
  b.scene->memory_list_growth_bytes = list_growth_bytes(in);  // (of this process's share, as counted above)
  const auto limit = read_memory_limit();
  // A machine's memory (every limit but SLIDE_MEMORY_LIMIT) holds the estimates of the processes on it together, each
  // its own: the first's is the largest (collectives on every process, whatever its limit).
  // The machine's free memory as the least any of them read, so that they decide alike. A run each of whose processes
  // holds the whole scene (a resumed 2-D run, built whole before it is shared): each its even part.
  double need = b.scene->memory_estimate_bytes, have = limit ? limit->total_bytes() : 0.0;
  const int here = b.machine.count();
  if (comm) {
    const double estimates = b.machine.sum_here(*comm, need);
    const double residents = b.machine.sum_here(*comm, limit ? limit->resident_when_read : 0.0);
    const double least = b.machine.least_here(*comm, limit ? limit->bytes : 0.0);
    if (limit && limit->per_machine) {
      need = estimates;
      have = limit->whole_process ? least : least + residents;
    }
  } else if (limit) {
    have = limit->even_share_bytes(here);
  }
  if (limit && need > have)
    throw SceneError("particle_spacing",
                     fmt::format("the run of its {} particles at dp = {} m would need about {} of memory at its peak{}, "
                                 "more than the {} available ({}); use a larger particle_spacing{}{}",
                                 whole[0], b.dp, size_text(need), where_needed(comm, *limit, here),
                                 size_text(have), limit->source + (comm ? "" : shared_by(*limit, here)),
                                 fewer_here(*limit, here),
                                 comm && comm->rank() == 0 ? " (the first process also holds a copy of the "
                                                             "particles its outputs read)"
                                                           : ""));
}

template void check_particle_budget(SceneBuild<2>&);
template void check_particle_budget(SceneBuild<3>&);
template void check_run_memory(SceneBuild<2>&);
template void check_run_memory(SceneBuild<3>&);

}  // namespace slide::cases
