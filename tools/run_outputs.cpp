#include "tools/run_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include <fmt/format.h>

#include "coupling/free_surface_gauge.hpp"
#include "coupling/rigid_bodies.hpp"
#include "coupling/slide_front.hpp"
#include "coupling/slide_shape_error.hpp"
#include "coupling/surge_front.hpp"
#include "coupling/velocity_profile.hpp"
#include "tools/measures/gauge_records.hpp"

namespace slide::tools {

template <int D>
void IdOrdered<D>::assign(const Particles<D>& P) {
  const std::size_t n = P.real_count();  // periodic ghosts are images, not particles of their own
  for (auto* v : {&position, &velocity}) v->resize(D * n);
  for (auto* v : {&pressure, &number_density, &density}) v->resize(n);
  for (auto* v : {&phase, &kind}) v->resize(n);
  id.resize(n);
  const auto put = [&](std::size_t slot, std::size_t i) {
    for (int d = 0; d < D; ++d) {
      position[D * slot + d] = P.position[i][d];
      velocity[D * slot + d] = P.velocity[i][d];
    }
    pressure[slot] = P.pressure[i];
    number_density[slot] = P.number_density[i];
    density[slot] = P.density[i];
    phase[slot] = P.phase[i];
    kind[slot] = static_cast<std::uint8_t>(P.kind[i]);
    id[slot] = P.id[i];
  };
  // By id. Without gaps the ids are 0 .. n - 1 and each particle goes straight to its slot (the last good state
  // takes this every few steps, and a temporary index each time fragmented the heap).
  ParticleId id_end = 0;
  for (std::size_t i = 0; i < n; ++i) id_end = std::max<ParticleId>(id_end, P.id[i] + 1);
  if (id_end == n) {
    for (std::size_t i = 0; i < n; ++i) put(P.id[i], i);
    return;
  }
  // Ids have gaps where particles left the domain (Particles::remove_keeping_ids), or where this process's share of
  // the particles (several processes) leaves the others' out.
  std::vector<std::uint32_t> index_of_id(id_end, std::numeric_limits<std::uint32_t>::max());
  for (std::size_t i = 0; i < n; ++i) index_of_id[P.id[i]] = static_cast<std::uint32_t>(i);
  std::size_t slot = 0;
  for (const std::uint32_t i : index_of_id)
    if (i != std::numeric_limits<std::uint32_t>::max()) put(slot++, i);
}

template <int D>
std::vector<unsigned char> IdOrdered<D>::bytes(std::size_t begin, std::size_t end) const {
  std::vector<unsigned char> out;
  const auto put = [&out, begin, end](const auto& v, std::size_t per) {
    const auto* p = reinterpret_cast<const unsigned char*>(v.data());
    const std::size_t row = per * sizeof(v[0]);
    out.insert(out.end(), p + begin * row, p + end * row);
  };
  const std::uint64_t n = end - begin;
  out.insert(out.end(), reinterpret_cast<const unsigned char*>(&n), reinterpret_cast<const unsigned char*>(&n + 1));
  put(position, D), put(velocity, D), put(pressure, 1), put(number_density, 1), put(density, 1), put(phase, 1);
  put(kind, 1), put(id, 1);
  return out;
}

template <int D>
IdOrdered<D> IdOrdered<D>::merged(const std::vector<unsigned char>& pieces) {
  IdOrdered all;
  for (const unsigned char *in = pieces.data(), *end = in + pieces.size(); in < end;) {
    std::uint64_t n = 0;
    std::memcpy(&n, in, sizeof n);
    in += sizeof n;
    const auto get = [&in, n](auto& v, std::size_t per) {
      const std::size_t old = v.size(), bytes = n * per * sizeof(v[0]);
      v.resize(old + n * per);
      std::memcpy(v.data() + old, in, bytes);
      in += bytes;
    };
    get(all.position, D), get(all.velocity, D), get(all.pressure, 1), get(all.number_density, 1), get(all.density, 1);
    get(all.phase, 1), get(all.kind, 1), get(all.id, 1);
  }
  std::vector<std::size_t> order(all.id.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return all.id[a] < all.id[b]; });
  const auto permute = [&order](auto& v, std::size_t per) {
    auto was = v;
    for (std::size_t k = 0; k < order.size(); ++k)
      for (std::size_t c = 0; c < per; ++c) v[per * k + c] = was[per * order[k] + c];
  };
  permute(all.position, D), permute(all.velocity, D), permute(all.pressure, 1), permute(all.number_density, 1);
  permute(all.density, 1), permute(all.phase, 1), permute(all.kind, 1), permute(all.id, 1);
  return all;
}

namespace {

// A gauge's point in the plan, at height 0 (the gauge scans the vertical through it).
template <int D>
Vec<D> gauge_point(const cases::GaugeSpec& g) {
  Vec<D> p = Vec<D>::Zero();
  p[0] = g.x;
  if constexpr (D == 3) p[1] = g.y;
  return p;
}

// The next time of a periodic sample after one taken now: one interval on, or from now if the run jumped past it.
double next_after(double next, double interval, double now) {
  next += interval;
  return now >= next ? now + interval : next;
}

// "0 fluid, 1 wall, 2 dummy" and "0 water, 1 sediment": what the snapshots' codes stand for.
template <int D>
SnapshotLegend snapshot_legend(const Simulation<D>& sim) {
  SnapshotLegend legend;
  for (const auto& [kind, name] : kind_names.entries)
    legend.kind_codes += fmt::format("{}{} {}", legend.kind_codes.empty() ? "" : ", ", static_cast<int>(kind), name);
  for (std::size_t k = 0; k < sim.phases.size(); ++k)
    legend.phase_codes += fmt::format("{}{} {}", k == 0 ? "" : ", ", k, sim.phases[k].name);
  legend.code = fmt::format("slide {}", SLIDE_VERSION);
  return legend;
}

// bodies.csv's columns. 2-D: the pose as (x, y, angle), torques about z. 3-D: the orientation as a quaternion (w, x,
// y, z) and as Tait-Bryan angles roll, pitch, yaw (rad; intrinsic z-y'-x'': R = Rz(yaw) Ry(pitch) Rx(roll)), the
// angular velocity and torques as vectors in world axes.
template <int D>
std::vector<std::string> body_columns() {
  if constexpr (D == 2)
    return {"time", "body", "x", "y", "angle", "vx", "vy", "omega", "fx", "fy",
            "torque", "fx_pressure", "fy_pressure", "torque_pressure", "fx_viscous",
            "fy_viscous", "torque_viscous", "fx_contact", "fy_contact"};
  else
    return {"time", "body", "x", "y", "z", "qw", "qx", "qy", "qz", "roll", "pitch", "yaw", "vx", "vy", "vz",
            "wx", "wy", "wz", "fx", "fy", "fz", "tx", "ty", "tz", "fx_pressure", "fy_pressure", "fz_pressure",
            "tx_pressure", "ty_pressure", "tz_pressure", "fx_viscous", "fy_viscous", "fz_viscous", "tx_viscous",
            "ty_viscous", "tz_viscous", "fx_contact", "fy_contact", "fz_contact"};
}

template <int D>
std::vector<double> body_row(const RigidBodies<D>& bodies, int b, const typename RigidBodies<D>::MeanForces& mean) {
  const auto s = bodies.state(b);
  const auto& f = mean.fluid;
  const auto& c = mean.contact;
  if constexpr (D == 2) {
    return {s.position[0], s.position[1], bodies.absolute_angle(b), s.velocity[0], s.velocity[1],
            s.angular_velocity, f.total()[0], f.total()[1], f.total_torque(), f.pressure[0],
            f.pressure[1], f.pressure_torque, f.viscous[0], f.viscous[1], f.viscous_torque, c[0], c[1]};
  } else {
    // q and -q are the same rotation; Bullet's may change sign between rows, so bodies.csv keeps qw >= 0.
    rigid::Quat q = bodies.absolute_orientation(b);
    if (q.w() < 0.0) q.coeffs() *= -1.0;
    const Eigen::Matrix3d R = Eigen::Quaterniond(q).toRotationMatrix();
    const double roll = std::atan2(R(2, 1), R(2, 2)), pitch = -std::asin(std::clamp(R(2, 0), -1.0, 1.0)),
                 yaw = std::atan2(R(1, 0), R(0, 0));
    std::vector<double> row{s.position[0], s.position[1], s.position[2], q.w(), q.x(), q.y(), q.z(), roll, pitch, yaw};
    for (const Vec<3>& v : {Vec<3>(s.velocity), Vec<3>(s.angular_velocity), f.total(), Vec<3>(f.total_torque()),
                            f.pressure, f.pressure_torque, f.viscous, f.viscous_torque, c})
      row.insert(row.end(), {v[0], v[1], v[2]});
    return row;
  }
}

}  // namespace

template <int D>
SnapshotFormat snapshot_format(const cases::Scene<D>& scene) {
  SnapshotFormat format;
  if (!scene.output.snapshot_fields.empty()) format.fields = scene.output.snapshot_fields;
  format.single_precision = scene.output.snapshot_single_precision;
  format.deflate = scene.output.snapshot_deflate;
  return format;
}

template <int D>
RunOutputs<D>::RunOutputs(const cases::Scene<D>& scene, const Simulation<D>& observed, const std::filesystem::path& out,
                          bool resuming)
    : scene_(scene), sim_(observed) {
  if (scene.output.snapshots) snapshots_.emplace(out, snapshot_legend(sim_), !resuming, snapshot_format(scene));
  if (sim_.bodies()) bodies_.emplace(out / "bodies.csv", body_columns<D>());
  if (!scene.gauges.empty()) {
    std::vector<std::string> cols{"time"};
    for (const auto& g : scene.gauges) cols.push_back(g.name);
    gauges_.emplace(out / "gauges.csv", cols);
  }
  if (scene.surge_front.enabled)
    front_.emplace(out / "surge_front.csv",
                   std::vector<std::string>{"time", "front", "wall_height", "T", "Z", "H_over_2a"});
  if (scene.velocity_profile.enabled)
    velocity_profile_.emplace(out / "velocity_profile.csv",
                              std::vector<std::string>{"time", "y", "u", "v", "particles"});
  if (!scene.profiles.times.empty())
    profiles_.emplace(out / "profiles.csv", D == 2 ? std::vector<std::string>{"time", "x", "eta"}
                                                   : std::vector<std::string>{"time", "x", "y", "eta"});
  if (!scene.slides.empty()) {
    std::vector<std::string> cols{"time", "slide", "front_x", "front_y"};
    if (D == 3) cols.push_back("front_z");
    for (const char* c : {"front_along", "thickness_max", "particles"}) cols.push_back(c);
    slide_front_.emplace(out / "slide_front.csv", cols);
  }
  // Rigid bodies' upper surfaces too, so that one scene's two slide models compare alike: 2-D, a line (x, y); 3-D, a
  // height map (x, y, z).
  if ((!scene.slides.empty() || sim_.bodies()) && !scene.slide_outline_times.empty())
    slide_outline_.emplace(out / "slide_outline.csv",
                           D == 2 ? std::vector<std::string>{"time", "slide", "x", "y"}
                                  : std::vector<std::string>{"time", "slide", "x", "y", "z"});
  if (scene.slide_shapes && (!scene.slides.empty() || sim_.bodies()))
    slide_shapes_.emplace(out / "slide_shapes.csv",
                          std::vector<std::string>{"time", "slide", "time_measured", "front_measured", "front_model",
                                                   "travel_measured", "front_error_percent", "surface_rms",
                                                   "compared_columns"});
  eps_ = 1e-12 * std::max(1.0, scene.end_time);
  if (scene.output.snapshot_interval > 0) next_snapshot_ = scene.output.snapshot_interval;
  next_sample_ = scene.output.gauge_interval;
  next_body_sample_ = scene.body_sample_interval;
}

template <int D>
void RunOutputs<D>::write_snapshot(const Particles<D>& P, double time, long step) {
  if (!snapshots_) return;
  if (shared_snapshot_) shared_snapshot_(time, step);
  else snapshots_->write(time, step, IdOrdered<D>(P).fields());
}

template <int D>
void RunOutputs<D>::write_snapshot(const IdOrdered<D>& snapshot, double time, long step) {
  if (snapshots_) snapshots_->write(time, step, snapshot.fields());
}

// Gauges, the surge front and the velocity profile.
template <int D>
void RunOutputs<D>::sample() {
  last_sample_time_ = sim_.time();
  sample_slides();
  if (gauges_) {
    std::vector<double> row{sim_.time()};
    for (const auto& g : scene_.gauges) row.push_back(free_surface_elevation<D>(sim_, gauge_point<D>(g)));
    gauges_->add_row(row);
  }
  if constexpr (D == 2) sample_flume_diagnostics();
}

// The 2-D flume's diagnostics: the dam break's surge front and the velocity profile across the flow.
template <int D>
void RunOutputs<D>::sample_flume_diagnostics() {
  if (front_) {
    const auto& sf = scene_.surge_front;
    const SurgeFront f = measure_surge_front<D>(sim_, sf.wall_face_x, sf.floor_y, 0.25 * sf.column_width);
    const double a = sf.column_width, g = -sim_.options.gravity[1];
    const double T = a > 0 ? sim_.time() * std::sqrt(2.0 * g / a) : NAN;
    front_->add_row({sim_.time(), f.front, f.wall_height, T, a > 0 ? f.front / a : NAN,
                     a > 0 ? f.wall_height / (2 * a) : NAN});
  }
  if (velocity_profile_) {
    const auto& vp = scene_.velocity_profile;
    for (const auto& r : velocity_profile<D>(sim_, vp.y_origin, vp.bin))
      velocity_profile_->add_row({sim_.time(), r.y, r.u, r.v, double(r.particles)});
  }
}

// Forces in bodies.csv are means over the interval since the previous row (the momentum received / time).
template <int D>
void RunOutputs<D>::sample_bodies() {
  const auto& bodies = sim_.bodies();
  if (!bodies) return;
  last_body_sample_time_ = sim_.time();
  const auto mean = bodies->take_mean_forces();
  for (std::size_t b = 0; b < bodies->size(); ++b)
    bodies_->add_labelled_row(sim_.time(), bodies->names[b], body_row<D>(*bodies, int(b), mean[b]));
}

// Each profile is taken at the first step at or after its time, at points evenly spaced from `from` to `to` (both
// included, the spacing rounded to divide the segment).
template <int D>
void RunOutputs<D>::sample_profiles() {
  const auto& ps = scene_.profiles;
  while (profiles_ && next_profile_ < ps.times.size() && sim_.time() >= ps.times[next_profile_] - 1e-12) {
    const double length = std::hypot(ps.to[0] - ps.from[0], ps.to[1] - ps.from[1]);
    const long n = std::max(1L, std::lround(length / ps.spacing));
    for (long k = 0; k <= n; ++k) {
      const double x = ps.from[0] + (ps.to[0] - ps.from[0]) * k / n, y = ps.from[1] + (ps.to[1] - ps.from[1]) * k / n;
      if constexpr (D == 2) {
        profiles_->add_row({sim_.time(), x, free_surface_elevation<2>(sim_, Vec<2>(x, 0.0))});
      } else {
        profiles_->add_row({sim_.time(), x, y, free_surface_elevation<3>(sim_, Vec<3>(x, y, 0.0))});
      }
    }
    ++next_profile_;
  }
}

// Each deformable slide's front (the particle furthest along its front direction, and how far along that is), its
// largest thickness over columns of width 2 dp, and its particle count (coupling/slide_front.hpp).
template <int D>
void RunOutputs<D>::sample_slides() {
  if (!slide_front_) return;
  const double dp = sim_.options.dp;
  for (const auto& s : scene_.slides) {
    const SlideFrontOf<D> f = measure_slide_front(sim_.particles(), s.phase, s.front_direction, dp, 2.0 * dp);
    std::vector<double> row(f.front.begin(), f.front.end());
    for (const double v : {s.front_direction.dot(f.front), f.thickness_max, double(f.particles)}) row.push_back(v);
    slide_front_->add_labelled_row(sim_.time(), s.name, row);
  }
}

// Every slide's upper surface now, in columns of 2 dp (coupling/slide_front.hpp), and its front: the deformable slides'
// from their particles, then the rigid bodies': in 2-D from their outlines, in 3-D from their wall particles.
template <int D>
std::vector<std::pair<std::string, typename RunOutputs<D>::ModelSurface>> RunOutputs<D>::model_surfaces() const {
  std::vector<std::pair<std::string, ModelSurface>> out;
  const double dp = sim_.options.dp, width = 2.0 * dp;
  for (const auto& s : scene_.slides) {
    const SlideFrontOf<D> f = measure_slide_front(sim_.particles(), s.phase, Vec<D>(Vec<D>::Unit(0)), dp, width);
    out.push_back({s.name, {slide_upper_surface(sim_.particles(), s.phase, dp, width), f.front[0] + 0.5 * dp}});
  }
  if (const auto& bodies = sim_.bodies())
    for (std::size_t b = 0; b < bodies->size(); ++b) {
      if constexpr (D == 2) {
        const std::vector<Vec<2>> outline = bodies->outline_now(int(b));
        double front = -std::numeric_limits<double>::infinity();
        for (const auto& v : outline) front = std::max(front, v[0]);
        out.push_back({bodies->names[b], {polygon_upper_surface(outline, width), front}});
      } else {
        auto surface = body_upper_surface(sim_.particles(), int(b), dp, width);
        double front = -std::numeric_limits<double>::infinity();
        for (const auto& v : surface) front = std::max(front, v[0] + 0.5 * width);
        out.push_back({bodies->names[b], {std::move(surface), front}});
      }
    }
  return out;
}

// The slides' upper surfaces at the scene's outline times (the first step at or after each).
template <int D>
void RunOutputs<D>::sample_slide_outlines() {
  const auto& times = scene_.slide_outline_times;
  while (slide_outline_ && next_outline_ < times.size() && sim_.time() >= times[next_outline_] - 1e-12) {
    for (const auto& [name, m] : model_surfaces())
      for (const auto& p : m.surface)
        slide_outline_->add_labelled_row(sim_.time(), name, std::vector<double>(p.begin(), p.end()));
    ++next_outline_;
  }
}

// The first slide's (or, without deformable slides, the first body's) shape against the measured one at each measured
// time plus the offset (the first step at or after it; coupling/slide_shape_error.hpp).
template <int D>
void RunOutputs<D>::sample_slide_shapes() {
  if constexpr (D == 2) {  // 2-D scenes only so far
    if (!slide_shapes_) return;
    const auto& spec = *scene_.slide_shapes;
    const double front_at_start = upper_envelope(spec.shapes.front().points).back()[0];
    while (next_shape_ < spec.shapes.size() &&
           sim_.time() >= spec.shapes[next_shape_].time_measured + spec.time_offset - 1e-12) {
      const auto surfaces = model_surfaces();
      const auto& [name, m] = surfaces.front();
      const auto& shape = spec.shapes[next_shape_];
      const SlideShapeError e = slide_shape_error(shape.points, front_at_start, m.surface, m.front);
      const double row[] = {shape.time_measured, e.front_measured, e.front_model,        e.travel_measured,
                            e.front_error_percent, e.surface_rms_m, double(e.compared)};
      slide_shapes_->add_labelled_row(sim_.time(), name, row);
      ++next_shape_;
    }
  }
}

template <int D>
void RunOutputs<D>::flush() {
  if (slide_front_) slide_front_->flush();
  if (slide_outline_) slide_outline_->flush();
  if (slide_shapes_) slide_shapes_->flush();
  if (profiles_) profiles_->flush();
  if (bodies_) bodies_->flush();
  if (gauges_) gauges_->flush();
  if (front_) front_->flush();
  if (velocity_profile_) velocity_profile_->flush();
}

template <int D>
void RunOutputs<D>::write_initial() {
  write_snapshot(sim_.particles(), sim_.time(), sim_.step_count());
  sample();
  sample_bodies();
  sample_profiles();
  sample_slide_outlines();
  sample_slide_shapes();
  flush();
}

// after_step's conditions, each in the same words.
template <int D>
bool RunOutputs<D>::samples_due(double t) const {
  const auto& ps = scene_.profiles;
  const auto& outlines = scene_.slide_outline_times;
  bool shape_due = false;
  if (D == 2 && slide_shapes_) {  // 2-D scenes only so far (sample_slide_shapes)
    const auto& spec = *scene_.slide_shapes;
    shape_due = next_shape_ < spec.shapes.size() && t >= spec.shapes[next_shape_].time_measured + spec.time_offset - 1e-12;
  }
  return t >= next_sample_ - eps_ || (profiles_ && next_profile_ < ps.times.size() && t >= ps.times[next_profile_] - 1e-12) ||
         (slide_outline_ && next_outline_ < outlines.size() && t >= outlines[next_outline_] - 1e-12) || shape_due ||
         (bodies_ && t >= next_body_sample_ - eps_);
}

template <int D>
void RunOutputs<D>::after_step(Simulation<D>& sim, double) {
  const double t = sim.time();
  if (t >= next_sample_ - eps_) {
    sample();
    next_sample_ = next_after(next_sample_, scene_.output.gauge_interval, t);
  }
  sample_profiles();
  sample_slide_outlines();
  sample_slide_shapes();
  if (bodies_ && t >= next_body_sample_ - eps_) {
    sample_bodies();
    next_body_sample_ = next_after(next_body_sample_, scene_.body_sample_interval, t);
  }
  write_snapshot_if_due(sim.particles(), t, sim.step_count());
}

template <int D>
void RunOutputs<D>::write_snapshot_if_due(const Particles<D>& P, double t, long step) {
  if (t < next_snapshot_ - eps_) return;
  write_snapshot(P, t, step);
  flush();
  next_snapshot_ = next_after(next_snapshot_, scene_.output.snapshot_interval, t);
}

template <int D>
bool RunOutputs<D>::final_snapshot_due() const {
  const double interval = scene_.output.snapshot_interval;
  return snapshots_ && (snapshots_->count() == 0 || interval <= 0 || sim_.time() > next_snapshot_ - interval + eps_);
}

template <int D>
void RunOutputs<D>::write_final() {
  const double t = sim_.time();
  if (final_snapshot_due()) write_snapshot(sim_.particles(), t, sim_.step_count());
  if (t > last_sample_time_ + eps_) sample();
  if (bodies_ && t > last_body_sample_time_ + eps_) sample_bodies();
  flush();
  if (scene_.gauge_records && gauges_) write_gauge_records();
}

// gauge_records.csv: each measured gauge against the run's (tools/measures/gauge_records.hpp), from gauges.csv as
// written, so that a resumed run compares its whole record.
template <int D>
void RunOutputs<D>::write_gauge_records() const {
  const auto comparisons = compare_gauge_records(read_csv(gauges_->path()), *scene_.gauge_records);
  std::string text =
      "gauge,from,to,samples,rms,measured_height,rms_over_height,trough_time,trough,measured_trough_time,"
      "measured_trough,crest_time,crest,measured_crest_time,measured_crest\n";
  for (const auto& c : comparisons)
    text += fmt::format("{},{:.17g},{:.17g},{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},"
                        "{:.17g},{:.17g}\n",
                        c.gauge, c.from, c.to, c.samples, c.rms, c.measured_height, c.rms / c.measured_height,
                        c.trough.time, c.trough.elevation, c.measured_trough.time, c.measured_trough.elevation,
                        c.crest.time, c.crest.elevation, c.measured_crest.time, c.measured_crest.elevation);
  write_file_atomically(gauges_->path().parent_path() / "gauge_records.csv", text);
}

// Every table, in one fixed order (the checkpoint's), each whether or not this scene writes it.
template <int D>
template <class F>
void RunOutputs<D>::for_each_csv(F&& f) {
  for (auto* csv : {&gauges_, &front_, &velocity_profile_, &bodies_, &profiles_, &slide_front_, &slide_outline_,
                    &slide_shapes_})
    f(*csv);
}

template <int D>
void RunOutputs<D>::save_state(StateWriter& out) const {
  for (double t : {eps_, next_snapshot_, next_sample_, next_body_sample_, last_sample_time_, last_body_sample_time_})
    out.put(t);
  out.put<std::uint64_t>(next_profile_);
  out.put<std::uint64_t>(next_outline_);
  out.put<std::uint64_t>(next_shape_);
  const_cast<RunOutputs<D>*>(this)->for_each_csv([&](const std::optional<CsvWriter>& csv) {
    out.put(csv.has_value());
    if (csv) {
      out.put<std::uint64_t>(csv->text().size());
      out.put<std::uint64_t>(csv->row_count());
    }
  });
  out.put(snapshots_.has_value());
  if (snapshots_) {
    out.put<std::uint64_t>(snapshots_->entries().size());
    for (const auto& e : snapshots_->entries()) {
      out.put(e.time);
      out.put<std::int64_t>(e.step);
      out.put<std::uint64_t>(e.n);
    }
  }
}

template <int D>
void RunOutputs<D>::restore_state(StateReader& in) {
  for (double* t : {&eps_, &next_snapshot_, &next_sample_, &next_body_sample_, &last_sample_time_, &last_body_sample_time_})
    in.get(*t);
  next_profile_ = in.get<std::uint64_t>();
  next_outline_ = in.get<std::uint64_t>();
  next_shape_ = in.get<std::uint64_t>();
  for_each_csv([&](std::optional<CsvWriter>& csv) {
    if (in.get<bool>() != csv.has_value()) throw std::runtime_error("the checkpoint's outputs are not the scene's");
    if (!csv) return;
    const auto length = in.get<std::uint64_t>();
    csv->continue_from_file(length, in.get<std::uint64_t>());
  });
  if (in.get<bool>() != snapshots_.has_value()) throw std::runtime_error("the checkpoint's outputs are not the scene's");
  if (snapshots_) {
    std::vector<SnapshotWriter::Entry> entries(in.get<std::uint64_t>());
    for (auto& e : entries) {
      in.get(e.time);
      e.step = in.get<std::int64_t>();
      e.n = in.get<std::uint64_t>();
    }
    snapshots_->continue_series(std::move(entries));
  }
}

template struct IdOrdered<2>;
template struct IdOrdered<3>;
template SnapshotFormat snapshot_format(const cases::Scene<2>&);
template SnapshotFormat snapshot_format(const cases::Scene<3>&);
template class RunOutputs<2>;
template class RunOutputs<3>;

}  // namespace slide::tools
