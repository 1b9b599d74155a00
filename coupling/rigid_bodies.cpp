#include "coupling/rigid_bodies.hpp"

#include <cmath>

#include "coupling/dry_face_pressure.hpp"
#include "fluid/collision.hpp"
#include "fluid/parallel.hpp"

namespace slide {

namespace {
Vec<2> rotate(const Vec<2>& v, double c, double s) { return Vec<2>(c * v[0] - s * v[1], s * v[0] + c * v[1]); }

// A body's rigid motion at one placement: where a point at offset r0 (body frame, as created) is, how fast it goes
// and how it accelerates, given the body's state and its mean linear and angular accelerations since the last one.
template <int D>
struct RigidField;

template <>
struct RigidField<2> {
  rigid::PlanarState s;
  double c = 1.0, sn = 0.0;
  Vec<2> linear_acceleration = Vec<2>::Zero();
  double angular_acceleration = 0.0;
  RigidField() = default;
  RigidField(const rigid::PlanarState& now, const rigid::PlanarState* before, double span)
      : s(now), c(std::cos(now.angle)), sn(std::sin(now.angle)) {
    if (!before) return;
    linear_acceleration = Vec<2>(s.velocity[0] - before->velocity[0], s.velocity[1] - before->velocity[1]) / span;
    angular_acceleration = (s.angular_velocity - before->angular_velocity) / span;
  }
  Vec<2> turned(const Vec<2>& v) const { return rotate(v, c, sn); }
  // x = X + r, v = V + omega x r (in 2-D omega (-r_y, r_x)), a = A + alpha x r - omega^2 r.
  void place(const Vec<2>& r0, Vec<2>& x, Vec<2>& v, Vec<2>& a) const {
    const Vec<2> r = turned(r0);
    const double omega = s.angular_velocity;
    x = Vec<2>(s.position[0], s.position[1]) + r;
    v = Vec<2>(s.velocity[0], s.velocity[1]) + omega * Vec<2>(-r[1], r[0]);
    a = linear_acceleration + angular_acceleration * Vec<2>(-r[1], r[0]) - (omega * omega) * r;
  }
};

template <>
struct RigidField<3> {
  rigid::SpatialState s;
  Mat<3> R = Mat<3>::Identity();
  Vec<3> linear_acceleration = Vec<3>::Zero(), angular_acceleration = Vec<3>::Zero();
  RigidField() = default;
  RigidField(const rigid::SpatialState& now, const rigid::SpatialState* before, double span)
      : s(now), R(now.orientation.toRotationMatrix()) {
    if (!before) return;
    linear_acceleration = (s.velocity - before->velocity) / span;
    angular_acceleration = (s.angular_velocity - before->angular_velocity) / span;
  }
  Vec<3> turned(const Vec<3>& v) const { return R * v; }
  // x = X + R r0, v = V + omega x r, a = A + alpha x r + omega x (omega x r).
  void place(const Vec<3>& r0, Vec<3>& x, Vec<3>& v, Vec<3>& a) const {
    const Vec<3> r = turned(r0);
    const Vec<3> w = s.angular_velocity;
    x = s.position + r;
    v = s.velocity + w.cross(r);
    a = linear_acceleration + angular_acceleration.cross(r) + w.cross(Vec<3>(w.cross(r)));
  }
};

template <int D>
Vec<D> centre_of(const BodyState<D>& s) {
  if constexpr (D == 2) return Vec<2>(s.position[0], s.position[1]);
  else return s.position;
}
}  // namespace

template <int D>
int RigidBodies<D>::add(const std::string& name, const BodySpecOf<D>& spec, const BodyMotion& m, double body_density,
                        const Placement<D>& placed_at) {
  int b = 0;
  if constexpr (D == 2) {
    b = world.add_body(spec);
    const auto centre = world.state(b).position;
    std::vector<Vec<2>> local;
    for (const auto& v : rigid::counter_clockwise(spec.outline)) local.emplace_back(v[0] - centre[0], v[1] - centre[1]);
    outline_.push_back(std::move(local));
  } else {
    b = world.add_solid(spec);
  }
  names.push_back(name);
  placed.push_back(placed_at);
  motion.push_back(m);
  force.emplace_back();
  pending_.emplace_back();
  impulse_.emplace_back();
  density.push_back(body_density);
  if (m.mode == BodyMotion::Mode::free && m.release_time > 0.0) world.set_held(b, true);
  return b;
}

template <int D>
void RigidBodies<D>::place_particles(Particles<D>& P, double time) {
  for (std::size_t b = 0; b < size(); ++b) {
    if (motion[b].mode != BodyMotion::Mode::prescribed) continue;
    const double t = settling_ ? 0.0 : time;
    if constexpr (D == 2)
      world.set_kinematic_state(int(b), motion[b].prescribed->at(t));
    else
      world.set_kinematic_state(int(b), motion[b].prescribed_3d->at(t));
  }
  std::vector<BodyState<D>> s(size());
  std::vector<RigidField<D>> field(size());
  const bool have_previous = placed_state_.size() == size() && time > placed_time_;
  for (std::size_t b = 0; b < size(); ++b) {
    s[b] = state(int(b));
    field[b] = RigidField<D>(s[b], have_previous ? &placed_state_[b] : nullptr, time - placed_time_);
  }
  placed_state_ = s;
  placed_time_ = time;
  // The owned particles; their ghosts take their images from the domain (Simulation::move_bodies).
  parallel_for(P.real_count(), [&](std::size_t i) {
    const int f = P.body_frame[i];
    if (f < 0) return;
    const auto& rf = field[static_cast<std::size_t>(P.body_frames.body[f])];
    rf.place(P.body_frames.offset[f], P.position[i], P.velocity[i], P.acceleration[i]);
    P.wall_normal[i] = rf.turned(P.body_frames.normal[f]);
  });
}

// Sums per-particle forces into their bodies in index order (deterministic for any thread count), with torques
// about each body's centre of mass.
template <int D>
void RigidBodies<D>::accumulate(const Domain<D>& domain, const std::vector<Vec<D>>& f, bool viscous) {
  const Particles<D>& P = domain.particles;
  std::vector<Vec<D>> centre(size());
  for (std::size_t b = 0; b < size(); ++b) centre[b] = centre_of<D>(state(int(b)));
  // Per body: the force's D components, then the torque's T (1 in 2-D, 3 in 3-D), each summed exactly.
  constexpr std::size_t T = D == 2 ? 1 : 3;
  using Values = std::array<double, D + T>;
  const auto sums = domain.template sum_by_group<D + T>(
      size(), [&](std::size_t i) { return P.body_of(i); },
      [&](std::size_t i) {
        const Vec<D> arm = P.position[i] - centre[static_cast<std::size_t>(P.body_of(i))];
        const Torque<D> t = torque_of(arm, f[i]);
        Values v;
        for (int k = 0; k < D; ++k) v[k] = f[i][k];
        if constexpr (D == 2) v[D] = t;
        else
          for (int k = 0; k < 3; ++k) v[D + k] = t[k];
        return v;
      });
  for (std::size_t b = 0; b < size(); ++b) {
    Vec<D> force;
    Torque<D> torque = zero_torque<D>();
    for (int k = 0; k < D; ++k) force[k] = sums[b][k];
    if constexpr (D == 2) torque = sums[b][D];
    else
      for (int k = 0; k < 3; ++k) torque[k] = sums[b][D + k];
    BodyFluidForce<D>& acc = pending_[b];
    (viscous ? acc.viscous : acc.pressure) += force;
    (viscous ? acc.viscous_torque : acc.pressure_torque) += torque;
  }
}

// For every body particle j, the sum over its fluid neighbours i of pair_force(i, j) (the force fluid i exerts on
// the body through j), then summed per body (Domain::sum_by_group).
template <int D>
template <class PairForce>
void RigidBodies<D>::exchange(const Domain<D>& domain, const NeighborList& nl, bool viscous,
                              const PairForce& pair_force) {
  const Particles<D>& P = domain.particles;
  scratch_.assign(P.size(), Vec<D>::Zero());
  parallel_for(domain.owned_count(), [&](std::size_t j) {
    if (P.body_frame[j] < 0) return;
    Vec<D> f = Vec<D>::Zero();
    for (const std::uint32_t* q = nl.begin(j); q != nl.end(j); ++q)
      if (P.kind[*q] == Kind::fluid) f += pair_force(*q, static_cast<std::uint32_t>(j));
    scratch_[j] = f;
  });
  accumulate(domain, scratch_, viscous);
}

// Viscous force of body particle j on fluid i: m_i scale_i term_ij; the body gets minus it.
template <int D>
void RigidBodies<D>::add_viscous_forces(const Domain<D>& domain, const NeighborList& nl, double re, double n0,
                                        double lambda, const ViscousWall& wall, double volume) {
  const Particles<D>& P = domain.particles;
  const double re2 = re * re;
  exchange(domain, nl, true, [&](std::uint32_t i, std::uint32_t j) -> Vec<D> {
    const double r2 = distance_squared<D>(P.position[j], P.position[i]);
    if (r2 >= re2) return Vec<D>::Zero();
    const double mass = P.density[i] * volume;
    return -(mass * viscous_scale<D>(i, P, n0, lambda)) * viscous_pair_term<D>(i, j, r2, P, re, wall);
  });
}

// Pressure force of body particle j on fluid i: -V_i grad_pair p_i (V_i = m_i / rho_i); the body gets plus it.
template <int D>
void RigidBodies<D>::add_pressure_forces(const Domain<D>& domain, const NeighborList& nl, GradientModel model,
                                         double re, double n0, double kappa, double volume) {
  const Particles<D>& P = domain.particles;
  exchange(domain, nl, false, [&](std::uint32_t i, std::uint32_t j) -> Vec<D> {
    const double mass = P.density[i] * volume;
    return (mass / P.density[i]) * pressure_gradient_pair<D>(model, i, j, P, nl, re, n0, kappa);
  });
}

// Collision of fluid i with body particle j changes u_i by du_ij: the body receives the impulse -m_i du_ij.
template <int D>
void RigidBodies<D>::add_collision_forces(const Domain<D>& domain, const NeighborList& nl, double distance,
                                          double restitution, double volume, double dt) {
  const Particles<D>& P = domain.particles;
  exchange(domain, nl, false, [&](std::uint32_t i, std::uint32_t j) -> Vec<D> {
    const double mass = P.density[i] * volume;
    return -(mass / dt) * collision_pair_change<D>(i, j, P, distance, restitution);
  });
}

template <int D>
std::vector<Vec<2>> RigidBodies<D>::outline_now(int b) const requires(D == 2) {
  const auto st = world.state(b);
  const double c = std::cos(st.angle), sn = std::sin(st.angle);
  std::vector<Vec<2>> outline;
  for (const auto& v : outline_[static_cast<std::size_t>(b)])
    outline.push_back(Vec<2>(st.position[0], st.position[1]) + rotate(v, c, sn));
  return outline;
}

template <int D>
void RigidBodies<D>::add_dry_face_pressure(const Domain<D>& domain, const NeighborGrid<D>& grid,
                                           const PorePressureField<D>& pore, double dp) {
  if constexpr (D == 2) {
    if (!pore.surface) return;
    std::vector<std::array<ExactSum, 3>> sums(size());
    const auto mine = [&](const Vec<2>& x) { return domain.owns_point(x, grid); };
    for (std::size_t b = 0; b < size(); ++b) {
      const auto st = world.state(int(b));
      add_dry_face_samples(outline_now(int(b)), int(b), Vec<2>(st.position[0], st.position[1]), domain.particles, grid,
                           pore, dp, mine, sums[b]);
    }
    domain.combine(sums.empty() ? nullptr : sums.front().data(), 3 * sums.size());
    for (std::size_t b = 0; b < size(); ++b) {
      pending_[b].pressure += Vec<2>(sums[b][0].value(), sums[b][1].value());
      pending_[b].pressure_torque += sums[b][2].value();
    }
  }
}

template <int D>
void RigidBodies<D>::set_settling(bool on) {
  settling_ = on;
  for (std::size_t b = 0; b < size(); ++b) {
    const auto& m = motion[b];
    if (m.mode != BodyMotion::Mode::free) continue;
    world.set_held(int(b), on ? !m.free_while_settling : m.release_time > 0.0);
    if (on) continue;
    if constexpr (D == 2) world.set_velocity(int(b), rigid::Vec2::Zero(), 0.0);
    else world.set_velocity(int(b), rigid::Vec3::Zero(), rigid::Vec3::Zero());
  }
  placed_state_.clear();
}

template <int D>
void RigidBodies<D>::damp_floating(double factor) {
  for (std::size_t b = 0; b < size(); ++b) {
    if (motion[b].mode != BodyMotion::Mode::free || !motion[b].free_while_settling) continue;
    const auto s = state(int(b));
    if constexpr (D == 2) world.set_velocity(int(b), factor * s.velocity, factor * s.angular_velocity);
    else world.set_velocity(int(b), rigid::Vec3(factor * s.velocity), rigid::Vec3(factor * s.angular_velocity));
  }
}

template <int D>
void RigidBodies<D>::advance(double time_after, double dt) {
  for (std::size_t b = 0; b < size(); ++b) {
    const auto& f = pending_[b];
    if (motion[b].mode == BodyMotion::Mode::free) {
      if (!settling_ && time_after > motion[b].release_time) world.set_held(int(b), false);
      world.apply_force(int(b), world_vector(f.total()), f.total_torque());
    } else if (motion[b].mode == BodyMotion::Mode::rail && !settling_ && time_after > motion[b].release_time) {
      move_on_rail(int(b), f.total(), dt);
    }
    force[b] = f;
    pending_[b] = BodyFluidForce<D>{};
  }
  world.step(dt);
  for (std::size_t b = 0; b < size(); ++b) {
    auto& m = impulse_[b];
    const auto& f = force[b];
    m.fluid.pressure += dt * f.pressure;
    m.fluid.viscous += dt * f.viscous;
    m.fluid.pressure_torque += dt * f.pressure_torque;
    m.fluid.viscous_torque += dt * f.viscous_torque;
    if constexpr (D == 2) {
      const auto c = world.contact_force(int(b));
      m.contact += dt * Vec<2>(c[0], c[1]);
    } else {
      m.contact += dt * Vec<3>(world.contact_force_3d(int(b)));
    }
  }
  impulse_time_ += dt;
}

template <int D>
void RigidBodies<D>::move_on_rail(int b, const Vec<D>& fluid_force, double dt) {
  if constexpr (D == 3) {
    const rigid::Rail& rail = *motion[static_cast<std::size_t>(b)].rail;
    const Vec<3> d(rail.direction[0], rail.direction[1], rail.direction[2]);
    const double mass = world.mass(b);
    const Vec<3> force = fluid_force + mass * gravity_;
    const double along = force.dot(d);
    rigid::SpatialState s = world.spatial_state(b);
    const double speed = rigid::rail_speed_after(Vec<3>(s.velocity).dot(d), along, (force - along * d).norm(), mass,
                                                 rail.friction, dt);
    s.position += rigid::Vec3(dt * speed * d);
    s.velocity = rigid::Vec3(speed * d);
    s.angular_velocity = rigid::Vec3::Zero();
    world.set_kinematic_state(b, s);
  } else {  // the same in the plane: mass and forces per unit width
    const rigid::Rail& rail = *motion[static_cast<std::size_t>(b)].rail;
    const Vec<2> d(rail.direction[0], rail.direction[1]);
    const double mass = world.mass(b);
    const Vec<2> force = fluid_force + mass * gravity_;
    const double along = force.dot(d);
    rigid::PlanarState s = world.state(b);
    const double speed =
        rigid::rail_speed_after(Vec<2>(s.velocity).dot(d), along, (force - along * d).norm(), mass, rail.friction, dt);
    s.position += rigid::Vec2(dt * speed * d);
    s.velocity = rigid::Vec2(speed * d);
    s.angular_velocity = 0.0;
    world.set_kinematic_state(b, s);
  }
}

template <int D>
std::vector<typename RigidBodies<D>::MeanForces> RigidBodies<D>::take_mean_forces() {
  std::vector<MeanForces> out(size());
  if (impulse_time_ > 0.0) {
    const double inv = 1.0 / impulse_time_;
    for (std::size_t b = 0; b < size(); ++b) {
      const auto& m = impulse_[b];
      out[b].fluid.pressure = inv * m.fluid.pressure;
      out[b].fluid.viscous = inv * m.fluid.viscous;
      out[b].fluid.pressure_torque = inv * m.fluid.pressure_torque;
      out[b].fluid.viscous_torque = inv * m.fluid.viscous_torque;
      out[b].contact = inv * m.contact;
    }
  }
  impulse_.assign(size(), MeanForces{});
  impulse_time_ = 0.0;
  return out;
}

namespace {
// The fields of a force and of a pose, in checkpoint order, for StateWriter (const) and StateReader alike.
template <class Stream, class Force>
void transfer_force(Stream& s, Force& f) {
  s.io(f.pressure);
  s.io(f.viscous);
  s.io(f.pressure_torque);
  s.io(f.viscous_torque);
}
template <class Stream, class Pose>
void transfer_pose(Stream& s, Pose& p) {
  if constexpr (std::is_same_v<std::remove_const_t<Pose>, rigid::PlanarState>) {
    s.io(p.position[0]);
    s.io(p.position[1]);
    s.io(p.angle);
    s.io(p.velocity[0]);
    s.io(p.velocity[1]);
    s.io(p.angular_velocity);
  } else {
    for (int k = 0; k < 3; ++k) s.io(p.position[k]);
    s.io(p.orientation.w());
    s.io(p.orientation.x());
    s.io(p.orientation.y());
    s.io(p.orientation.z());
    for (int k = 0; k < 3; ++k) s.io(p.velocity[k]);
    for (int k = 0; k < 3; ++k) s.io(p.angular_velocity[k]);
  }
}
}  // namespace

template <int D>
void RigidBodies<D>::save_state(StateWriter& out) const {
  out.put(world.journal());
  out.put<std::uint64_t>(size());
  for (std::size_t b = 0; b < size(); ++b) {
    transfer_force(out, force[b]);
    transfer_force(out, pending_[b]);
    transfer_force(out, impulse_[b].fluid);
    out.put(impulse_[b].contact);
  }
  out.put(impulse_time_);
  out.put<std::uint64_t>(placed_state_.size());
  for (const auto& s : placed_state_) transfer_pose(out, s);
  out.put(placed_time_);
  out.put(settling_);
}

template <int D>
void RigidBodies<D>::restore_state(StateReader& in) {
  std::vector<double> journal;
  in.get(journal);
  world.replay(journal);
  if (in.get<std::uint64_t>() != size() || world.size() != size())
    throw std::runtime_error("the checkpoint's bodies are not the scene's");
  for (std::size_t b = 0; b < size(); ++b) {
    transfer_force(in, force[b]);
    transfer_force(in, pending_[b]);
    transfer_force(in, impulse_[b].fluid);
    in.get(impulse_[b].contact);
  }
  in.get(impulse_time_);
  placed_state_.resize(in.get<std::uint64_t>());
  for (auto& s : placed_state_) transfer_pose(in, s);
  in.get(placed_time_);
  in.get(settling_);
}

template class RigidBodies<2>;
template class RigidBodies<3>;

}  // namespace slide
