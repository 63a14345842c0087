#include "engines/bullet_model.hpp"

#include <btBulletDynamicsCommon.h>

namespace bookspin::engines {

int bullet_gyroscopic_flags(physics::Integrator integrator) {
  switch (integrator) {
    case physics::Integrator::implicit_body:
      return BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_BODY;
    case physics::Integrator::implicit_world:
      return BT_ENABLE_GYROSCOPIC_FORCE_IMPLICIT_WORLD;
    case physics::Integrator::explicit_gyro:
      return BT_ENABLE_GYROSCOPIC_FORCE_EXPLICIT;
    default:
      return 0;
  }
}

struct BulletModel::World {
  btDefaultCollisionConfiguration configuration;
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  btSequentialImpulseConstraintSolver solver;
  btDiscreteDynamicsWorld world{&dispatcher, &broadphase, &solver, &configuration};
  btSphereShape shape{1.0};
  btRigidBody body;

  World(const physics::Body& b, int flags)
      : body(btRigidBody::btRigidBodyConstructionInfo(
            b.cage.mass, nullptr, &shape, btVector3(b.moments.x(), b.moments.y(), b.moments.z()))) {
    world.setGravity(btVector3(0, 0, 0));
    body.setDamping(0, 0);
    body.setSleepingThresholds(0, 0);
    body.setActivationState(DISABLE_DEACTIVATION);
    body.setFlags(flags);
    world.addRigidBody(&body);
  }
  ~World() { world.removeRigidBody(&body); }
};

BulletModel::BulletModel(const physics::Body& body, physics::Integrator integrator)
    : EngineBody(body), world_(std::make_unique<World>(body, bullet_gyroscopic_flags(integrator))) {
  reset(physics::InitialState{});
}

BulletModel::~BulletModel() = default;

void BulletModel::reset(const physics::InitialState& initial) {
  btRigidBody& body = world_->body;
  body.setWorldTransform(btTransform::getIdentity());
  body.setLinearVelocity(btVector3(0, 0, 0));
  const Eigen::Vector3d omega = initial_omega(initial);  // world = body frame at reset
  body.setAngularVelocity(btVector3(omega.x(), omega.y(), omega.z()));
  body.updateInertiaTensor();
  t_ = 0.0;
}

void BulletModel::step(double dt) {
  world_->world.stepSimulation(dt, 0);
  t_ += dt;
}

Eigen::Quaterniond BulletModel::engine_quaternion() const {
  const btQuaternion q = world_->body.getWorldTransform().getRotation();
  return Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z());
}

// Bullet keeps ω in the world frame: ω_body = Rᵀ ω_world with R the body's basis.
Eigen::Vector3d BulletModel::engine_omega_body() const {
  const btTransform& x = world_->body.getWorldTransform();
  const btVector3 w = x.getBasis().transpose() * world_->body.getAngularVelocity();
  return Eigen::Vector3d(w.x(), w.y(), w.z());
}

}  // namespace bookspin::engines
