#include "tools/run_driver.hpp"

#include <fmt/format.h>

#include <chrono>
#include <csignal>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cases/scene.hpp"
#include "coupling/free_surface_gauge.hpp"
#include "coupling/rigid_bodies.hpp"
#include "coupling/surge_front.hpp"
#include "fluid/parallel.hpp"
#include "tools/atomic_file.hpp"
#include "tools/snapshot_writer.hpp"

namespace slide::tools {
namespace {

volatile std::sig_atomic_t interrupted = 0;
extern "C" void on_sigint(int) { interrupted = 1; }

using Clock = std::chrono::steady_clock;
using nlohmann::json;

// The resolved scene as JSON: scalars become booleans, numbers or strings.
json to_json(const YAML::Node& n) {
  if (n.IsMap()) {
    json j = json::object();
    for (const auto& kv : n) j[kv.first.as<std::string>()] = to_json(kv.second);
    return j;
  }
  if (n.IsSequence()) {
    json j = json::array();
    for (const auto& v : n) j.push_back(to_json(v));
    return j;
  }
  if (!n.IsScalar()) return nullptr;
  const std::string s = n.Scalar();
  if (s == "true") return true;
  if (s == "false") return false;
  try {
    std::size_t used = 0;
    const double d = std::stod(s, &used);
    if (used == s.size()) {
      if (s.find_first_of(".eE") == std::string::npos && std::abs(d) < 9e15) return static_cast<long long>(d);
      return d;
    }
  } catch (const std::exception&) {
  }
  return s;
}

// Copies particle data in id order, the order every snapshot uses.
struct IdOrdered {
  std::vector<double> position, velocity, pressure, number_density, density;
  std::vector<std::uint8_t> phase, kind;
  std::vector<std::uint32_t> id;

  explicit IdOrdered(const Particles<2>& P) {
    const std::size_t n = P.size();
    position.resize(2 * n);
    velocity.resize(2 * n);
    pressure.resize(n);
    number_density.resize(n);
    density.resize(n);
    phase.resize(n);
    kind.resize(n);
    id.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t k = P.id[i];
      for (int d = 0; d < 2; ++d) {
        position[2 * k + d] = P.position[i][d];
        velocity[2 * k + d] = P.velocity[i][d];
      }
      pressure[k] = P.pressure[i];
      number_density[k] = P.number_density[i];
      density[k] = P.density[i];
      phase[k] = P.phase[i];
      kind[k] = static_cast<std::uint8_t>(P.kind[i]);
      id[k] = k;
    }
  }
  SnapshotFields fields() const { return {2, position, velocity, pressure, number_density, density, phase, kind, id}; }
};

std::string limit_summary(const std::array<long, time_step_limit_count>& counts) {
  std::string s;
  for (std::size_t k = 0; k < counts.size(); ++k)
    if (counts[k] > 0) s += fmt::format("{}{} {}", s.empty() ? "" : ", ", to_string(TimeStepLimit(k)), counts[k]);
  return s;
}

// Reads, checks and builds the scene; on a scene error prints it and returns null (the caller exits 2).
std::unique_ptr<cases::Scene> load_or_report(const RunArguments& args) {
  try {
    return cases::build_scene(cases::load_scene(args.scene, args.overrides), args.scene.stem().string(),
                              args.scene.parent_path().empty() ? "." : args.scene.parent_path());
  } catch (const cases::SceneError& e) {
    std::cerr << "slide: invalid scene " << args.scene.string() << ": " << e.what() << "\n";
    return nullptr;
  }
}

double memory_estimate_mb(const Simulation<2>& sim) {
  const std::size_t n = sim.particles.size();
  const std::size_t per_particle = 4 * sizeof(Vec<2>) + 5 * sizeof(double) + 2 + 4 + sizeof(Vec<2>) + 8;
  const std::size_t list = n * sim.neighbors().capacity * sizeof(std::uint32_t) + n * 4;
  // The run keeps one more copy of the particles as the last good state, and a position copy for the skin test.
  return (2.0 * n * per_particle + n * sizeof(Vec<2>) * 2 + list) / 1.0e6;
}

}  // namespace

int check_command(const RunArguments& args) {
  const std::unique_ptr<cases::Scene> scene = load_or_report(args);
  if (!scene) return 2;
  const auto& sim = *scene->simulation;
  const auto [dt, limit] = sim.allowed_time_step();
  const auto& o = sim.options;
  std::cout << fmt::format(
      "case            {}\n"
      "particles       {} total: {} fluid, {} wall, {} dummy\n"
      "spacing dp      {} m, kernel radius re = {} dp = {} m\n"
      "lattice         {} (nearest spacing {:.6g} dp){}\n"
      "n0, lambda      {:.9g}, {:.9g} m^2 (lambda / dp^2 = {:.6g})\n"
      "sound speed c0  {:.6g} m/s ({})\n"
      "gradient model  {}\n"
      "initial dt      {:.6g} s, limited by {}\n"
      "end time        {} s (about {:.0f} steps at the initial dt)\n"
      "domain          [{:.6g}, {:.6g}] x [{:.6g}, {:.6g}] m\n"
      "memory          about {:.1f} MB\n"
      "{}",
      scene->name, sim.particles.size(), scene->fluid_count, scene->wall_count, scene->dummy_count, o.dp,
      o.re_over_dp, sim.re(), to_string(o.lattice), nearest_spacing(o.lattice, o.dp) / o.dp,
      scene->lattice_offset[1] != 0.0
          ? fmt::format(", rows moved {:+.6g} m to meet bodies[0]'s bottom", scene->lattice_offset[1])
          : std::string(),
      sim.lattice.n0, sim.lattice.lambda, sim.lattice.lambda / (o.dp * o.dp), o.sound_speed,
      scene->sound_speed_source, to_string(o.gradient), dt, to_string(limit),
      scene->end_time, scene->end_time / dt, o.domain_lo[0], o.domain_hi[0], o.domain_lo[1], o.domain_hi[1],
      memory_estimate_mb(sim),
      scene->equilibrium
          ? fmt::format("hydrostatic start: equilibrium column relaxed for {:.4g} s ({} steps), residual row speed "
                        "{:.3g} m/s\n",
                        scene->equilibrium->relaxation_time, scene->equilibrium->steps,
                        scene->equilibrium->residual_speed)
          : std::string());
  if (scene->settling)
    std::cout << fmt::format("settled start: {:.4g} s of settling at damping {:.4g} 1/s ({} steps), largest speed {:.3g} m/s, "
                             "residual speed {:.3g} m/s, largest shift {:.3g} dp\n",
                             scene->settling->duration, scene->settling->damping_rate, scene->settling->steps,
                             scene->settling->largest_speed, scene->settling->residual_speed,
                             scene->settling->largest_shift / o.dp);
  for (const auto& b : scene->bodies)
    std::cout << fmt::format(
        "body {:<10} {} motion, {} boundary particles\n"
        "  mass            {:.6g} kg/m (lattice sum {:.6g}), inertia {:.6g} kg m (lattice sum {:.6g})\n"
        "  area            {:.6g} m^2, displaced below the still-water level {:.6g} m^2, buoyancy / weight {:.4g}\n",
        b.name, b.motion, b.particles, b.mass, b.mass_particles, b.inertia, b.inertia_particles, b.area,
        b.displaced_area, b.buoyancy_ratio);
  for (std::size_t k = 0; k < scene->bodies.size(); ++k) {
    const auto& b = scene->bodies[k];
    if (!b.free_while_settling || !scene->settling) continue;
    const auto s = sim.bodies->state(static_cast<int>(k));
    std::cout << fmt::format("  settled with the water: centre ({:.6g}, {:.6g}) m, angle {:.4g} deg, {:.3g} mm from "
                             "where it was put\n",
                             s.position[0], s.position[1], s.angle * 180.0 / M_PI,
                             1000.0 * (Vec<2>(s.position[0], s.position[1]) - b.placed).norm());
  }
  return 0;
}

int run_command(const RunArguments& args) {
  const auto setup_start = Clock::now();
  if (args.threads < 0) {
    std::cerr << "slide: --threads must be at least 1 (got " << args.threads << ")\n";
    return 2;
  }
  if (args.threads > 0) set_thread_count(args.threads);
  const std::unique_ptr<cases::Scene> scene = load_or_report(args);
  if (!scene) return 2;
  auto& sim = *scene->simulation;
  const std::filesystem::path out = args.out.empty() ? std::filesystem::path("runs") / scene->name : args.out;
  std::filesystem::create_directories(out);

  std::optional<SnapshotWriter> snapshots;
  if (scene->output.snapshots) snapshots.emplace(out);
  std::optional<CsvWriter> gauges, front, bodies_csv;
  const std::shared_ptr<RigidBodies> bodies = sim.bodies;
  if (bodies)
    bodies_csv.emplace(out / "bodies.csv",
                       std::vector<std::string>{"time", "body", "x", "y", "angle", "vx", "vy", "omega", "fx", "fy",
                                                "torque", "fx_pressure", "fy_pressure", "torque_pressure",
                                                "fx_viscous", "fy_viscous", "torque_viscous", "fx_contact",
                                                "fy_contact"});
  // Forces in bodies.csv are means over the interval since the previous row (the momentum received / time).
  auto sample_bodies = [&]() {
    if (!bodies) return;
    const auto mean = bodies->take_mean_forces();
    for (std::size_t b = 0; b < bodies->size(); ++b) {
      const auto s = bodies->state(int(b));
      const auto& f = mean[b].fluid;
      const auto& c = mean[b].contact;
      const double row[] = {s.position[0], s.position[1], s.angle, s.velocity[0], s.velocity[1],
                            s.angular_velocity, f.total()[0], f.total()[1], f.total_torque(), f.pressure[0],
                            f.pressure[1], f.pressure_torque, f.viscous[0], f.viscous[1], f.viscous_torque, c[0], c[1]};
      bodies_csv->add_labelled_row(sim.time, bodies->names[b], row);
    }
  };
  if (!scene->gauges.empty()) {
    std::vector<std::string> cols{"time"};
    for (const auto& g : scene->gauges) cols.push_back(g.name);
    gauges.emplace(out / "gauges.csv", cols);
  }
  const auto& sf = scene->surge_front;
  if (sf.enabled)
    front.emplace(out / "surge_front.csv",
                  std::vector<std::string>{"time", "front", "wall_height", "T", "Z", "H_over_2a"});

  auto write_snapshot = [&](const Particles<2>& P, double t, long step) {
    if (snapshots) snapshots->write(t, step, IdOrdered(P).fields());
  };
  auto sample = [&]() {
    if (gauges) {
      std::vector<double> row{sim.time};
      for (const auto& g : scene->gauges) row.push_back(free_surface_elevation<2>(sim, Vec<2>(g.x, 0.0)));
      gauges->add_row(row);
    }
    if (front) {
      const SurgeFront f = measure_surge_front<2>(sim, sf.wall_face_x, sf.floor_y);
      const double a = sf.column_width, g = -sim.options.gravity[1];
      const double T = a > 0 ? sim.time * std::sqrt(2.0 * g / a) : NAN;
      front->add_row({sim.time, f.front, f.wall_height, T, a > 0 ? f.front / a : NAN,
                      a > 0 ? f.wall_height / (2 * a) : NAN});
    }
  };
  std::optional<CsvWriter> profiles;
  std::size_t next_profile = 0;
  if (!scene->profiles.times.empty()) profiles.emplace(out / "profiles.csv", std::vector<std::string>{"time", "x", "eta"});
  auto sample_profiles = [&]() {
    const auto& ps = scene->profiles;
    while (profiles && next_profile < ps.times.size() && sim.time >= ps.times[next_profile] - 1e-12) {
      const long n = std::lround((ps.x_max - ps.x_min) / ps.spacing);
      for (long k = 0; k <= n; ++k) {
        const double x = ps.x_min + (ps.x_max - ps.x_min) * k / std::max(1L, n);
        profiles->add_row({sim.time, x, free_surface_elevation<2>(sim, Vec<2>(x, 0.0))});
      }
      ++next_profile;
    }
  };
  auto flush_csv = [&]() {
    if (profiles) profiles->flush();
    if (bodies_csv) bodies_csv->flush();
    if (gauges) gauges->flush();
    if (front) front->flush();
  };

  const auto loop_start = Clock::now();
  const double setup_seconds = std::chrono::duration<double>(loop_start - setup_start).count();
  auto write_run_json = [&](const std::string& status, const std::string& message, const json& extra) {
    const double wall = std::chrono::duration<double>(Clock::now() - loop_start).count();
    const double particle_steps = double(sim.particles.size()) * double(sim.step_count);
    json j;
    j["program"] = "slide";
    j["version"] = SLIDE_VERSION;
    j["case"] = scene->name;
    j["scene_file"] = args.scene.string();
    j["overrides"] = args.overrides;
    j["status"] = status;
    j["message"] = message;
    j["threads"] = thread_count();
    j["particles"] = {{"total", sim.particles.size()}, {"fluid", scene->fluid_count},
                      {"wall", scene->wall_count},      {"dummy", scene->dummy_count}};
    j["derived"] = {{"n0", sim.lattice.n0},
                    {"lambda", sim.lattice.lambda},
                    {"sound_speed", sim.options.sound_speed},
                    {"sound_speed_source", scene->sound_speed_source},
                    {"deepest_water", scene->deepest_water},
                    {"domain_min", {sim.options.domain_lo[0], sim.options.domain_lo[1]}},
                    {"domain_max", {sim.options.domain_hi[0], sim.options.domain_hi[1]}}};
    json limits = json::object();
    for (std::size_t k = 0; k < sim.limit_counts.size(); ++k) limits[std::string(to_string(TimeStepLimit(k)))] = sim.limit_counts[k];
    j["time_step_limits"] = limits;
    j["simulated_time"] = sim.time;
    j["steps"] = sim.step_count;
    j["neighbor_rebuilds"] = sim.neighbor_rebuilds();
    j["setup_seconds"] = setup_seconds;
    j["wall_seconds"] = wall;
    j["particle_steps_per_second"] = wall > 0 ? particle_steps / wall : 0.0;
    j["snapshots"] = snapshots ? snapshots->count() : 0;
    j["scene"] = to_json(scene->resolved);
    for (auto it = extra.begin(); it != extra.end(); ++it) j[it.key()] = it.value();
    write_file_atomically(out / "run.json", j.dump(2) + "\n");
  };

  try {
    // Initial state.
    write_snapshot(sim.particles, sim.time, sim.step_count);
    sample();
    sample_bodies();
    sample_profiles();
    flush_csv();
    write_run_json("running", "", json::object());

    auto previous_handler = std::signal(SIGINT, on_sigint);
    interrupted = 0;
    Particles<2> last_good = sim.particles;
    double last_good_time = sim.time;
    long last_good_step = sim.step_count;
    const long save_every = 10;
    const double snapshot_interval = scene->output.snapshot_interval;
    double next_snapshot = snapshot_interval > 0 ? snapshot_interval : std::numeric_limits<double>::infinity();
    double next_sample = scene->output.gauge_interval;
    double next_body_sample = scene->body_sample_interval;
    auto next_progress = Clock::now() + std::chrono::seconds(1);
    const double end = scene->end_time;
    const double eps = 1e-12 * std::max(1.0, end);

    while (sim.time < end - eps) {
      if (interrupted) {
        std::signal(SIGINT, previous_handler);
        write_snapshot(sim.particles, sim.time, sim.step_count);
        flush_csv();
        const std::string msg = fmt::format("interrupted at t = {:.6g} s (step {}); final snapshot written", sim.time,
                                            sim.step_count);
        write_run_json("interrupted", msg, json::object());
        std::cerr << "\nslide: " << msg << "\n";
        return 130;
      }
      if (sim.step_count % save_every == 0) {
        last_good = sim.particles;
        last_good_time = sim.time;
        last_good_step = sim.step_count;
      }
      auto [dt, limit] = sim.allowed_time_step();
      if (sim.time + dt >= end - eps) {
        dt = end - sim.time;
        limit = TimeStepLimit::end_time;
      }
      if (auto bad = sim.step(dt, limit)) {
        std::signal(SIGINT, previous_handler);
        write_snapshot(last_good, last_good_time, last_good_step);
        flush_csv();
        const std::string where =
            bad->position.size() >= 2 ? fmt::format("({:.6g}, {:.6g})", bad->position[0], bad->position[1]) : "";
        const std::string msg = fmt::format(
            "unstable at t = {:.6g} s (step {}): particle {} at {}: {}; last good snapshot: t = {:.6g} s (step {})",
            bad->time, bad->step, bad->particle, where, bad->reason, last_good_time, last_good_step);
        write_run_json("unstable", msg,
                       {{"instability",
                         {{"time", bad->time},
                          {"step", bad->step},
                          {"particle", bad->particle},
                          {"position", bad->position},
                          {"reason", bad->reason},
                          {"last_good_time", last_good_time},
                          {"last_good_step", last_good_step}}}});
        std::cerr << "\nslide: " << msg << "\n";
        return 3;
      }
      if (sim.time >= next_sample - eps) {
        sample();
        next_sample += scene->output.gauge_interval;
        if (sim.time >= next_sample) next_sample = sim.time + scene->output.gauge_interval;
      }
      sample_profiles();
      if (bodies && sim.time >= next_body_sample - eps) {
        sample_bodies();
        next_body_sample += scene->body_sample_interval;
        if (sim.time >= next_body_sample) next_body_sample = sim.time + scene->body_sample_interval;
      }
      if (sim.time >= next_snapshot - eps) {
        write_snapshot(sim.particles, sim.time, sim.step_count);
        flush_csv();
        next_snapshot += snapshot_interval;
        if (sim.time >= next_snapshot) next_snapshot = sim.time + snapshot_interval;
      }
      if (!args.quiet && Clock::now() >= next_progress) {
        next_progress = Clock::now() + std::chrono::seconds(1);
        const double wall = std::chrono::duration<double>(Clock::now() - loop_start).count();
        const double rate = double(sim.particles.size()) * sim.step_count / wall;
        const double eta = wall / sim.time * (end - sim.time);
        std::cerr << fmt::format("\rt = {:.5f} / {:.5g} s  dt = {:.3e} s  {:.3g} M particle-steps/s  ETA {:.0f} s   ",
                                 sim.time, end, dt, rate / 1e6, eta)
                  << std::flush;
      }
    }
    std::signal(SIGINT, previous_handler);
    if (snapshots && (snapshots->count() == 0 || snapshot_interval <= 0 || sim.time > next_snapshot - snapshot_interval + eps))
      write_snapshot(sim.particles, sim.time, sim.step_count);
    sample();
    if (bodies && sim.time > next_body_sample - scene->body_sample_interval + eps) sample_bodies();
    flush_csv();
    const double wall = std::chrono::duration<double>(Clock::now() - loop_start).count();
    const std::string msg = fmt::format(
        "completed t = {:.6g} s in {} steps, {:.3f} s wall, {:.4g} M particle-steps/s; time-step limits: {}", sim.time,
        sim.step_count, wall, double(sim.particles.size()) * sim.step_count / wall / 1e6,
        limit_summary(sim.limit_counts));
    write_run_json("completed", msg, json::object());
    if (!args.quiet) std::cerr << "\r" << std::string(100, ' ') << "\rslide: " << msg << "\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "\nslide: error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace slide::tools
