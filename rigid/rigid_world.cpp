#include "rigid/rigid_world.hpp"

#include <btBulletDynamicsCommon.h>

#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <vector>

namespace slide::rigid {

static_assert(sizeof(btScalar) == 8, "Bullet must be compiled and used in double precision (BT_USE_DOUBLE_PRECISION)");

namespace {
btVector3 v3(const Vec2& v) { return btVector3(v[0], v[1], 0.0); }

// The rotation about z from a quaternion that has only a z component (planar motion).
double z_angle(const btQuaternion& q) { return 2.0 * std::atan2(q.z(), q.w()); }
}  // namespace

// The calls a journal records.
enum class Op { add_body = 1, add_static_segment, set_held, set_kinematic_state, translate, set_velocity, apply_force, step };

namespace {
// Bullet's default pools hold 4096 contact manifolds and 4096 collision algorithms: 8 MB resident for every scene
// with a body (measured: a Heinrich wedge's peak 33 MB against 25 MB without them), where a slide's bodies touch a
// few wall segments at once. A pool that runs out takes from the heap, so small ones only cost memory where more
// contacts are live.
btDefaultCollisionConstructionInfo small_pools() {
  btDefaultCollisionConstructionInfo info;
  info.m_defaultMaxPersistentManifoldPoolSize = 64;
  info.m_defaultMaxCollisionAlgorithmPoolSize = 64;
  return info;
}
}  // namespace

struct RigidWorld::Impl {
  btDefaultCollisionConfiguration configuration{small_pools()};
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  double margin;
  Vec2 gravity;

  struct Body {
    std::unique_ptr<btConvexHullShape> shape;
    std::unique_ptr<btDefaultMotionState> motion;
    std::unique_ptr<btRigidBody> rigid;
    BodySpec spec;
    bool held = false;
    double angle = 0.0;  // continuous angle
    Vec2 velocity_before = Vec2::Zero();
    Vec2 force = Vec2::Zero();         // applied during the current step
    Vec2 applied_last = Vec2::Zero();  // applied during the last step
    Vec2 contact = Vec2::Zero();
    btVector3 linear_factor, angular_factor;
    PlanarState kinematic_state;  // kinematic bodies: as last set
  };
  std::vector<Body> bodies;
  // Every call that changed the world, in order, with its arguments (RigidWorld::journal).
  std::vector<double> journal;
  void record(Op op, std::initializer_list<double> args) {
    journal.push_back(static_cast<double>(op));
    journal.insert(journal.end(), args);
  }
  std::vector<std::unique_ptr<btBoxShape>> ground_shapes;
  std::vector<std::unique_ptr<btRigidBody>> ground;

  Impl(const Vec2& g, double m) : margin(m), gravity(g) { world.setGravity(v3(g)); }
  ~Impl() {
    for (auto& b : bodies) world.removeRigidBody(b.rigid.get());
    for (auto& g : ground) world.removeRigidBody(g.get());
  }
};

RigidWorld::RigidWorld(const Vec2& gravity, double margin) : impl_(std::make_unique<Impl>(gravity, margin)) {
  if (!(margin > 0.0)) throw std::invalid_argument("collision margin must be positive");
}
RigidWorld::~RigidWorld() = default;

int RigidWorld::add_body(const BodySpec& spec_in) {
  impl_->record(Op::add_body, {double(spec_in.kinematic), double(spec_in.locked[0]), double(spec_in.locked[1]),
                               double(spec_in.locked[2]), spec_in.mass, spec_in.inertia, spec_in.friction,
                               spec_in.restitution, double(spec_in.outline.size())});
  for (const Vec2& p : spec_in.outline) impl_->journal.insert(impl_->journal.end(), {p[0], p[1]});
  BodySpec spec = spec_in;
  spec.outline = counter_clockwise(spec.outline);
  if (!is_convex_ccw(spec.outline)) throw std::invalid_argument("a body's outline must be a convex polygon");
  if (!spec.kinematic && !(spec.mass > 0.0 && spec.inertia > 0.0))
    throw std::invalid_argument("a body needs a positive mass and inertia");
  Impl::Body b;
  b.spec = spec;
  const Vec2 c = centroid(spec.outline);
  b.shape = std::make_unique<btConvexHullShape>();
  for (const Vec2& p : inset(spec.outline, impl_->margin)) {
    b.shape->addPoint(btVector3(p[0] - c[0], p[1] - c[1], -0.5), false);
    b.shape->addPoint(btVector3(p[0] - c[0], p[1] - c[1], 0.5), false);
  }
  b.shape->recalcLocalAabb();
  b.shape->setMargin(impl_->margin);
  btTransform start;
  start.setIdentity();
  start.setOrigin(btVector3(c[0], c[1], 0.0));
  b.motion = std::make_unique<btDefaultMotionState>(start);
  const double mass = spec.kinematic ? 0.0 : spec.mass;
  // Inertia about x and y is irrelevant under the planar constraint but must be positive.
  const btVector3 inertia(spec.inertia, spec.inertia, spec.inertia);
  btRigidBody::btRigidBodyConstructionInfo info(mass, b.motion.get(), b.shape.get(),
                                                spec.kinematic ? btVector3(0, 0, 0) : inertia);
  info.m_friction = spec.friction;
  info.m_restitution = spec.restitution;
  info.m_linearDamping = 0.0;
  info.m_angularDamping = 0.0;
  b.rigid = std::make_unique<btRigidBody>(info);
  b.rigid->setActivationState(DISABLE_DEACTIVATION);  // a slide at rest must wake when released
  if (spec.kinematic) b.rigid->setCollisionFlags(b.rigid->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
  b.linear_factor = btVector3(spec.locked[0] ? 0 : 1, spec.locked[1] ? 0 : 1, 0);
  b.angular_factor = btVector3(0, 0, spec.locked[2] ? 0 : 1);
  b.rigid->setLinearFactor(b.linear_factor);
  b.rigid->setAngularFactor(b.angular_factor);
  b.kinematic_state.position = c;
  impl_->world.addRigidBody(b.rigid.get());
  impl_->bodies.push_back(std::move(b));
  return static_cast<int>(impl_->bodies.size() - 1);
}

void RigidWorld::add_static_segment(const Vec2& a, const Vec2& b, const Vec2& into_solid, double thickness,
                                    double friction, double restitution) {
  impl_->record(Op::add_static_segment,
                {a[0], a[1], b[0], b[1], into_solid[0], into_solid[1], thickness, friction, restitution});
  const Vec2 d = b - a;
  const double len = d.norm();
  if (len <= 0.0) throw std::invalid_argument("static segment of zero length");
  // A box whose face lies on the segment, extended by its thickness at both ends so that corners are closed.
  auto shape = std::make_unique<btBoxShape>(btVector3(0.5 * len + thickness, 0.5 * thickness, 1.0));
  shape->setMargin(std::min(impl_->margin, 0.25 * thickness));
  const Vec2 t = d / len;
  const Vec2 centre = 0.5 * (a + b) + (0.5 * thickness) * into_solid;
  btTransform tr;
  tr.setIdentity();
  tr.setOrigin(btVector3(centre[0], centre[1], 0.0));
  tr.setRotation(btQuaternion(btVector3(0, 0, 1), std::atan2(t[1], t[0])));
  btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr, shape.get());
  info.m_startWorldTransform = tr;
  info.m_friction = friction;
  info.m_restitution = restitution;
  auto body = std::make_unique<btRigidBody>(info);
  impl_->world.addRigidBody(body.get());
  impl_->ground_shapes.push_back(std::move(shape));
  impl_->ground.push_back(std::move(body));
}

std::size_t RigidWorld::size() const { return impl_->bodies.size(); }

PlanarState RigidWorld::state(int i) const {
  const auto& b = impl_->bodies.at(i);
  if (b.spec.kinematic) return b.kinematic_state;
  const btTransform& tr = b.rigid->getWorldTransform();
  PlanarState s;
  s.position = Vec2(tr.getOrigin().x(), tr.getOrigin().y());
  s.angle = b.angle;
  const btVector3 v = b.rigid->getLinearVelocity(), w = b.rigid->getAngularVelocity();
  s.velocity = Vec2(v.x(), v.y());
  s.angular_velocity = w.z();
  return s;
}

double RigidWorld::mass(int i) const { return impl_->bodies.at(i).spec.mass; }
double RigidWorld::inertia(int i) const { return impl_->bodies.at(i).spec.inertia; }

void RigidWorld::set_held(int i, bool held) {
  auto& b = impl_->bodies.at(i);
  if (b.spec.kinematic || b.held == held) return;  // no change: nothing to record either
  impl_->record(Op::set_held, {double(i), double(held)});
  b.held = held;
  b.rigid->setLinearFactor(held ? btVector3(0, 0, 0) : b.linear_factor);
  b.rigid->setAngularFactor(held ? btVector3(0, 0, 0) : b.angular_factor);
  if (held) {
    b.rigid->setLinearVelocity(btVector3(0, 0, 0));
    b.rigid->setAngularVelocity(btVector3(0, 0, 0));
  }
}

void RigidWorld::set_kinematic_state(int i, const PlanarState& s) {
  impl_->record(Op::set_kinematic_state, {double(i), s.position[0], s.position[1], s.angle, s.velocity[0],
                                          s.velocity[1], s.angular_velocity});
  auto& b = impl_->bodies.at(i);
  if (!b.spec.kinematic) throw std::logic_error("set_kinematic_state on a dynamic body");
  btTransform tr;
  tr.setIdentity();
  tr.setOrigin(btVector3(s.position[0], s.position[1], 0.0));
  tr.setRotation(btQuaternion(btVector3(0, 0, 1), s.angle));
  b.rigid->setWorldTransform(tr);
  b.motion->setWorldTransform(tr);
  b.rigid->setLinearVelocity(btVector3(s.velocity[0], s.velocity[1], 0.0));
  b.rigid->setAngularVelocity(btVector3(0, 0, s.angular_velocity));
  b.angle = s.angle;
  b.kinematic_state = s;
}

void RigidWorld::translate(int i, const Vec2& delta) {
  impl_->record(Op::translate, {double(i), delta[0], delta[1]});
  auto& b = impl_->bodies.at(i);
  btTransform tr = b.rigid->getWorldTransform();
  tr.setOrigin(tr.getOrigin() + v3(delta));
  b.rigid->setWorldTransform(tr);
  b.rigid->setCenterOfMassTransform(tr);
  b.motion->setWorldTransform(tr);
  b.kinematic_state.position += delta;
}

void RigidWorld::set_velocity(int i, const Vec2& velocity, double angular_velocity) {
  impl_->record(Op::set_velocity, {double(i), velocity[0], velocity[1], angular_velocity});
  auto& b = impl_->bodies.at(i);
  b.rigid->setLinearVelocity(v3(velocity));
  b.rigid->setAngularVelocity(btVector3(0, 0, angular_velocity));
}

void RigidWorld::apply_force(int i, const Vec2& force, double torque) {
  auto& b = impl_->bodies.at(i);
  if (b.spec.kinematic) return;
  impl_->record(Op::apply_force, {double(i), force[0], force[1], torque});
  b.rigid->applyCentralForce(v3(force));
  b.rigid->applyTorque(btVector3(0, 0, torque));
  b.force += force;
}

void RigidWorld::step(double dt) {
  impl_->record(Op::step, {dt});
  for (auto& b : impl_->bodies) {
    const btVector3 v = b.rigid->getLinearVelocity();
    b.velocity_before = Vec2(v.x(), v.y());
  }
  // maxSubSteps = 0: one step of exactly dt, no fixed-step interpolation (DESIGN.md pitfalls).
  impl_->world.stepSimulation(dt, 0, dt);
  for (auto& b : impl_->bodies) {
    // Continuous angle: add the wrapped change of the quaternion's angle.
    const double a = z_angle(b.rigid->getWorldTransform().getRotation());
    if (!b.spec.kinematic) b.angle += std::remainder(a - b.angle, 2.0 * M_PI);
    b.applied_last = b.force;
    b.force = Vec2::Zero();
    if (b.spec.kinematic) {
      b.contact = Vec2::Zero();
      continue;
    }
    const btVector3 v = b.rigid->getLinearVelocity();
    const Vec2 dv = Vec2(v.x(), v.y()) - b.velocity_before;
    b.contact = b.spec.mass * dv / dt - b.spec.mass * impl_->gravity - b.applied_last;
  }
  impl_->world.clearForces();
}

Vec2 RigidWorld::contact_force(int i) const { return impl_->bodies.at(i).contact; }

const std::vector<double>& RigidWorld::journal() const { return impl_->journal; }

void RigidWorld::replay(const std::vector<double>& journal) {
  impl_ = std::make_unique<Impl>(impl_->gravity, impl_->margin);
  std::size_t at = 0;
  auto next = [&]() {
    if (at >= journal.size()) throw std::runtime_error("the rigid world's journal is truncated");
    return journal[at++];
  };
  auto vec = [&]() {
    const double x = next();
    return Vec2(x, next());
  };
  while (at < journal.size()) {
    switch (static_cast<Op>(static_cast<int>(next()))) {
      case Op::add_body: {
        BodySpec spec;
        spec.kinematic = next() != 0.0;
        for (bool& l : spec.locked) l = next() != 0.0;
        spec.mass = next();
        spec.inertia = next();
        spec.friction = next();
        spec.restitution = next();
        const auto n = static_cast<std::size_t>(next());
        for (std::size_t k = 0; k < n; ++k) spec.outline.push_back(vec());
        add_body(spec);
        break;
      }
      case Op::add_static_segment: {
        const Vec2 a = vec(), b = vec(), into = vec();
        const double thickness = next(), friction = next();
        add_static_segment(a, b, into, thickness, friction, next());
        break;
      }
      case Op::set_held: {
        const int i = static_cast<int>(next());
        set_held(i, next() != 0.0);
        break;
      }
      case Op::set_kinematic_state: {
        const int i = static_cast<int>(next());
        PlanarState s;
        s.position = vec();
        s.angle = next();
        s.velocity = vec();
        s.angular_velocity = next();
        set_kinematic_state(i, s);
        break;
      }
      case Op::translate: {
        const int i = static_cast<int>(next());
        translate(i, vec());
        break;
      }
      case Op::set_velocity: {
        const int i = static_cast<int>(next());
        const Vec2 v = vec();
        set_velocity(i, v, next());
        break;
      }
      case Op::apply_force: {
        const int i = static_cast<int>(next());
        const Vec2 f = vec();
        apply_force(i, f, next());
        break;
      }
      case Op::step: step(next()); break;
      default: throw std::runtime_error("the rigid world's journal holds an unknown call");
    }
  }
}

std::size_t bullet_scalar_size() { return sizeof(btScalar); }

}  // namespace slide::rigid
