#include "physics/rigid_integrators.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

namespace bookspin::physics {

std::optional<Eigen::Quaterniond> implicit_midpoint_increment(
    const Eigen::Vector3d& Pi_body, const Eigen::Vector3d& inverse_moments, double dt) {
  // Solve Π_mid = Π_n + (dt/2) Π_mid × I⁻¹Π_mid; a contraction for dt·|ω| ≪ 1.
  const double size = Pi_body.lpNorm<Eigen::Infinity>();
  const double round_off = 4.0 * std::numeric_limits<double>::epsilon() * size;
  Eigen::Vector3d Pi_mid = Pi_body;
  double previous_change = std::numeric_limits<double>::infinity();
  bool converged = false;
  for (int iteration = 0; iteration < kMidpointMaxIterations && !converged; ++iteration) {
    const Eigen::Vector3d next =
        Pi_body + (0.5 * dt) * Pi_mid.cross(inverse_moments.cwiseProduct(Pi_mid));
    const double change = (next - Pi_mid).lpNorm<Eigen::Infinity>();
    Pi_mid = next;
    // Converged at round-off, or at the floor where rounding makes the update wander.
    converged = change <= round_off || (change >= previous_change && change <= 1e-12 * size);
    previous_change = change;
  }
  if (!converged || !Pi_mid.allFinite()) return std::nullopt;
  // Cayley transform of dt·[ω_mid]× as a quaternion: (1, dt·ω_mid/2), normalized.
  const Eigen::Vector3d half_v = 0.5 * dt * inverse_moments.cwiseProduct(Pi_mid);
  return Eigen::Quaterniond(1.0, half_v.x(), half_v.y(), half_v.z()).normalized();
}

std::string midpoint_failure(double t, double dt) {
  char text[200];
  std::snprintf(text, sizeof text,
                "implicit midpoint: the fixed-point iteration did not converge in %d iterations "
                "at t = %.6g (dt = %.6g is too large for the spin rate)",
                kMidpointMaxIterations, t, dt);
  return text;
}

std::array<int, 3> axes_by_moment(const Eigen::Vector3d& inverse_moments) {
  std::array<int, 3> axes{0, 1, 2};
  // Insertion sort of three: smallest moment = largest inverse moment first.
  for (int i = 1; i < 3; ++i)
    for (int j = i; j > 0 && inverse_moments[axes[j]] > inverse_moments[axes[j - 1]]; --j)
      std::swap(axes[j], axes[j - 1]);
  return axes;
}

namespace {

/// The body-frame state a splitting carries through its sub-flows.
struct RotorState {
  Eigen::Vector3d Pi;        ///< body-frame angular momentum
  Eigen::Quaterniond delta;  ///< body-frame rotation so far
};

/// Exact flow of T_axis = Π_axis²/(2 I_axis) for time h: the body turns about its own axis
/// by θ = h·Π_axis/I_axis, so Δ ← Δ ⊗ (cos θ/2, sin θ/2 e_axis), and the body-frame momentum
/// turns by −θ (Π_axis is constant along this flow). One sine and cosine of θ/2; those of
/// θ follow from the double-angle formulas.
void rotor_flow(int axis, double h, const Eigen::Vector3d& inverse_moments, RotorState& s) {
  const double half_angle = 0.5 * h * s.Pi[axis] * inverse_moments[axis];
  const double c = std::cos(half_angle), sn = std::sin(half_angle);
  const double cos_angle = c * c - sn * sn, sin_angle = 2.0 * sn * c;
  const int j = (axis + 1) % 3, k = (axis + 2) % 3;  // (axis, j, k) is right-handed
  const double Pj = s.Pi[j], Pk = s.Pi[k];
  s.Pi[j] = cos_angle * Pj + sin_angle * Pk;
  s.Pi[k] = cos_angle * Pk - sin_angle * Pj;
  // Δ ⊗ (c, sn·e_axis), written out: e_axis has one non-zero component.
  Eigen::Vector3d v = s.delta.vec();
  const double w = s.delta.w();
  s.delta.w() = c * w - sn * v[axis];
  s.delta.vec()[axis] = c * v[axis] + sn * w;
  s.delta.vec()[j] = c * v[j] + sn * v[k];
  s.delta.vec()[k] = c * v[k] - sn * v[j];
}

/// Strang steps of γ_i·dt in sequence, in the order {outer, middle, inner}; the outer
/// half-flow ending one step and the one starting the next are a single flow (T_outer
/// commutes with itself), so s steps cost 4s + 1 sub-flows.
Eigen::Quaterniond compose(const Eigen::Vector3d& Pi_body, const Eigen::Vector3d& inverse_moments,
                           double dt, const std::array<int, 3>& order,
                           std::span<const double> gammas) {
  RotorState s{Pi_body, Eigen::Quaterniond::Identity()};
  const auto [outer, middle, inner] = order;
  double outer_time = 0.5 * gammas[0] * dt;
  for (std::size_t i = 0; i < gammas.size(); ++i) {
    const double h = gammas[i] * dt;
    rotor_flow(outer, outer_time, inverse_moments, s);
    rotor_flow(middle, 0.5 * h, inverse_moments, s);
    rotor_flow(inner, h, inverse_moments, s);
    rotor_flow(middle, 0.5 * h, inverse_moments, s);
    outer_time = 0.5 * h + (i + 1 < gammas.size() ? 0.5 * gammas[i + 1] * dt : 0.0);
  }
  rotor_flow(outer, outer_time, inverse_moments, s);
  return s.delta;
}

constexpr std::array<double, 1> kStrang{1.0};

}  // namespace

Eigen::Quaterniond splitting_increment(const Eigen::Vector3d& Pi_body,
                                       const Eigen::Vector3d& inverse_moments, double dt,
                                       const std::array<int, 3>& order) {
  return compose(Pi_body, inverse_moments, dt, order, kStrang);
}

Eigen::Quaterniond splitting_increment(const Eigen::Vector3d& Pi_body,
                                       const Eigen::Vector3d& inverse_moments, double dt) {
  return splitting_increment(Pi_body, inverse_moments, dt, axes_by_moment(inverse_moments));
}

namespace composition4 {

std::span<const double> triple_jump() {
  static const double g1 = 1.0 / (2.0 - std::cbrt(2.0));
  static const std::array<double, 3> gammas{g1, 1.0 - 2.0 * g1, g1};
  return gammas;
}

std::span<const double> suzuki5() {
  static const double g1 = 1.0 / (4.0 - std::cbrt(4.0));
  static const std::array<double, 5> gammas{g1, g1, 1.0 - 4.0 * g1, g1, g1};
  return gammas;
}

std::span<const double> mclachlan5() {
  constexpr double g1 = 0.28, g2 = 0.62546642846767004501;
  static constexpr std::array<double, 5> gammas{g1, g2, 1.0 - 2.0 * (g1 + g2), g2, g1};
  return gammas;
}

}  // namespace composition4

Eigen::Quaterniond composed_splitting_increment(const Eigen::Vector3d& Pi_body,
                                                const Eigen::Vector3d& inverse_moments, double dt,
                                                std::span<const double> gammas) {
  return compose(Pi_body, inverse_moments, dt, axes_by_moment(inverse_moments), gammas);
}

Eigen::Quaterniond splitting4_increment(const Eigen::Vector3d& Pi_body,
                                        const Eigen::Vector3d& inverse_moments, double dt) {
  return composed_splitting_increment(Pi_body, inverse_moments, dt, composition4::mclachlan5());
}

}  // namespace bookspin::physics
