#include "coupling/rigid_bodies.hpp"

#include <cmath>

#include "coupling/dry_face_pressure.hpp"
#include "fluid/collision.hpp"
#include "fluid/parallel.hpp"

namespace slide {

namespace {
double cross2(const Vec<2>& a, const Vec<2>& b) { return a[0] * b[1] - a[1] * b[0]; }
Vec<2> rotate(const Vec<2>& v, double c, double s) { return Vec<2>(c * v[0] - s * v[1], s * v[0] + c * v[1]); }
}  // namespace

int RigidBodies::add(const std::string& name, const rigid::BodySpec& spec, const BodyMotion& m, double body_density,
                     double placed_angle_rad) {
  const int b = world.add_body(spec);
  const auto centre = world.state(b).position;
  std::vector<Vec<2>> local;
  for (const auto& v : rigid::counter_clockwise(spec.outline)) local.emplace_back(v[0] - centre[0], v[1] - centre[1]);
  outline_.push_back(std::move(local));
  names.push_back(name);
  placed_angle.push_back(placed_angle_rad);
  motion.push_back(m);
  force.emplace_back();
  pending_.emplace_back();
  impulse_.emplace_back();
  density.push_back(body_density);
  if (m.mode == BodyMotion::Mode::free && m.release_time > 0.0) world.set_held(b, true);
  return b;
}

void RigidBodies::place_particles(Particles<2>& P, double time) {
  for (std::size_t b = 0; b < size(); ++b)
    if (motion[b].mode == BodyMotion::Mode::prescribed)
      world.set_kinematic_state(int(b), motion[b].prescribed->at(settling_ ? 0.0 : time));
  std::vector<rigid::PlanarState> s(size());
  std::vector<double> c(size()), sn(size());
  std::vector<Vec<2>> linear_acceleration(size(), Vec<2>::Zero());
  std::vector<double> angular_acceleration(size(), 0.0);
  const bool have_previous = placed_state_.size() == size() && time > placed_time_;
  for (std::size_t b = 0; b < size(); ++b) {
    s[b] = world.state(int(b));
    c[b] = std::cos(s[b].angle);
    sn[b] = std::sin(s[b].angle);
    if (have_previous) {
      const double span = time - placed_time_;
      const auto& before = placed_state_[b];
      linear_acceleration[b] = Vec<2>(s[b].velocity[0] - before.velocity[0], s[b].velocity[1] - before.velocity[1]) / span;
      angular_acceleration[b] = (s[b].angular_velocity - before.angular_velocity) / span;
    }
  }
  placed_state_ = s;
  placed_time_ = time;
  parallel_for(P.size(), [&](std::size_t i) {
    const int f = P.body_frame[i];
    if (f < 0) return;
    const int b = P.body_frames.body[f];
    const Vec<2> r = rotate(P.body_frames.offset[f], c[b], sn[b]);
    const auto& st = s[b];
    const double omega = st.angular_velocity;
    P.position[i] = Vec<2>(st.position[0], st.position[1]) + r;
    // v = V + omega x r, in 2-D omega x r = omega (-r_y, r_x).
    P.velocity[i] = Vec<2>(st.velocity[0], st.velocity[1]) + omega * Vec<2>(-r[1], r[0]);
    // a = A + alpha x r + omega x (omega x r) = A + alpha (-r_y, r_x) - omega^2 r.
    P.acceleration[i] = linear_acceleration[b] + angular_acceleration[b] * Vec<2>(-r[1], r[0]) - (omega * omega) * r;
    P.wall_normal[i] = rotate(P.body_frames.normal[f], c[b], sn[b]);
  });
}

// Sums per-particle forces into their bodies in index order (deterministic for any thread count), with torques
// about each body's centre of mass.
void RigidBodies::accumulate(const Domain<2>& domain, const std::vector<Vec<2>>& f, bool viscous) {
  const Particles<2>& P = domain.particles;
  std::vector<Vec<2>> centre(size());
  for (std::size_t b = 0; b < size(); ++b) {
    const rigid::Vec2 c = world.state(int(b)).position;
    centre[b] = Vec<2>(c[0], c[1]);
  }
  domain.sum_by_group(
      pending_, [&](std::size_t i) { return P.body_of(i); },
      [&](BodyFluidForce& acc, std::size_t i) {
        const Vec<2> arm = P.position[i] - centre[static_cast<std::size_t>(P.body_of(i))];
        if (viscous) {
          acc.viscous += f[i];
          acc.viscous_torque += cross2(arm, f[i]);
        } else {
          acc.pressure += f[i];
          acc.pressure_torque += cross2(arm, f[i]);
        }
      });
}

// For every body particle j, the sum over its fluid neighbours i of pair_force(i, j) (the force fluid i exerts on
// the body through j), then summed per body (Domain::sum_by_group).
template <class PairForce>
void RigidBodies::exchange(const Domain<2>& domain, const NeighborList& nl, bool viscous,
                           const PairForce& pair_force) {
  const Particles<2>& P = domain.particles;
  scratch_.assign(P.size(), Vec<2>::Zero());
  parallel_for(domain.owned_count(), [&](std::size_t j) {
    if (P.body_frame[j] < 0) return;
    Vec<2> f = Vec<2>::Zero();
    for (const std::uint32_t* q = nl.begin(j); q != nl.end(j); ++q)
      if (P.kind[*q] == Kind::fluid) f += pair_force(*q, static_cast<std::uint32_t>(j));
    scratch_[j] = f;
  });
  accumulate(domain, scratch_, viscous);
}

// Viscous force of body particle j on fluid i: m_i scale_i term_ij; the body gets minus it.
void RigidBodies::add_viscous_forces(const Domain<2>& domain, const NeighborList& nl, double re, double n0,
                                     double lambda, const ViscousWall& wall, double volume) {
  const Particles<2>& P = domain.particles;
  const double re2 = re * re;
  exchange(domain, nl, true, [&](std::uint32_t i, std::uint32_t j) -> Vec<2> {
    const double r2 = distance_squared<2>(P.position[j], P.position[i]);
    if (r2 >= re2) return Vec<2>::Zero();
    const double mass = P.density[i] * volume;
    return -(mass * viscous_scale<2>(i, P, n0, lambda)) * viscous_pair_term<2>(i, j, r2, P, re, wall);
  });
}

// Pressure force of body particle j on fluid i: -V_i grad_pair p_i (V_i = m_i / rho_i); the body gets plus it.
void RigidBodies::add_pressure_forces(const Domain<2>& domain, const NeighborList& nl, GradientModel model, double re,
                                      double n0, double kappa, double volume) {
  const Particles<2>& P = domain.particles;
  exchange(domain, nl, false, [&](std::uint32_t i, std::uint32_t j) -> Vec<2> {
    const double mass = P.density[i] * volume;
    return (mass / P.density[i]) * pressure_gradient_pair<2>(model, i, j, P, nl, re, n0, kappa);
  });
}

// Collision of fluid i with body particle j changes u_i by du_ij: the body receives the impulse -m_i du_ij.
void RigidBodies::add_collision_forces(const Domain<2>& domain, const NeighborList& nl, double distance,
                                       double restitution, double volume, double dt) {
  const Particles<2>& P = domain.particles;
  exchange(domain, nl, false, [&](std::uint32_t i, std::uint32_t j) -> Vec<2> {
    const double mass = P.density[i] * volume;
    return -(mass / dt) * collision_pair_change<2>(i, j, P, distance, restitution);
  });
}

std::vector<Vec<2>> RigidBodies::outline_now(int b) const {
  const auto st = world.state(b);
  const double c = std::cos(st.angle), sn = std::sin(st.angle);
  std::vector<Vec<2>> outline;
  for (const auto& v : outline_[static_cast<std::size_t>(b)])
    outline.push_back(Vec<2>(st.position[0], st.position[1]) + rotate(v, c, sn));
  return outline;
}

void RigidBodies::add_dry_face_pressure(const Particles<2>& P, const NeighborGrid<2>& grid,
                                        const PorePressureField<2>& pore, double dp) {
  if (!pore.surface) return;
  for (std::size_t b = 0; b < size(); ++b) {
    const auto st = world.state(int(b));
    const ForceAndTorque f =
        dry_face_pressure(outline_now(int(b)), int(b), Vec<2>(st.position[0], st.position[1]), P, grid, pore, dp);
    pending_[b].pressure += f.force;
    pending_[b].pressure_torque += f.torque;
  }
}

void RigidBodies::set_settling(bool on) {
  settling_ = on;
  for (std::size_t b = 0; b < size(); ++b) {
    const auto& m = motion[b];
    if (m.mode != BodyMotion::Mode::free) continue;
    world.set_held(int(b), on ? !m.free_while_settling : m.release_time > 0.0);
    if (!on) world.set_velocity(int(b), rigid::Vec2::Zero(), 0.0);
  }
  placed_state_.clear();
}

void RigidBodies::damp_floating(double factor) {
  for (std::size_t b = 0; b < size(); ++b) {
    if (motion[b].mode != BodyMotion::Mode::free || !motion[b].free_while_settling) continue;
    const auto s = world.state(int(b));
    world.set_velocity(int(b), factor * s.velocity, factor * s.angular_velocity);
  }
}

void RigidBodies::advance(double time_after, double dt) {
  for (std::size_t b = 0; b < size(); ++b) {
    const auto& f = pending_[b];
    if (motion[b].mode == BodyMotion::Mode::free) {
      if (!settling_ && time_after > motion[b].release_time) world.set_held(int(b), false);
      world.apply_force(int(b), rigid::Vec2(f.total()[0], f.total()[1]), f.total_torque());
    }
    force[b] = f;
    pending_[b] = BodyFluidForce{};
  }
  world.step(dt);
  for (std::size_t b = 0; b < size(); ++b) {
    auto& m = impulse_[b];
    const auto& f = force[b];
    m.fluid.pressure += dt * f.pressure;
    m.fluid.viscous += dt * f.viscous;
    m.fluid.pressure_torque += dt * f.pressure_torque;
    m.fluid.viscous_torque += dt * f.viscous_torque;
    const auto c = world.contact_force(int(b));
    m.contact += dt * Vec<2>(c[0], c[1]);
  }
  impulse_time_ += dt;
}

std::vector<RigidBodies::MeanForces> RigidBodies::take_mean_forces() {
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
  s.io(p.position[0]);
  s.io(p.position[1]);
  s.io(p.angle);
  s.io(p.velocity[0]);
  s.io(p.velocity[1]);
  s.io(p.angular_velocity);
}
}  // namespace

void RigidBodies::save_state(StateWriter& out) const {
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

void RigidBodies::restore_state(StateReader& in) {
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

}  // namespace slide
