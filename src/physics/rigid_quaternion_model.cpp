#include "physics/rigid_quaternion_model.hpp"

#include <cmath>

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

// The Euler step q += dt·derivative(q), then q /= |q| if normalizing, written out in
// scalars: the same operations in the same order as the Eigen expressions it replaces
// (toRotationMatrix, the two products, the SSE quaternion product of Eigen's
// Geometry_SIMD.h including its multiplications by w = 0, squaredNorm's pairwise sum), so
// the results are bit for bit those of derivative() and normalize(). The step is one long
// chain of dependent operations; in scalars nothing goes through memory on the way
// (GCC assembled Eigen's packets through the stack, stalling store forwarding).
// dt·(½P) = (½dt)·P exactly, since halving is exact.
void RigidQuaternionModel::euler_step(double dt) {
  const double x = q_.x(), y = q_.y(), z = q_.z(), w = q_.w();
  const double tx = 2.0 * x, ty = 2.0 * y, tz = 2.0 * z;
  const double twx = tx * w, twy = ty * w, twz = tz * w;
  const double txx = tx * x, txy = ty * x, txz = tz * x;
  const double tyy = ty * y, tyz = tz * y, tzz = tz * z;
  const double r00 = 1.0 - (tyy + tzz), r01 = txy - twz, r02 = txz + twy;
  const double r10 = txy + twz, r11 = 1.0 - (txx + tzz), r12 = tyz - twx;
  const double r20 = txz - twy, r21 = tyz + twx, r22 = 1.0 - (txx + tyy);
  // Body frame I⁻¹ Rᵀ L, then world ω = R (I⁻¹ Rᵀ L).
  const double b0 = inverse_moments_[0] * ((r00 * L_[0] + r10 * L_[1]) + r20 * L_[2]);
  const double b1 = inverse_moments_[1] * ((r01 * L_[0] + r11 * L_[1]) + r21 * L_[2]);
  const double b2 = inverse_moments_[2] * ((r02 * L_[0] + r12 * L_[1]) + r22 * L_[2]);
  const double ox = (r00 * b0 + r01 * b1) + r02 * b2;
  const double oy = (r10 * b0 + r11 * b1) + r12 * b2;
  const double oz = r20 * b0 + (r21 * b1 + r22 * b2);  // Eigen's scalar tail sums this way
  // (0, ω) ⊗ q.
  const double px = (0.0 * x + oy * z) - (oz * y - ox * w);
  const double py = (0.0 * y + oy * w) + (oz * x - ox * z);
  const double pz = (0.0 * z - oy * x) + (oz * w + ox * y);
  const double pw = (0.0 * w - oy * y) - (oz * z + ox * x);
  const double h = 0.5 * dt;
  double nx = x + h * px, ny = y + h * py, nz = z + h * pz, nw = w + h * pw;
  if (config_.normalize) {
    const double squared = (nx * nx + nz * nz) + (ny * ny + nw * nw);
    if (squared > 0.0) {
      const double norm = std::sqrt(squared);
      nx /= norm, ny /= norm, nz /= norm, nw /= norm;
    }
  }
  q_ = Eigen::Quaterniond(nw, nx, ny, nz);
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
    default:  // euler, the paper's method, normalizing itself
      euler_step(dt);
      t_ += dt;
      return;
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
