#include "rigid/rigid_world.hpp"

#include <btBulletDynamicsCommon.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <vector>

namespace slide::rigid {

static_assert(sizeof(btScalar) == 8, "Bullet must be compiled and used in double precision (BT_USE_DOUBLE_PRECISION)");

namespace {
btVector3 v3(const Vec2& v) { return btVector3(v[0], v[1], 0.0); }
btVector3 v3(const Vec3& v) { return btVector3(v[0], v[1], v[2]); }
Vec3 from_bt(const btVector3& v) { return Vec3(v.x(), v.y(), v.z()); }

// The rotation about z from a quaternion that has only a z component (planar motion).
double z_angle(const btQuaternion& q) { return 2.0 * std::atan2(q.z(), q.w()); }
}  // namespace

// The calls a journal records.
enum class Op {
  add_body = 1, add_static_segment, set_held, set_kinematic_state, translate, set_velocity, apply_force, step,
  add_solid, add_static_box, translate_3d, set_velocity_3d, apply_force_3d, set_kinematic_state_3d, add_static_mesh
};

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
  Vec3 gravity;

  struct Body {
    std::vector<std::unique_ptr<btConvexHullShape>> hulls;  // one (a convex body) or a concave body's pieces
    std::unique_ptr<btCompoundShape> compound;               // the pieces together, where there are several
    btCollisionShape* shape() const {
      return compound ? static_cast<btCollisionShape*>(compound.get()) : hulls[0].get();
    }
    std::unique_ptr<btDefaultMotionState> motion;
    std::unique_ptr<btRigidBody> rigid;
    BodySpec spec;     // planar bodies
    bool planar = true;
    double mass = 0.0;  // kg (per unit width for planar bodies)
    // Solid bodies: Bullet's frame is the body's principal axes; this turns its rotation back into the rotation since
    // creation (identity when the inertia tensor was diagonal in world axes already).
    btQuaternion principal_to_placed = btQuaternion::getIdentity();
    bool held = false;
    double angle = 0.0;  // continuous angle (planar bodies)
    Vec3 velocity_before = Vec3::Zero();
    Vec3 force = Vec3::Zero();         // applied during the current step
    Vec3 applied_last = Vec3::Zero();  // applied during the last step
    Vec3 contact = Vec3::Zero();
    btVector3 linear_factor, angular_factor;
    PlanarState kinematic_state;  // kinematic bodies: as last set
    SpatialState kinematic_solid_state;  // kinematic solids: as last set (Bullet's step rewrites their velocity)
  };
  std::vector<Body> bodies;
  // Every call that changed the world, in order, with its arguments (RigidWorld::journal).
  std::vector<double> journal;
  void record(Op op, std::initializer_list<double> args) {
    journal.push_back(static_cast<double>(op));
    journal.insert(journal.end(), args);
  }
  std::vector<std::unique_ptr<btTriangleMesh>> ground_meshes;  // the triangles a static mesh shape refers to (kept
                                                               // until after the shapes, declared later, are gone)
  std::vector<std::unique_ptr<btCollisionShape>> ground_shapes;
  std::vector<std::unique_ptr<btRigidBody>> ground;

  Impl(const Vec3& g, double m) : margin(m), gravity(g) { world.setGravity(v3(g)); }
  // Static ground: `shape` placed at `where`, added to the world and kept.
  void add_ground(std::unique_ptr<btCollisionShape> shape, const btTransform& where, double friction,
                  double restitution) {
    btRigidBody::btRigidBodyConstructionInfo info(0.0, nullptr, shape.get());
    info.m_startWorldTransform = where;
    info.m_friction = friction;
    info.m_restitution = restitution;
    auto body = std::make_unique<btRigidBody>(info);
    world.addRigidBody(body.get());
    ground_shapes.push_back(std::move(shape));
    ground.push_back(std::move(body));
  }
  // The body's rigid object from its shape, start transform, mass and principal inertia; added to the world.
  void add(Body&& b, const btTransform& start, double friction, double restitution, const btVector3& inertia,
           bool kinematic);
  ~Impl() {
    for (auto& b : bodies) world.removeRigidBody(b.rigid.get());
    for (auto& g : ground) world.removeRigidBody(g.get());
  }
};

RigidWorld::RigidWorld(const Vec2& gravity, double margin)
    : impl_(std::make_unique<Impl>(Vec3(gravity[0], gravity[1], 0.0), margin)) {
  if (!(margin > 0.0)) throw std::invalid_argument("collision margin must be positive");
}
RigidWorld::RigidWorld(const Vec3& gravity, double margin) : impl_(std::make_unique<Impl>(gravity, margin)) {
  if (!(margin > 0.0)) throw std::invalid_argument("collision margin must be positive");
}

void RigidWorld::Impl::add(Body&& b, const btTransform& start, double friction, double restitution,
                           const btVector3& inertia, bool kinematic) {
  b.motion = std::make_unique<btDefaultMotionState>(start);
  btRigidBody::btRigidBodyConstructionInfo info(kinematic ? 0.0 : b.mass, b.motion.get(), b.shape(),
                                                kinematic ? btVector3(0, 0, 0) : inertia);
  info.m_friction = friction;
  info.m_restitution = restitution;
  info.m_linearDamping = 0.0;
  info.m_angularDamping = 0.0;
  b.rigid = std::make_unique<btRigidBody>(info);
  b.rigid->setActivationState(DISABLE_DEACTIVATION);  // a slide at rest must wake when released
  if (kinematic) b.rigid->setCollisionFlags(b.rigid->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
  b.rigid->setLinearFactor(b.linear_factor);
  b.rigid->setAngularFactor(b.angular_factor);
  world.addRigidBody(b.rigid.get());
  bodies.push_back(std::move(b));
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
  b.mass = spec.mass;
  const Vec2 c = centroid(spec.outline);
  auto& hull = *b.hulls.emplace_back(std::make_unique<btConvexHullShape>());
  for (const Vec2& p : inset(spec.outline, impl_->margin)) {
    hull.addPoint(btVector3(p[0] - c[0], p[1] - c[1], -0.5), false);
    hull.addPoint(btVector3(p[0] - c[0], p[1] - c[1], 0.5), false);
  }
  hull.recalcLocalAabb();
  hull.setMargin(impl_->margin);
  btTransform start;
  start.setIdentity();
  start.setOrigin(btVector3(c[0], c[1], 0.0));
  b.linear_factor = btVector3(spec.locked[0] ? 0 : 1, spec.locked[1] ? 0 : 1, 0);
  b.angular_factor = btVector3(0, 0, spec.locked[2] ? 0 : 1);
  b.kinematic_state.position = c;
  // Inertia about x and y is irrelevant under the planar constraint but must be positive.
  impl_->add(std::move(b), start, spec.friction, spec.restitution, btVector3(spec.inertia, spec.inertia, spec.inertia),
             spec.kinematic);
  return static_cast<int>(impl_->bodies.size() - 1);
}

int RigidWorld::add_solid(const SolidSpec& spec) {
  impl_->record(Op::add_solid, {double(spec.locked[0]), double(spec.locked[1]), double(spec.locked[2]),
                                double(spec.locked[3]), double(spec.locked[4]), double(spec.locked[5]), spec.mass,
                                spec.friction, spec.restitution, spec.centre_of_mass[0], spec.centre_of_mass[1],
                                spec.centre_of_mass[2], double(spec.hull_inset), double(spec.kinematic)});
  impl_->journal.insert(impl_->journal.end(), spec.inertia.data(), spec.inertia.data() + 9);
  impl_->journal.push_back(double(spec.hulls.size()));
  for (const auto& hull : spec.hulls) {
    impl_->journal.push_back(double(hull.vertices.size()));
    for (const Vec3& p : hull.vertices) impl_->journal.insert(impl_->journal.end(), {p[0], p[1], p[2]});
    impl_->journal.push_back(double(hull.triangles.size()));
    for (const auto& t : hull.triangles)
      impl_->journal.insert(impl_->journal.end(), {double(t[0]), double(t[1]), double(t[2])});
  }
  if (spec.hulls.empty()) throw std::invalid_argument("a body needs a hull");
  if (!(spec.mass > 0.0)) throw std::invalid_argument("a body needs a positive mass");
  // The angular factor masks torques in world axes, but the inertia and the gyroscopic term still couple the axes:
  // only all three rotations or none can be held.
  if (spec.locked[3] != spec.locked[4] || spec.locked[3] != spec.locked[5])
    throw std::invalid_argument("a solid body's rotations are locked all three or none");
  // The principal axes: Bullet takes a diagonal inertia in the body's frame.
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  Eigen::Vector3d principal(spec.inertia(0, 0), spec.inertia(1, 1), spec.inertia(2, 2));
  const bool diagonal = spec.inertia(0, 1) == 0.0 && spec.inertia(0, 2) == 0.0 && spec.inertia(1, 2) == 0.0;
  if (!diagonal) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig{Eigen::Matrix3d(spec.inertia)};
    axes = eig.eigenvectors();
    if (axes.determinant() < 0.0) axes.col(2) *= -1.0;
    principal = eig.eigenvalues();
  }
  if (!(principal.minCoeff() > 0.0)) throw std::invalid_argument("a body needs a positive inertia tensor");
  Impl::Body b;
  b.planar = false;
  b.mass = spec.mass;
  const btMatrix3x3 basis(axes(0, 0), axes(0, 1), axes(0, 2), axes(1, 0), axes(1, 1), axes(1, 2), axes(2, 0),
                          axes(2, 1), axes(2, 2));
  btQuaternion to_principal;
  basis.getRotation(to_principal);
  if (!diagonal) b.principal_to_placed = to_principal.inverse();
  const btMatrix3x3 to_body = basis.transpose();
  for (const auto& surface : spec.hulls) {
    auto& hull = *b.hulls.emplace_back(std::make_unique<btConvexHullShape>());
    for (const Vec3& p : spec.hull_inset ? surface.vertices : inset_convex(surface, impl_->margin))
      hull.addPoint(to_body * v3(Vec3(p - spec.centre_of_mass)), false);
    hull.recalcLocalAabb();
    hull.setMargin(impl_->margin);
  }
  if (b.hulls.size() > 1) {  // a concave body: its convex pieces in one compound, each where it is in the body's frame
    b.compound = std::make_unique<btCompoundShape>(false, int(b.hulls.size()));
    btTransform here;
    here.setIdentity();
    for (const auto& hull : b.hulls) b.compound->addChildShape(here, hull.get());
    b.compound->setMargin(impl_->margin);
  }
  btTransform start;
  start.setIdentity();
  start.setOrigin(v3(spec.centre_of_mass));
  start.setBasis(basis);
  b.linear_factor = btVector3(spec.locked[0] ? 0 : 1, spec.locked[1] ? 0 : 1, spec.locked[2] ? 0 : 1);
  b.angular_factor = btVector3(spec.locked[3] ? 0 : 1, spec.locked[4] ? 0 : 1, spec.locked[5] ? 0 : 1);
  b.spec.kinematic = spec.kinematic;
  b.kinematic_solid_state.position = spec.centre_of_mass;  // at rest where it is made until a state is set
  impl_->add(std::move(b), start, spec.friction, spec.restitution, btVector3(principal[0], principal[1], principal[2]),
             spec.kinematic);
  return static_cast<int>(impl_->bodies.size() - 1);
}

void RigidWorld::add_static_box(const Vec3& lo, const Vec3& hi, double friction, double restitution) {
  impl_->record(Op::add_static_box, {lo[0], lo[1], lo[2], hi[0], hi[1], hi[2], friction, restitution});
  const Vec3 half = 0.5 * (hi - lo);
  if (!(half.minCoeff() > 0.0)) throw std::invalid_argument("a static box needs a positive size");
  auto shape = std::make_unique<btBoxShape>(v3(half));
  shape->setMargin(std::min(impl_->margin, 0.25 * half.minCoeff()));
  btTransform where;
  where.setIdentity();
  where.setOrigin(v3(Vec3(0.5 * (lo + hi))));
  impl_->add_ground(std::move(shape), where, friction, restitution);
}

void RigidWorld::add_static_mesh(const TriangleSurface& surface, double friction, double restitution) {
  impl_->record(Op::add_static_mesh, {friction, restitution, double(surface.vertices.size())});
  for (const Vec3& p : surface.vertices) impl_->journal.insert(impl_->journal.end(), {p[0], p[1], p[2]});
  impl_->journal.push_back(double(surface.triangles.size()));
  for (const auto& t : surface.triangles) impl_->journal.insert(impl_->journal.end(), {double(t[0]), double(t[1]), double(t[2])});
  if (surface.triangles.empty()) throw std::invalid_argument("a static mesh needs triangles");
  auto mesh = std::make_unique<btTriangleMesh>();
  for (const auto& t : surface.triangles)
    mesh->addTriangle(v3(surface.vertices[t[0]]), v3(surface.vertices[t[1]]), v3(surface.vertices[t[2]]));
  auto shape = std::make_unique<btBvhTriangleMeshShape>(mesh.get(), true);
  shape->setMargin(impl_->margin);
  impl_->ground_meshes.push_back(std::move(mesh));
  btTransform where;
  where.setIdentity();
  impl_->add_ground(std::move(shape), where, friction, restitution);
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
  impl_->add_ground(std::move(shape), tr, friction, restitution);
}

std::size_t RigidWorld::size() const { return impl_->bodies.size(); }

PlanarState RigidWorld::state(int i) const {
  const auto& b = impl_->bodies.at(i);
  if (!b.planar) throw std::logic_error("the planar state of a solid body");
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

SpatialState RigidWorld::spatial_state(int i) const {
  const auto& b = impl_->bodies.at(i);
  if (b.planar) {
    const PlanarState p = state(i);
    SpatialState s;
    s.position = Vec3(p.position[0], p.position[1], 0.0);
    s.orientation = Quat(Eigen::AngleAxisd(p.angle, Eigen::Vector3d::UnitZ()));
    s.velocity = Vec3(p.velocity[0], p.velocity[1], 0.0);
    s.angular_velocity = Vec3(0.0, 0.0, p.angular_velocity);
    return s;
  }
  if (b.spec.kinematic) return b.kinematic_solid_state;
  const btTransform& tr = b.rigid->getWorldTransform();
  const btQuaternion q = tr.getRotation() * b.principal_to_placed;
  SpatialState s;
  s.position = from_bt(tr.getOrigin());
  s.orientation = Quat(q.w(), q.x(), q.y(), q.z());
  s.velocity = from_bt(b.rigid->getLinearVelocity());
  s.angular_velocity = from_bt(b.rigid->getAngularVelocity());
  return s;
}

double RigidWorld::mass(int i) const { return impl_->bodies.at(i).mass; }
double RigidWorld::inertia(int i) const {
  const auto& b = impl_->bodies.at(i);
  if (!b.planar) throw std::logic_error("the planar inertia of a solid body");
  return b.spec.inertia;
}

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
  if (!b.planar || !b.spec.kinematic) throw std::logic_error("set_kinematic_state on a dynamic or solid body");
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

void RigidWorld::set_kinematic_state(int i, const SpatialState& s) {
  impl_->record(Op::set_kinematic_state_3d,
                {double(i), s.position[0], s.position[1], s.position[2], s.orientation.w(), s.orientation.x(),
                 s.orientation.y(), s.orientation.z(), s.velocity[0], s.velocity[1], s.velocity[2],
                 s.angular_velocity[0], s.angular_velocity[1], s.angular_velocity[2]});
  auto& b = impl_->bodies.at(i);
  if (b.planar || !b.spec.kinematic) throw std::logic_error("a 3-D kinematic state for a dynamic or planar body");
  // Bullet's frame is the principal axes: its rotation is the one since creation less principal_to_placed.
  const btQuaternion q(s.orientation.x(), s.orientation.y(), s.orientation.z(), s.orientation.w());
  btTransform tr;
  tr.setIdentity();
  tr.setOrigin(v3(s.position));
  tr.setRotation(q * b.principal_to_placed.inverse());
  b.rigid->setWorldTransform(tr);
  b.motion->setWorldTransform(tr);
  b.rigid->setLinearVelocity(v3(s.velocity));
  b.rigid->setAngularVelocity(v3(s.angular_velocity));
  b.kinematic_solid_state = s;
}

namespace {
void move_by(btRigidBody& rigid, btMotionState& motion, const btVector3& delta) {
  btTransform tr = rigid.getWorldTransform();
  tr.setOrigin(tr.getOrigin() + delta);
  rigid.setWorldTransform(tr);
  rigid.setCenterOfMassTransform(tr);
  motion.setWorldTransform(tr);
}
}  // namespace

void RigidWorld::translate(int i, const Vec2& delta) {
  impl_->record(Op::translate, {double(i), delta[0], delta[1]});
  auto& b = impl_->bodies.at(i);
  if (!b.planar) throw std::logic_error("a 2-D translation of a solid body");
  move_by(*b.rigid, *b.motion, v3(delta));
  b.kinematic_state.position += delta;
}

void RigidWorld::translate(int i, const Vec3& delta) {
  impl_->record(Op::translate_3d, {double(i), delta[0], delta[1], delta[2]});
  auto& b = impl_->bodies.at(i);
  if (b.planar) throw std::logic_error("a 3-D translation of a planar body");
  move_by(*b.rigid, *b.motion, v3(delta));
  b.kinematic_solid_state.position += delta;
}

void RigidWorld::set_velocity(int i, const Vec2& velocity, double angular_velocity) {
  impl_->record(Op::set_velocity, {double(i), velocity[0], velocity[1], angular_velocity});
  auto& b = impl_->bodies.at(i);
  if (!b.planar) throw std::logic_error("a 2-D velocity of a solid body");
  b.rigid->setLinearVelocity(v3(velocity));
  b.rigid->setAngularVelocity(btVector3(0, 0, angular_velocity));
}

void RigidWorld::set_velocity(int i, const Vec3& velocity, const Vec3& angular_velocity) {
  impl_->record(Op::set_velocity_3d, {double(i), velocity[0], velocity[1], velocity[2], angular_velocity[0],
                                      angular_velocity[1], angular_velocity[2]});
  auto& b = impl_->bodies.at(i);
  if (b.planar) throw std::logic_error("a 3-D velocity of a planar body");
  b.rigid->setLinearVelocity(v3(velocity));
  b.rigid->setAngularVelocity(v3(angular_velocity));
}

void RigidWorld::apply_force(int i, const Vec2& force, double torque) {
  auto& b = impl_->bodies.at(i);
  if (!b.planar) throw std::logic_error("a 2-D force on a solid body");
  if (b.spec.kinematic) return;
  impl_->record(Op::apply_force, {double(i), force[0], force[1], torque});
  b.rigid->applyCentralForce(v3(force));
  b.rigid->applyTorque(btVector3(0, 0, torque));
  b.force += Vec3(force[0], force[1], 0.0);
}

void RigidWorld::apply_force(int i, const Vec3& force, const Vec3& torque) {
  auto& b = impl_->bodies.at(i);
  if (b.planar) throw std::logic_error("a 3-D force on a planar body");
  if (b.spec.kinematic) return;
  impl_->record(Op::apply_force_3d, {double(i), force[0], force[1], force[2], torque[0], torque[1], torque[2]});
  b.rigid->applyCentralForce(v3(force));
  b.rigid->applyTorque(v3(torque));
  b.force += force;
}

void RigidWorld::step(double dt) {
  impl_->record(Op::step, {dt});
  for (auto& b : impl_->bodies) b.velocity_before = from_bt(b.rigid->getLinearVelocity());
  // maxSubSteps = 0: one step of exactly dt, no fixed-step interpolation (DESIGN.md pitfalls).
  impl_->world.stepSimulation(dt, 0, dt);
  for (auto& b : impl_->bodies) {
    // Continuous angle: add the wrapped change of the quaternion's angle.
    if (b.planar && !b.spec.kinematic) {
      const double a = z_angle(b.rigid->getWorldTransform().getRotation());
      b.angle += std::remainder(a - b.angle, 2.0 * M_PI);
    }
    b.applied_last = b.force;
    b.force = Vec3::Zero();
    if (b.spec.kinematic) {
      b.contact = Vec3::Zero();
      continue;
    }
    const Vec3 dv = from_bt(b.rigid->getLinearVelocity()) - b.velocity_before;
    b.contact = b.mass * dv / dt - b.mass * impl_->gravity - b.applied_last;
  }
  impl_->world.clearForces();
}

Vec2 RigidWorld::contact_force(int i) const {
  const Vec3& c = impl_->bodies.at(i).contact;
  return Vec2(c[0], c[1]);
}
Vec3 RigidWorld::contact_force_3d(int i) const { return impl_->bodies.at(i).contact; }

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
  auto vec3 = [&]() {
    const double x = next(), y = next();
    return Vec3(x, y, next());
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
      case Op::add_solid: {
        SolidSpec spec;
        for (bool& l : spec.locked) l = next() != 0.0;
        spec.mass = next();
        spec.friction = next();
        spec.restitution = next();
        spec.centre_of_mass = vec3();
        spec.hull_inset = next() != 0.0;
        spec.kinematic = next() != 0.0;
        for (int k = 0; k < 9; ++k) spec.inertia.data()[k] = next();
        spec.hulls.resize(static_cast<std::size_t>(next()));
        for (auto& hull : spec.hulls) {
          const auto n = static_cast<std::size_t>(next());
          for (std::size_t k = 0; k < n; ++k) hull.vertices.push_back(vec3());
          const auto m = static_cast<std::size_t>(next());
          for (std::size_t k = 0; k < m; ++k) {
            const int a = static_cast<int>(next()), b = static_cast<int>(next());
            hull.triangles.push_back({a, b, static_cast<int>(next())});
          }
        }
        add_solid(spec);
        break;
      }
      case Op::add_static_mesh: {
        const double friction = next(), restitution = next();
        TriangleSurface surface;
        const auto n = static_cast<std::size_t>(next());
        for (std::size_t k = 0; k < n; ++k) surface.vertices.push_back(vec3());
        const auto m = static_cast<std::size_t>(next());
        for (std::size_t k = 0; k < m; ++k) {
          const int a = static_cast<int>(next()), b = static_cast<int>(next());
          surface.triangles.push_back({a, b, static_cast<int>(next())});
        }
        add_static_mesh(surface, friction, restitution);
        break;
      }
      case Op::add_static_box: {
        const Vec3 lo = vec3(), hi = vec3();
        const double friction = next();
        add_static_box(lo, hi, friction, next());
        break;
      }
      case Op::set_kinematic_state_3d: {
        const int i = static_cast<int>(next());
        SpatialState st;
        st.position = vec3();
        const double w = next(), x = next(), y = next();
        st.orientation = Quat(w, x, y, next());
        st.velocity = vec3();
        st.angular_velocity = vec3();
        set_kinematic_state(i, st);
        break;
      }
      case Op::translate_3d: {
        const int i = static_cast<int>(next());
        translate(i, vec3());
        break;
      }
      case Op::set_velocity_3d: {
        const int i = static_cast<int>(next());
        const Vec3 v = vec3();
        set_velocity(i, v, vec3());
        break;
      }
      case Op::apply_force_3d: {
        const int i = static_cast<int>(next());
        const Vec3 f = vec3();
        apply_force(i, f, vec3());
        break;
      }
      case Op::step: step(next()); break;
      default: throw std::runtime_error("the rigid world's journal holds an unknown call");
    }
  }
}

std::size_t bullet_scalar_size() { return sizeof(btScalar); }

}  // namespace slide::rigid
