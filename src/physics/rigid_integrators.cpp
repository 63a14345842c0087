#include "physics/rigid_integrators.hpp"

#include <cmath>

namespace bookspin::physics {

Eigen::Quaterniond implicit_midpoint_increment(const Eigen::Vector3d& Pi_body,
                                               const Eigen::Vector3d& inverse_moments, double dt) {
  // Solve Π_mid = Π_n + (dt/2) Π_mid × I⁻¹Π_mid; a contraction for dt·|ω| ≪ 1.
  Eigen::Vector3d Pi_mid = Pi_body;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const Eigen::Vector3d next =
        Pi_body + (0.5 * dt) * Pi_mid.cross(inverse_moments.cwiseProduct(Pi_mid));
    const double change = (next - Pi_mid).lpNorm<Eigen::Infinity>();
    Pi_mid = next;
    if (change <= 1e-16 * Pi_body.lpNorm<Eigen::Infinity>()) break;
  }
  // Cayley transform of dt·[ω_mid]× as a quaternion: (1, dt·ω_mid/2), normalized.
  const Eigen::Vector3d half_v = 0.5 * dt * inverse_moments.cwiseProduct(Pi_mid);
  return Eigen::Quaterniond(1.0, half_v.x(), half_v.y(), half_v.z()).normalized();
}

namespace {

/// Exact flow of T_axis for time h: the body turns about its own axis by h·Π_axis/I_axis,
/// and the body-frame momentum turns the opposite way. Appends the turn to `delta`.
void rotor_flow(int axis, double h, const Eigen::Vector3d& inverse_moments, Eigen::Vector3d& Pi,
                Eigen::Quaterniond& delta) {
  const double angle = h * Pi[axis] * inverse_moments[axis];
  const Eigen::AngleAxisd turn(angle, Eigen::Vector3d::Unit(axis));
  Pi = turn.inverse() * Pi;
  delta = delta * Eigen::Quaterniond(turn);
}

void strang_step(double h, const Eigen::Vector3d& inverse_moments, Eigen::Vector3d& Pi,
                 Eigen::Quaterniond& delta) {
  rotor_flow(0, 0.5 * h, inverse_moments, Pi, delta);
  rotor_flow(1, 0.5 * h, inverse_moments, Pi, delta);
  rotor_flow(2, h, inverse_moments, Pi, delta);
  rotor_flow(1, 0.5 * h, inverse_moments, Pi, delta);
  rotor_flow(0, 0.5 * h, inverse_moments, Pi, delta);
}

}  // namespace

Eigen::Quaterniond splitting_increment(const Eigen::Vector3d& Pi_body,
                                       const Eigen::Vector3d& inverse_moments, double dt) {
  Eigen::Vector3d Pi = Pi_body;
  Eigen::Quaterniond delta = Eigen::Quaterniond::Identity();
  strang_step(dt, inverse_moments, Pi, delta);
  return delta;
}

}  // namespace bookspin::physics
