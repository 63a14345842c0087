#include "physics/rigid_integrators.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <utility>

namespace bookspin::physics {

RescaledEulerStep rescaled_euler_step(const Eigen::Vector3d& Pi_body,
                                      const Eigen::Vector3d& inverse_moments, double dt) {
  // docs/physics.md §10.7: Π̇ = Π × ω (Euler's equations in the body frame), one explicit
  // step; |Π − dt ω × Π|² = |Π|² + dt²|ω × Π|², so the rescaling only shrinks it back.
  const Eigen::Vector3d omega = inverse_moments.cwiseProduct(Pi_body);
  Eigen::Vector3d Pi = Pi_body - dt * omega.cross(Pi_body);
  const double squared = Pi.squaredNorm();
  if (squared > 0.0) Pi *= std::sqrt(Pi_body.squaredNorm() / squared);
  const Eigen::Vector3d turn = dt * inverse_moments.cwiseProduct(Pi);  // ω'·dt, body frame
  const double angle = turn.norm();
  Eigen::Quaterniond increment = Eigen::Quaterniond::Identity();
  if (angle > 0.0) increment = Eigen::Quaterniond(Eigen::AngleAxisd(angle, turn / angle));
  return {Pi, increment};
}

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

/// The body-frame state a splitting carries through its sub-flows, in scalars so that it
/// stays in registers (each sub-flow waits on the previous one's Π: the step is one chain).
struct RotorState {
  double P[3];     ///< body-frame angular momentum Π
  double w, v[3];  ///< body-frame rotation so far, Δ = (w, v)
};

struct SinCos {
  double sin, cos;
};

/// sin x and cos x for |x| ≤ 1/32 by their Taylor series to x⁷ and x⁸, exact to round-off
/// there (the first omitted terms are below 3e-18·|x| and 3e-22), in Estrin's form so that
/// the halves of each polynomial evaluate side by side: a fraction of the library's cost.
[[gnu::always_inline]] inline SinCos small_sincos(double x) {
  // Coefficients as products with constant reciprocals: a division would not be rewritten
  // as a multiplication (the reciprocal is inexact) and costs several times as much.
  constexpr double s3 = 1.0 / 6, s5 = 1.0 / 120, s7 = 1.0 / 5040;
  constexpr double c4 = 1.0 / 24, c6 = 1.0 / 720, c8 = 1.0 / 40320;
  const double x2 = x * x, x4 = x2 * x2;
  return {x * ((1.0 - x2 * s3) + x4 * (s5 - x2 * s7)),
          (1.0 - 0.5 * x2) + x4 * ((c4 - x2 * c6) + x4 * c8)};
}

/// (c·Pj + s·Pk, c·Pk − s·Pj) for c = cos x, s = sin x and |x| ≤ 1/256, written as one
/// polynomial in x per component whose coefficients come from Pj and Pk (known before x):
/// the degree-4 cosine and degree-5 sine series are exact to round-off there (the first
/// omitted terms, x⁶/720 and x⁷/5040, are below 5e-18 and 7e-19·|x|), and in Estrin's form
/// each component is ready 5 operations after x instead of the 7 of series, then rotation.
[[gnu::always_inline]] inline void small_turn(double x, double& Pj, double& Pk) {
  constexpr double s3 = 1.0 / 6, s5 = 1.0 / 120, c4 = 1.0 / 24;
  const double j = Pj, k = Pk, x2 = x * x, x4 = x2 * x2;
  Pj = ((j + x * k) + x2 * (-0.5 * j - x * (s3 * k))) + x4 * (c4 * j + x * (s5 * k));
  Pk = ((k - x * j) + x2 * (-0.5 * k + x * (s3 * j))) + x4 * (c4 * k - x * (s5 * j));
}

/// Exact flow of T_A = Π_A²/(2 I_A) for time h: the body turns about its own axis A by
/// θ = h·Π_A/I_A, so Δ ← Δ ⊗ (cos θ/2, sin θ/2 e_A), and the body-frame momentum turns by
/// −θ (Π_A is constant along this flow). `rate` = h / I_A. The sub-flows form one chain
/// (each waits on the previous Π) and Δ hangs off it, so only Π's path is short: for the
/// angles of any usable dt (|θ| ≤ 1/256 covers dt = 1/60 for the book) small_turn(); up to
/// |θ| ≤ 1/32 the short series of θ, then the rotation; beyond, the library's sin and cos
/// of θ/2 and the double-angle formulas. The axis is a template argument so that every
/// index is a constant, and it is inlined so that the state stays in registers.
template <int A>
[[gnu::always_inline]] inline void rotor_flow(double rate, RotorState& s) {
  constexpr int j = (A + 1) % 3, k = (A + 2) % 3;  // (A, j, k) is right-handed
  const double angle = rate * s.P[A];
  SinCos half;
  if (std::abs(angle) <= 1.0 / 256) {
    small_turn(angle, s.P[j], s.P[k]);
    half = small_sincos(0.5 * angle);
  } else {
    SinCos full;
    if (std::abs(angle) <= 1.0 / 32) {
      full = small_sincos(angle);
      half = small_sincos(0.5 * angle);
    } else {
      half = {std::sin(0.5 * angle), std::cos(0.5 * angle)};
      full = {2.0 * half.sin * half.cos, 1.0 - 2.0 * half.sin * half.sin};
    }
    const double Pj = s.P[j], Pk = s.P[k];
    s.P[j] = full.cos * Pj + full.sin * Pk;
    s.P[k] = full.cos * Pk - full.sin * Pj;
  }
  // Δ ⊗ (cos θ/2, sin θ/2·e_A), written out: e_A has one non-zero component.
  const double c = half.cos, sn = half.sin;
  const double w = s.w, vA = s.v[A], vj = s.v[j], vk = s.v[k];
  s.w = c * w - sn * vA;
  s.v[A] = c * vA + sn * w;
  s.v[j] = c * vj + sn * vk;
  s.v[k] = c * vk - sn * vj;
}

/// Strang steps of γ_i·dt in sequence, sub-flows in the order O, M, N, M, O, applied to `s`
/// except for the last outer half-flow, whose time it returns. The outer half-flow ending one
/// step and the one starting the next are a single flow (T_O commutes with itself), so s
/// steps cost 4s sub-flows plus the pending one; `pending` is the time of an outer flow left
/// over from before, merged into the first.
template <int O, int M, int N>
double advance(RotorState& s, const Eigen::Vector3d& inverse_moments, double pending, double dt,
               std::span<const double> gammas) {
  const double rate_O = inverse_moments[O], rate_M = inverse_moments[M],
               rate_N = inverse_moments[N];
  double outer_time = pending + 0.5 * gammas[0] * dt;
  for (std::size_t i = 0; i < gammas.size(); ++i) {
    const double h = gammas[i] * dt;
    rotor_flow<O>(rate_O * outer_time, s);
    rotor_flow<M>(rate_M * (0.5 * h), s);
    rotor_flow<N>(rate_N * h, s);
    rotor_flow<M>(rate_M * (0.5 * h), s);
    outer_time = 0.5 * h + (i + 1 < gammas.size() ? 0.5 * gammas[i + 1] * dt : 0.0);
  }
  return outer_time;
}

using AdvanceFunction = double (*)(RotorState&, const Eigen::Vector3d&, double, double,
                                   std::span<const double>);

/// advance() for a run-time order: one of the six instantiations.
AdvanceFunction advance_for(const std::array<int, 3>& order) {
  using Entry = std::pair<std::array<int, 3>, AdvanceFunction>;
  static constexpr std::array<Entry, 6> instantiations{{{{0, 1, 2}, advance<0, 1, 2>},
                                                        {{0, 2, 1}, advance<0, 2, 1>},
                                                        {{1, 0, 2}, advance<1, 0, 2>},
                                                        {{1, 2, 0}, advance<1, 2, 0>},
                                                        {{2, 0, 1}, advance<2, 0, 1>},
                                                        {{2, 1, 0}, advance<2, 1, 0>}}};
  for (const auto& [key, function] : instantiations)
    if (key == order) return function;
  throw std::invalid_argument("splitting order must be a permutation of the axes 0, 1, 2");
}

/// The flow of T_axis for time h, for a run-time axis.
void outer_flow(int axis, double h, const Eigen::Vector3d& inverse_moments, RotorState& s) {
  const double rate = inverse_moments[axis] * h;
  if (axis == 0) rotor_flow<0>(rate, s);
  if (axis == 1) rotor_flow<1>(rate, s);
  if (axis == 2) rotor_flow<2>(rate, s);
}

/// Whole steps from Π with Δ starting at the identity: the increment of s Strang steps.
Eigen::Quaterniond compose(const Eigen::Vector3d& Pi_body, const Eigen::Vector3d& inverse_moments,
                           double dt, const std::array<int, 3>& order,
                           std::span<const double> gammas) {
  RotorState s{{Pi_body[0], Pi_body[1], Pi_body[2]}, 1.0, {0.0, 0.0, 0.0}};
  const double pending = advance_for(order)(s, inverse_moments, 0.0, dt, gammas);
  outer_flow(order[0], pending, inverse_moments, s);
  return Eigen::Quaterniond(s.w, s.v[0], s.v[1], s.v[2]);
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

std::span<const double> strang_gammas() { return kStrang; }

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
  return composed_splitting_increment(Pi_body, inverse_moments, dt, composition4::suzuki5());
}

SplittingStepper::SplittingStepper(const Eigen::Vector3d& inverse_moments,
                                   std::span<const double> gammas)
    : inverse_moments_(inverse_moments), gammas_(gammas), order_(axes_by_moment(inverse_moments)) {}

void SplittingStepper::reset(const Eigen::Vector3d& Pi_body) {
  Pi_lag_ = Pi_body;
  pending_ = 0.0;
}

void SplittingStepper::step(double dt, const Eigen::Vector3d& Pi_of_orientation,
                            Eigen::Quaterniond& orientation) {
  // Π's own rounding, measured against Rᵀ L at the step's start, beside the sub-flows; added
  // at the end, it ties Π to the orientation as closely as taking Rᵀ L afresh would.
  const Eigen::Vector3d correction = Pi_of_orientation - Pi_lag_;
  RotorState s{{Pi_lag_[0], Pi_lag_[1], Pi_lag_[2]},
               orientation.w(),
               {orientation.x(), orientation.y(), orientation.z()}};
  pending_ = advance_for(order_)(s, inverse_moments_, pending_, dt, gammas_);
  Pi_lag_ = Eigen::Vector3d(s.P[0], s.P[1], s.P[2]) + correction;
  orientation = Eigen::Quaterniond(s.w, s.v[0], s.v[1], s.v[2]);
}

Eigen::Quaterniond SplittingStepper::pending_increment() const {
  RotorState s{{Pi_lag_[0], Pi_lag_[1], Pi_lag_[2]}, 1.0, {0.0, 0.0, 0.0}};
  outer_flow(order_[0], pending_, inverse_moments_, s);
  return Eigen::Quaterniond(s.w, s.v[0], s.v[1], s.v[2]);
}

Eigen::Vector3d SplittingStepper::Pi_body() const {
  RotorState s{{Pi_lag_[0], Pi_lag_[1], Pi_lag_[2]}, 1.0, {0.0, 0.0, 0.0}};
  outer_flow(order_[0], pending_, inverse_moments_, s);
  return Eigen::Vector3d(s.P[0], s.P[1], s.P[2]);
}

}  // namespace bookspin::physics
