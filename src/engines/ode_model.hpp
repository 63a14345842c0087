#pragma once
// ODE's rigid body (Debian's double-precision build) as a bookspin model (docs/engines.md):
// dWorldStep or dWorldQuickStep, gyroscopic mode on or off.
#include <ode/ode.h>

#include "engines/engine_body.hpp"

namespace bookspin::engines {

/// One dBody in a dWorld with no gravity and no damping, its dMass the body's mass and
/// principal moments (dMassSetParameters: centre of mass at the origin, diagonal inertia: the
/// principal frame is the body frame). Modes: step (dWorldStep, gyroscopic mode on: ODE's
/// default), quickstep (dWorldQuickStep, gyroscopic on), none (dWorldStep, gyroscopic off).
class OdeModel final : public EngineBody {
 public:
  OdeModel(const physics::Body& body, physics::Integrator integrator);
  ~OdeModel() override;
  OdeModel(const OdeModel&) = delete;
  OdeModel& operator=(const OdeModel&) = delete;

  void reset(const physics::InitialState& initial) override;
  void step(double dt) override;

 private:
  Eigen::Quaterniond engine_quaternion() const override;
  Eigen::Vector3d engine_omega_body() const override;

  physics::Integrator integrator_;
  dWorldID world_ = nullptr;
  dThreadingImplementationID threading_ = nullptr;  ///< this world's own (self-threaded)
  dBodyID body_id_ = nullptr;
};

}  // namespace bookspin::engines
