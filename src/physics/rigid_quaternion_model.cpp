#include "physics/rigid_quaternion_model.hpp"

#include <cmath>

#include "physics/rigid_integrators.hpp"
#include "physics/shape.hpp"

namespace bookspin::physics {

RigidQuaternionModel::RigidQuaternionModel(const Body& body, const ModelConfig& config)
    : RigidBody(body, config) {}

void RigidQuaternionModel::reset(const InitialState& initial) {
  q_.setIdentity();
  reset_motion(initial);
  splitting_.reset(body_momentum());
}

Eigen::Quaterniond RigidQuaternionModel::quaternion() const {
  return splits() ? q_ * splitting_.pending_increment() : q_;
}

Eigen::Matrix3d RigidQuaternionModel::orientation() const {
  return quaternion().normalized().toRotationMatrix();
}

// q̇ = ½ (0, ω) ⊗ q with world-frame ω (Baraff 1997, eq. 4-2), coefficients (x, y, z, w).
// ω comes from R(q/|q|): RK4's stage values are not unit quaternions, and R(q) of a non-unit
// q is not a rotation (it would put an O(dt⁴)-per-step error of |q| into ω, ~80× the
// method's own error at dt = 1/60; docs/physics.md §10). The flow q̇ keeps |q| constant.
Eigen::Vector4d RigidQuaternionModel::derivative(const Eigen::Vector4d& q_coeffs) const {
  const Eigen::Quaterniond q(q_coeffs);
  const Eigen::Matrix3d R = q.normalized().toRotationMatrix();
  const Eigen::Vector3d omega = R * (inverse_moments_.asDiagonal() * (R.transpose() * L_));
  const Eigen::Quaterniond omega_q(0.0, omega.x(), omega.y(), omega.z());
  return 0.5 * (omega_q * q).coeffs();
}

namespace {

/// R(q) by Eigen's unit-quaternion formula (toRotationMatrix, same operations and order;
/// no division by |q|², which is what makes an unnormalized book pulsate).
struct Rotation {
  double r00, r01, r02, r10, r11, r12, r20, r21, r22;
};

Rotation rotation_of(double x, double y, double z, double w) {
  const double tx = 2.0 * x, ty = 2.0 * y, tz = 2.0 * z;
  const double twx = tx * w, twy = ty * w, twz = tz * w;
  const double txx = tx * x, txy = ty * x, txz = tz * x;
  const double tyy = ty * y, tyz = tz * y, tzz = tz * z;
  return {1.0 - (tyy + tzz), txy - twz, txz + twy, txy + twz,        1.0 - (txx + tzz),
          tyz - twx,         txz - twy, tyz + twx, 1.0 - (txx + tyy)};
}

}  // namespace

// The Euler step written out in scalars. The step is one long chain of dependent
// operations, so every cycle on it shows in ns per step; in scalars nothing goes through
// memory on the way (GCC assembled Eigen's packets through the stack, which stalls store
// forwarding).
//
// Unnormalized, q += dt·derivative(q): the same operations in the same order as the Eigen
// expressions of derivative() (toRotationMatrix, the two products, the SSE quaternion
// product of Eigen's Geometry_SIMD.h with its multiplications by w = 0), so the results
// are bit for bit those; dt·(½P) = (½dt)·P exactly. The pulsating book of Figures 11–12
// depends on this R(q) of a non-unit q.
void RigidQuaternionModel::raw_euler_step(double dt) {
  const double x = q_.x(), y = q_.y(), z = q_.z(), w = q_.w();
  const Rotation r = rotation_of(x, y, z, w);
  const double b0 = inverse_moments_[0] * ((r.r00 * L_[0] + r.r10 * L_[1]) + r.r20 * L_[2]);
  const double b1 = inverse_moments_[1] * ((r.r01 * L_[0] + r.r11 * L_[1]) + r.r21 * L_[2]);
  const double b2 = inverse_moments_[2] * ((r.r02 * L_[0] + r.r12 * L_[1]) + r.r22 * L_[2]);
  const double ox = (r.r00 * b0 + r.r01 * b1) + r.r02 * b2;
  const double oy = (r.r10 * b0 + r.r11 * b1) + r.r12 * b2;
  const double oz = r.r20 * b0 + (r.r21 * b1 + r.r22 * b2);  // Eigen's scalar tail order
  const double px = (0.0 * x + oy * z) - (oz * y - ox * w);
  const double py = (0.0 * y + oy * w) + (oz * x - ox * z);
  const double pz = (0.0 * z - oy * x) + (oz * w + ox * y);
  const double pw = (0.0 * w - oy * y) - (oz * z + ox * x);
  const double h = 0.5 * dt;
  q_ = Eigen::Quaterniond(w + h * pw, x + h * px, y + h * py, z + h * pz);
}

// Normalized, q is a unit quaternion at the start of every step, and then
// (0, ω_world) ⊗ q = q ⊗ (0, ω_body) with ω_body = I⁻¹ R(q)ᵀ L: the body-frame form skips
// the product R·ω_body, and ½dt folds into I⁻¹ off the chain. The same step to round-off,
// ~10 cycles shorter. Then q /= |q| as one division and four multiplications.
void RigidQuaternionModel::unit_euler_step(double dt) {
  const double x = q_.x(), y = q_.y(), z = q_.z(), w = q_.w();
  const Rotation r = rotation_of(x, y, z, w);
  const double h = 0.5 * dt;
  const double b0 = (h * inverse_moments_[0]) * ((r.r00 * L_[0] + r.r10 * L_[1]) + r.r20 * L_[2]);
  const double b1 = (h * inverse_moments_[1]) * ((r.r01 * L_[0] + r.r11 * L_[1]) + r.r21 * L_[2]);
  const double b2 = (h * inverse_moments_[2]) * ((r.r02 * L_[0] + r.r12 * L_[1]) + r.r22 * L_[2]);
  const double nx = x + (w * b0 + (y * b2 - z * b1));  // q + q ⊗ (0, ½dt ω_body)
  const double ny = y + (w * b1 + (z * b0 - x * b2));
  const double nz = z + (w * b2 + (x * b1 - y * b0));
  const double nw = w - ((x * b0 + y * b1) + z * b2);
  const double squared = (nx * nx + nz * nz) + (ny * ny + nw * nw);
  const double scale = squared > 0.0 ? 1.0 / std::sqrt(squared) : 1.0;
  q_ = Eigen::Quaterniond(nw * scale, nx * scale, ny * scale, nz * scale);
}

// The orientation the non-Euler integrators work from: R(q/|q|), a rotation even when |q|
// has drifted (only the paper's Euler, and drawing the book, use R(q) of a non-unit q).
// As a quaternion rotation by q* = (w, −u) scaled by 1/|q|²: Rᵀ L = L + (2/|q|²)(u × (u × L)
// − w u × L), fewer operations than forming the matrix.
Eigen::Vector3d RigidQuaternionModel::body_momentum() const {
  const Eigen::Vector3d u = q_.vec();
  const Eigen::Vector3d u_cross_L = u.cross(L_);
  return L_ + (2.0 / q_.squaredNorm()) * (u.cross(u_cross_L) - q_.w() * u_cross_L);
}

void RigidQuaternionModel::apply_pending_flow() { q_ = quaternion(); }

void RigidQuaternionModel::free_step(double dt) {
  switch (config_.integrator) {
    case Integrator::rk4:
      q_.coeffs() = rk4_step(Eigen::Vector4d(q_.coeffs()), dt,
                             [this](const Eigen::Vector4d& c) { return derivative(c); });
      break;
    case Integrator::implicit_midpoint: {
      const auto delta = implicit_midpoint_increment(body_momentum(), inverse_moments_, dt);
      if (!delta) {
        failure_ = midpoint_failure(t_, dt);
        return;
      }
      q_ = q_ * *delta;
      break;
    }
    case Integrator::rescaled_euler: {
      // World L turns with the step (docs/physics.md §10.7): the body-frame Π' is carried
      // through the turn about ω' unchanged, so L = R' Π'.
      const RescaledEulerStep s = rescaled_euler_step(body_momentum(), inverse_moments_, dt);
      q_ = (q_ * s.increment).normalized();
      L_ = q_.toRotationMatrix() * s.Pi_body;
      t_ += dt;
      return;
    }
    case Integrator::splitting:
    case Integrator::splitting4:
      // The increments are unit quaternions, so |q| = 1 + O(ε) here and one Newton step
      // for 1/|q| (1.5 − ½|q|²) is q/|q| to round-off, without the square root and division.
      splitting_.step(dt, body_momentum(), q_);
      if (schedule_.due()) q_.coeffs() *= 1.5 - 0.5 * q_.squaredNorm();
      t_ += dt;
      return;
    default:  // euler, the paper's method
      // Normalized every step, the unit step (which normalizes itself); every N-th step
      // (docs/physics.md §18), the paper's step and q/|q| after each N-th: q is not a unit
      // quaternion in between, where the unit step's body-frame form does not hold.
      if (config_.normalize && config_.normalize_every == 1) {
        schedule_.due();
        unit_euler_step(dt);
      } else {
        raw_euler_step(dt);
        if (schedule_.due()) q_.normalize();
      }
      t_ += dt;
      return;
  }
  if (schedule_.due()) q_.normalize();
  t_ += dt;
}

Corners RigidQuaternionModel::corners() const {
  return quaternion().toRotationMatrix() * cage_corners_;
}

Diagnostics RigidQuaternionModel::diagnostics() const {
  const Eigen::Quaterniond q = quaternion();
  Diagnostics d = rigid_diagnostics(body_, q.toRotationMatrix(), L_, t_);
  d.quaternion_norm = q.norm();
  return d;
}

bool RigidQuaternionModel::finite() const { return failure_.empty() && is_sane(q_.coeffs()); }

}  // namespace bookspin::physics
