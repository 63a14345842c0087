#include "physics/rigid_quaternion_model.hpp"

#include "physics/rigid_integrators.hpp"
#include "physics/shape.hpp"

namespace bookspin::physics {

RigidQuaternionModel::RigidQuaternionModel(const Book& book, const ModelConfig& config)
    : book_(book), config_(config), inverse_moments_(book.principal_moments().cwiseInverse()) {}

void RigidQuaternionModel::reset(const InitialState& initial) {
  q_.setIdentity();
  L_ = initial_angular_momentum(book_, initial);
  t_ = 0.0;
}

// q̇ = ½ (0, ω) ⊗ q with world-frame ω (Baraff 1997, eq. 4-2), coefficients (x, y, z, w).
Eigen::Vector4d RigidQuaternionModel::derivative(const Eigen::Vector4d& q_coeffs) const {
  const Eigen::Quaterniond q(q_coeffs);
  const Eigen::Matrix3d R = q.toRotationMatrix();
  const Eigen::Vector3d omega = R * (inverse_moments_.asDiagonal() * (R.transpose() * L_));
  const Eigen::Quaterniond omega_q(0.0, omega.x(), omega.y(), omega.z());
  return 0.5 * (omega_q * q).coeffs();
}

void RigidQuaternionModel::step(double dt) {
  switch (config_.integrator) {
    case Integrator::rk4:
      q_.coeffs() = rk4_step(Eigen::Vector4d(q_.coeffs()), dt,
                             [this](const Eigen::Vector4d& c) { return derivative(c); });
      break;
    case Integrator::implicit_midpoint:
      q_ = q_ * implicit_midpoint_increment(q_.toRotationMatrix().transpose() * L_,
                                            inverse_moments_, dt);
      break;
    case Integrator::splitting:
      q_ = q_ * splitting_increment(q_.toRotationMatrix().transpose() * L_, inverse_moments_, dt);
      break;
    default:  // euler, the paper's method
      q_.coeffs() += dt * derivative(q_.coeffs());
  }
  if (config_.normalize) q_.normalize();
  t_ += dt;
}

Corners RigidQuaternionModel::corners() const {
  return q_.toRotationMatrix() * book_.body_corners();
}

Diagnostics RigidQuaternionModel::diagnostics() const {
  Diagnostics d = rigid_diagnostics(book_, q_.toRotationMatrix(), L_, t_);
  d.quaternion_norm = q_.norm();
  return d;
}

bool RigidQuaternionModel::finite() const { return is_sane(q_.coeffs()); }

}  // namespace bookspin::physics
