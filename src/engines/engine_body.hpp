#pragma once
// What the three engine models share: the body, the run's time, and the diagnostics computed
// from the engine's orientation and angular velocity (docs/engines.md, docs/physics.md §9).
#include <Eigen/Geometry>

#include "physics/shape.hpp"
#include "physics/simulator.hpp"

namespace bookspin::engines {

/// A rigid body stepped by another engine. The engine holds the state; a subclass reads it
/// back as q (body→world, w x y z) and ω (body frame, rad per time unit).
class EngineBody : public physics::Simulator {
 public:
  physics::Corners corners() const override { return orientation() * cage_corners_; }
  Eigen::Matrix3d orientation() const override {
    return engine_quaternion().normalized().toRotationMatrix();
  }
  /// ω in the body frame, as the engine has it, and L = R I_body ω in the world frame (not
  /// constant: its drift is the engine's error), energies, cosines (docs/physics.md §9, §12).
  physics::Diagnostics diagnostics() const override {
    const Eigen::Matrix3d R = orientation();
    const Eigen::Vector3d omega = engine_omega_body();
    const Eigen::Vector3d L = R * body_.moments.cwiseProduct(omega);
    physics::Diagnostics d = physics::rigid_diagnostics(body_, R, L, t_);
    d.omega_body = omega;
    d.quaternion_norm = engine_quaternion().norm();
    return d;
  }
  bool finite() const override {
    return physics::is_sane(engine_quaternion().coeffs()) && physics::is_sane(engine_omega_body());
  }

 protected:
  explicit EngineBody(const physics::Body& body)
      : body_(body), cage_corners_(body.cage.body_corners()) {}

  /// ω0 = I_body⁻¹ L0 (body frame = world frame at reset), L0 with the jiggle
  /// (docs/physics.md §5): every model starts from the same L.
  Eigen::Vector3d initial_omega(const physics::InitialState& initial) const {
    return physics::initial_angular_momentum(body_.moments, initial).cwiseQuotient(body_.moments);
  }

  /// The engine's orientation quaternion, body → world, as stored (not renormalized).
  virtual Eigen::Quaterniond engine_quaternion() const = 0;
  /// The engine's angular velocity, body frame.
  virtual Eigen::Vector3d engine_omega_body() const = 0;

  physics::Body body_;
  physics::Corners cage_corners_;  ///< body.cage's corners, body frame (3×8)
  double t_ = 0.0;                 ///< time units
};

}  // namespace bookspin::engines
