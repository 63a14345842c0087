#include "physics/rigid_matrix_model.hpp"

#include "physics/polar.hpp"
#include "physics/rigid_integrators.hpp"
#include "physics/shape.hpp"

namespace bookspin::physics {

RigidMatrixModel::RigidMatrixModel(const Body& body, const ModelConfig& config)
    : RigidBody(body, config) {}

void RigidMatrixModel::reset(const InitialState& initial) {
  R_.setIdentity();
  reset_motion(initial);
  splitting_.reset(R_.transpose() * L_);
}

Eigen::Matrix3d RigidMatrixModel::matrix() const {
  return splits() ? Eigen::Matrix3d(R_ * splitting_.pending_increment().toRotationMatrix()) : R_;
}

Eigen::Matrix3d RigidMatrixModel::orientation() const { return nearest_rotation(matrix()); }

Eigen::Vector3d RigidMatrixModel::omega_world(const Eigen::Matrix3d& R) const {
  return R * (inverse_moments_.asDiagonal() * (R.transpose() * L_));
}

Eigen::Matrix3d RigidMatrixModel::derivative(const Eigen::Matrix3d& R) const {
  return cross_matrix(omega_world(R)) * R;
}

// The paper's SVD normalization R ← U Vᵀ, computed as the polar factor by Newton's method:
// the same rotation to round-off, over ten times faster than JacobiSVD (polar.hpp).
void RigidMatrixModel::normalize() { R_ = nearest_rotation(R_); }

// R += dt·[ω]× R, the product written as ω × each column of R (the same values as the
// 3×3 product with the skew matrix, without its multiplications by zero).
void RigidMatrixModel::euler_step(double dt) {
  const Eigen::Vector3d omega = omega_world(R_);
  Eigen::Matrix3d turn;
  for (int k = 0; k < 3; ++k) turn.col(k) = omega.cross(R_.col(k));
  R_ += dt * turn;
}

void RigidMatrixModel::apply_pending_flow() { R_ = matrix(); }

void RigidMatrixModel::free_step(double dt) {
  switch (config_.integrator) {
    case Integrator::rk4:
      R_ = rk4_step(R_, dt, [this](const Eigen::Matrix3d& R) { return derivative(R); });
      break;
    case Integrator::implicit_midpoint: {
      const auto delta = implicit_midpoint_increment(R_.transpose() * L_, inverse_moments_, dt);
      if (!delta) {
        failure_ = midpoint_failure(t_, dt);
        return;
      }
      R_ = R_ * delta->toRotationMatrix();
      break;
    }
    case Integrator::rescaled_euler: {
      // World L turns with the step (docs/physics.md §10.7): L = R' Π'.
      const RescaledEulerStep s = rescaled_euler_step(R_.transpose() * L_, inverse_moments_, dt);
      R_ = R_ * s.increment.toRotationMatrix();
      L_ = R_ * s.Pi_body;
      break;
    }
    case Integrator::splitting:
    case Integrator::splitting4: {
      Eigen::Quaterniond delta = Eigen::Quaterniond::Identity();
      splitting_.step(dt, R_.transpose() * L_, delta);
      R_ = R_ * delta.toRotationMatrix();
      break;
    }
    default:  // euler, the paper's method
      euler_step(dt);
  }
  if (schedule_.due()) normalize();
  t_ += dt;
}

Corners RigidMatrixModel::corners() const { return matrix() * cage_corners_; }

Diagnostics RigidMatrixModel::diagnostics() const {
  return rigid_diagnostics(body_, matrix(), L_, t_);
}

bool RigidMatrixModel::finite() const { return failure_.empty() && is_sane(R_); }

}  // namespace bookspin::physics
