#pragma once
// Bullet's rigid body (its double-precision build, bullet-float64) as a bookspin model
// (docs/engines.md): btDiscreteDynamicsWorld::stepSimulation with the body's gyroscopic flag.
#include <memory>

#include "engines/engine_body.hpp"

namespace bookspin::engines {

/// One btRigidBody in a btDiscreteDynamicsWorld with no gravity, no damping, never
/// deactivated, given the body's mass and principal moments as its local inertia (the
/// principal frame is the body frame). Its collision shape, a sphere, only lets the world hold
/// it: its own inertia is never used. step(dt) is stepSimulation(dt, 0): one step of exactly
/// dt. Modes: implicit-body (Bullet's default flag), implicit-world, explicit, none.
class BulletModel final : public EngineBody {
 public:
  BulletModel(const physics::Body& body, physics::Integrator integrator);
  ~BulletModel() override;
  BulletModel(const BulletModel&) = delete;
  BulletModel& operator=(const BulletModel&) = delete;

  void reset(const physics::InitialState& initial) override;
  void step(double dt) override;

 private:
  Eigen::Quaterniond engine_quaternion() const override;
  Eigen::Vector3d engine_omega_body() const override;

  struct World;
  std::unique_ptr<World> world_;
};

/// The btRigidBodyFlags of a Bullet mode (BT_ENABLE_GYROSCOPIC_FORCE_…; 0 for none).
int bullet_gyroscopic_flags(physics::Integrator integrator);

}  // namespace bookspin::engines
