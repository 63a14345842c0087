#include "physics/exact_solution.hpp"

#include <algorithm>
#include <array>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "physics/exact_kernels.hpp"

namespace bookspin::physics {

namespace {

using exact_kernels::Real;
using exact_kernels::sin_cos;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Q, a signed permutation with det +1, such that Q·v lists v's components in the order of
/// ascending moments. A proper rotation leaves Euler's equations I ω̇ = (Iω)×ω unchanged,
/// whereas a mirror would flip the sign of the cross product.
Eigen::Matrix3d sorting_rotation(const Eigen::Vector3d& moments) {
  std::array<int, 3> perm{0, 1, 2};
  std::stable_sort(perm.begin(), perm.end(), [&](int a, int b) { return moments[a] < moments[b]; });
  Eigen::Matrix3d q = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 3; ++i) q(i, perm[i]) = 1.0;
  if (q.determinant() < 0.0) q.row(2) *= -1.0;
  return q;
}

Real sign_of(Real x) { return x < 0 ? -1.0L : 1.0L; }

/// `angle` less the nearest multiple of 2π, in long double, before it is rounded to a double: a
/// double would carry an angle of 2⁴⁰ rad only to 2⁻¹² (docs/physics.md §8, "How far in time").
double reduced_angle(long double angle) {
  constexpr Real kTwoPi = 2 * std::numbers::pi_v<Real>;
  return static_cast<double>(angle - kTwoPi * std::round(angle / kTwoPi));
}

/// Rotation by ψ about the z axis.
Eigen::Matrix3d rotation_z(double psi) {
  const double c = std::cos(psi), s = std::sin(psi);
  Eigen::Matrix3d r;
  r << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  return r;
}

}  // namespace

ExactRotation::ExactRotation(const Eigen::Vector3d& moments, const Eigen::Vector3d& omega0_body,
                             ExactParts parts)
    : moments_(moments), omega0_(omega0_body), parts_(parts) {
  if (!moments.allFinite() || (moments.array() <= 0.0).any())
    throw std::invalid_argument("ExactRotation: principal moments must be finite and positive");
  if (!omega0_body.allFinite())
    throw std::invalid_argument("ExactRotation: initial angular velocity must be finite");
  to_sorted_ = sorting_rotation(moments);
  I_ = to_sorted_.cwiseAbs() * moments;
  L_world_ = moments.cwiseProduct(omega0_body);
  // |L| and |ω0| in long double: ψ's rates and a steady motion's angle take their rounding
  // times t (docs/physics.md §8, "How far in time").
  Real L2 = 0.0L, w2 = 0.0L, E = 0.0L;
  for (int i = 0; i < 3; ++i) {
    const Real w_i = omega0_body[i], L_i = static_cast<Real>(moments[i]) * w_i;
    L2 += L_i * L_i;
    w2 += w_i * w_i;
    E += 0.5L * L_i * w_i;
  }
  // ½ ω·Iω too: in doubles ω·L overflows before it is halved (E = 9e307 gave inf).
  energy_ = static_cast<double>(E);
  L_long_ = std::sqrt(L2);
  rate_long_ = std::sqrt(w2);
  // Not Eigen's norm(): its squares overflow a double from |L| ~ 1e154 (and underflow below
  // 1e-154), where |L| itself is far inside the range.
  L_norm_ = static_cast<double>(L_long_);
  const Eigen::Vector3d w = to_sorted_ * omega0_body;
  classify(w);
  set_peak_rate();
  if (case_ != ExactCase::steady) {
    set_phase(w);
    set_landen_chain();
    set_quarter_phase(w);
    if (parts_ == ExactParts::omega_and_orientation) set_precession();
    // W from the momentum frame of ω(0) as state() evaluates it (jacobi at u0), not of ω0 as
    // given: where L lies within ~1e-7 of the reference axis, the frame's axis L × e_r is set by
    // components of L a few orders above ω's rounding, and ω0's frame against the evaluated one
    // turned R(0) 9e-6 rad off the identity (docs/physics.md §8, "How far in time").
    anchor_ = (momentum_frame(scaled_momentum(sorted_omega_long(jacobi_at(0.0)))) * to_sorted_)
                  .transpose();
  }
  set_horizon();
}

void ExactRotation::classify(const Eigen::Vector3d& w) {
  // Steady iff ω is an eigenvector of I: no two nonzero components with different moments.
  bool steady = true;
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j)
      if (w[i] != 0.0 && w[j] != 0.0 && I_[i] != I_[j]) steady = false;
  if (steady) {
    case_ = ExactCase::steady;
    return;
  }
  const Real I1 = I_[0], I2 = I_[1], I3 = I_[2];
  const Real w1 = w[0], w2 = w[1], w3 = w[2];
  // 2E·I3 − L², L² − 2E·I1 and L² − 2E·I2 written as sums of single-signed terms, so that
  // they carry no cancellation error (the case decision near the separatrix depends on d2).
  const Real d3 = I1 * (I3 - I1) * w1 * w1 + I2 * (I3 - I2) * w2 * w2;
  const Real d1 = I2 * (I2 - I1) * w2 * w2 + I3 * (I3 - I1) * w3 * w3;
  const Real d2 = I3 * (I3 - I2) * w3 * w3 - I1 * (I2 - I1) * w1 * w1;
  case_ = d2 > 0 ? ExactCase::around_largest
                 : (d2 < 0 ? ExactCase::around_smallest : ExactCase::separatrix);
  set_amplitudes(d1, d2, d3);
}

// Amplitudes, λ and k of docs/physics.md §8. Case A (and the separatrix): ω1 ∝ cn, ω3 ∝ dn;
// case B: ω1 ∝ dn, ω3 ∝ cn; ω2 ∝ sn always. The denominators are positive whenever the
// motion is not steady (then I3 > I2 and ω3 ≠ 0 in case A, I2 > I1 and ω1 ≠ 0 in case B).
// k'² = 1 − k² comes from (I3 − I2)(L² − 2E·I1) − (I2 − I1)(2E·I3 − L²) = (I3 − I1)(L² − 2E·I2)
// rather than from 1 − k², which would lose digits near the separatrix.
void ExactRotation::set_amplitudes(long double d1, long double d2, long double d3) {
  const Real I1 = I_[0], I2 = I_[1], I3 = I_[2];
  Real k2;
  if (case_ == ExactCase::around_smallest) {
    cn_axis_ = 2;
    dn_axis_ = 0;
    k2 = (I3 - I2) * d1 / ((I2 - I1) * d3);
    kc2_ = (I3 - I1) * -d2 / ((I2 - I1) * d3);
    lambda_ = std::sqrt((I2 - I1) * d3 / (I1 * I2 * I3));
    amplitude_ = {std::sqrt(d3 / (I1 * (I3 - I1))), std::sqrt(d1 / (I2 * (I2 - I1))),
                  std::sqrt(d1 / (I3 * (I3 - I1)))};
  } else {
    cn_axis_ = 0;
    dn_axis_ = 2;
    k2 = (I2 - I1) * d3 / ((I3 - I2) * d1);
    kc2_ = (I3 - I1) * d2 / ((I3 - I2) * d1);
    lambda_ = std::sqrt((I3 - I2) * d1 / (I1 * I2 * I3));
    amplitude_ = {std::sqrt(d3 / (I1 * (I3 - I1))), std::sqrt(d3 / (I2 * (I3 - I2))),
                  std::sqrt(d1 / (I3 * (I3 - I1)))};
  }
  // k² rounds to 1 only within ~1e-19 of the separatrix; treat that as on it (cn = dn there,
  // so either case's form holds) for sn and cn, but keep k'² in dn² = k'² + k² cn²: dropped, it
  // dropped the dn axis' a·k', which moments far apart make a fair share of ω0 (moments 6.5e-25,
  // 2.6e11, 1.4e16: ω(0)'s z came out 4e-32 for −3.2e-11; docs/physics.md §8, "The phase by
  // quarter periods").
  if (case_ == ExactCase::separatrix || k2 >= 1.0L || kc2_ <= 0.0L) {
    case_ = ExactCase::separatrix;
    k_ = 1.0L;
    kc2_ = std::max(kc2_, 0.0L);
  } else {
    k_ = std::sqrt(k2);
  }
}

// The largest |ω| the motion reaches (docs/physics.md §8): with cn² = 1 − sn² and
// dn² = 1 − k²sn², |ω|² = a_cn² + a_dn² + sn²(a_sn² − a_cn² − k²a_dn²) is linear in sn² ∈ [0, 1],
// so its largest value is at sn² = 0 or sn² = 1. In long double: it can pass a double's range
// (up to |L|/I_min) while E and |L| are far inside it.
void ExactRotation::set_peak_rate() {
  if (case_ == ExactCase::steady) {
    peak_rate_ = static_cast<double>(rate_long_);
    return;
  }
  const Real a_cn2 = amplitude_[cn_axis_] * amplitude_[cn_axis_];
  const Real a_sn2 = amplitude_[1] * amplitude_[1];
  const Real a_dn2 = amplitude_[dn_axis_] * amplitude_[dn_axis_];
  const Real peak2 = std::max(a_cn2 + a_dn2, a_sn2 + kc2_ * a_dn2);
  // Rounded to a double: a peak within a part in 1e12 of DBL_MAX counts as past it, since
  // R·ω's rounding could carry a world component over.
  const Real peak = std::max(std::sqrt(peak2), rate_long_);
  peak_rate_ = peak * (1 + 1e-12L) > std::numeric_limits<double>::max()
                   ? std::numeric_limits<double>::infinity()
                   : static_cast<double>(peak);
}

// Signs and u0 so that ω(0) = ω0. Euler's equations need sign(cn axis) = sign(sn)·sign(dn).
// Off the separatrix sn's sign is absorbed into u0 (sn is odd, cn and dn even), and dn > 0
// gives the dn axis its sign. On it cn = dn = sech > 0, so both those signs come from ω0.
void ExactRotation::set_phase(const Eigen::Vector3d& w) {
  const Real s_dn = sign_of(w[dn_axis_]);
  const Real s_cn = case_ == ExactCase::separatrix ? sign_of(w[cn_axis_]) : s_dn;
  amplitude_[dn_axis_] *= s_dn;
  amplitude_[cn_axis_] *= s_cn;
  amplitude_[1] *= s_cn * s_dn;
  const Real cn0 = w[cn_axis_] / amplitude_[cn_axis_];
  const Real sn0 = w[1] / amplitude_[1];
  if (case_ == ExactCase::separatrix) {
    // sn = tanh u, cn = sech u ≥ 0: |cn0|, since a component −0 (its sign taken as +) would
    // give sn0/−0 = ∓∞ and ω(0) the wrong sign on axis 2.
    u0_ = std::asinh(sn0 / std::abs(cn0));
    K_ = std::numeric_limits<Real>::infinity();
  }
  // Off it u0 and K follow the Landen chain (set_landen_chain, set_quarter_phase).
}

// The descending Landen transformation (DLMF 22.7(i)): with k_{n+1} = (1 − k'_n)/(1 + k'_n)
// = k_n²/(1 + k'_n)² and k'_{n+1} = 2√k'_n/(1 + k'_n), both free of cancellation, the moduli
// fall quadratically (six levels from k' = 1e-9). k'_0 is Boost's, √(2(1 − k) − (1 − k)²) of
// the stored k, so that the precession's R_J (Boost's) sees the same modulus. K is the chain's,
// (π/2)(1 + k_N²/4)/∏(1 + k_n) (DLMF 19.8.12): Boost's ellint_1(k) forms 1 − k², which cancels
// near the separatrix (1e-14 of K off for the book's jiggled x spin, k' = 2e-3), and the phase by
// quarter periods (set_quarter_phase) counts in the K of the sn, cn, dn it evaluates.
void ExactRotation::set_landen_chain() {
  landen_ = LandenChain{};
  landen_.quarter = std::numbers::pi_v<Real> / 2;
  if (case_ != ExactCase::separatrix) K_ = landen_.quarter;
  period_ = 4.0L * K_;
  if (k_ == 0.0L || k_ >= 1.0L) return;
  const Real kc = 1 - k_;
  Real k = k_, kp = k_ < 0.5L ? Real(std::sqrt(1 - k_ * k_)) : Real(std::sqrt(2 * kc - kc * kc));
  landen_.kc = kp;
  while (k >= 1e-5L && landen_.levels < LandenChain::kMaxLevels) {
    const Real next = k * k / ((1 + kp) * (1 + kp));
    landen_.k[landen_.levels] = next;
    landen_.one_minus_k[landen_.levels] = 2 * kp / (1 + kp);
    landen_.scale /= 1 + next;
    kp = 2 * std::sqrt(kp) / (1 + kp);
    k = next;
    ++landen_.levels;
  }
  landen_.m_last = k * k;
  landen_.quarter = std::numbers::pi_v<Real> / 2 * (1 + landen_.m_last / 4) / landen_.scale;
  K_ = landen_.quarter;
  period_ = 4.0L * K_;
}

// u0 as a whole number q of quarter periods K plus an offset δ0 of at most about K/2, each kept
// on its own (docs/physics.md §8, "The phase by quarter periods"). ω0 may lie a hair from a zero
// of cn or sn whose amplitude is many orders above ω0 (moments 1e-50, 1, 1e50: cn(u0) = 1e-24),
// and u0 = F(φ | k) ≈ K − 1e-24 as one long double keeps no digit of that hair: ω(0) came out
// −25083 where ω0 is 1. The offset keeps it to its own relative precision, and sn, cn, dn of
// qK + δ follow from those of δ by the quarter-period shifts (DLMF 22.4(iii)):
//   sn(K + δ) = cn δ/dn δ,   cn(K + δ) = −k' sn δ/dn δ,   dn(K + δ) = k'/dn δ,
// sn(2K + δ) = −sn δ, cn(2K + δ) = −cn δ. With (s, c) = (sn u0, cn u0) from ω0, tan am δ is s/c
// for q = 0 (c > 0) or q = 2 (c < 0), and −c/(k' s) for q = ±1 (the sign of s); the smaller of
// the two (k' s² < c² picks the first) keeps |tan am δ| ≤ 1/√k', so δ ≤ about K/2. Then, with
// τ = tan am δ, F(atan τ | k) = τ R_F(1, 1 + k'²τ², 1 + τ²) (DLMF 19.25.5, R_F homogeneous of
// degree −1/2): positive terms, no cancellation near the separatrix, and k' the Landen chain's
// (that of the sn, cn, dn it is evaluated with).
void ExactRotation::set_quarter_phase(const Eigen::Vector3d& w) {
  if (case_ == ExactCase::separatrix) {
    quarter0_ = 0;
    delta0_ = u0_;
    return;
  }
  const Real s = w[1] / amplitude_[1], c = w[cn_axis_] / amplitude_[cn_axis_];
  const Real kc = landen_.kc;
  Real tau;
  if (kc * s * s < c * c) {
    quarter0_ = c > 0.0L ? 0 : 2;
    tau = s / c;
  } else {
    quarter0_ = s > 0.0L ? 1 : -1;
    tau = -c / (kc * s);
  }
  delta0_ = tau * boost::math::ellint_rf(1.0L, 1.0L + kc * kc * tau * tau, 1.0L + tau * tau);
  if (quarter0_ == 2 && delta0_ > 0.0L) quarter0_ = -2;  // u0 within [−2K, 2K]
  u0_ = quarter0_ * landen_.quarter + delta0_;
}

ExactRotation::Jacobi ExactRotation::jacobi_at(double t) const {
  if (case_ == ExactCase::separatrix) return jacobi(phase(t));
  // δ = δ0 + λt less the nearest whole number n of quarter periods (counted through a double,
  // as in jacobi()); then sn, cn, dn of r by the Landen chain and the shift by q0 + n quarters.
  const Real K = landen_.quarter;
  Real r = delta0_ + lambda_ * static_cast<Real>(t);
  const double ratio = static_cast<double>(r / K);
  const long long n = static_cast<long long>(std::floor(ratio + 0.5));
  r -= static_cast<Real>(n) * K;
  const Jacobi j = jacobi_reduced(r);
  const Real d = k_ == 0.0L ? 1.0L : j.dn, kc = landen_.kc;
  Jacobi out{};
  switch (static_cast<int>(((quarter0_ + n) % 4 + 4) % 4)) {
    case 0:
      out = {j.sn, j.cn, 0.0L};
      break;
    case 1:
      out = {j.cn / d, -kc * j.sn / d, 0.0L};
      break;
    case 2:
      out = {-j.sn, -j.cn, 0.0L};
      break;
    default:
      out = {-j.cn / d, kc * j.sn / d, 0.0L};
      break;
  }
  out.dn = std::sqrt(kc2_ + k_ * k_ * out.cn * out.cn);
  return out;
}

// sn and cn of u in [0, 4K] (dn is left 0). At the bottom of the chain, modulus k_N < 1e-5 and
// v = u/∏(1 + k_n) in [0, 2π]: sn, cn = sin v ∓ ¼k_N²(v − sin v cos v)(cos v, −sin v), dn =
// 1 − ½k_N² sin² v (A&S 16.13, error O(k_N⁴) < 1e-20). Each level up (DLMF 22.7.1–22.7.3),
// with s, c, d of modulus k_{n+1} and D = 1 + k_{n+1} s²:
//   sn = (1 + k_{n+1}) s/D,  cn = c d/D,  dn = (1 − k_{n+1} s²)/D = ((1 − k_{n+1}) + k_{n+1} c²)/D,
// the last summing positive terms (1 − k_{n+1} s² would cancel near the separatrix).
ExactRotation::Jacobi ExactRotation::jacobi_reduced(long double u) const {
  if (k_ >= 1.0L) return {std::tanh(u), 1 / std::cosh(u), 1 / std::cosh(u)};
  const Real v = landen_.scale * u;
  Real s0, c0;
  sin_cos(v, s0, c0);
  if (k_ == 0.0L) return {s0, c0, 1.0L};
  const Real m = landen_.m_last, w = m * (v - s0 * c0) / 4;
  Real s = s0 - w * c0, c = c0 + w * s0, d = 1 - m * s0 * s0 / 2;
  for (int n = landen_.levels - 1; n >= 0; --n) {
    const Real kn = landen_.k[n], D = 1 + kn * s * s;
    const Real s_up = (1 + kn) * s / D, c_up = c * d / D;
    d = (landen_.one_minus_k[n] + kn * c * c) / D;
    s = s_up;
    c = c_up;
  }
  return {s, c, d};
}

ExactRotation::Jacobi ExactRotation::jacobi(long double u) const {
  // Reduce to one period 4K first: the functions lose accuracy with the argument's size. The
  // whole periods are counted in a double (glibc's floorl sets the x87 control word): where
  // that rounds up, u is left a hair below 0, which jacobi_reduced takes as well.
  if (case_ != ExactCase::separatrix)
    u -= period_ * static_cast<Real>(std::floor(static_cast<double>(u / period_)));
  Jacobi j = jacobi_reduced(u);
  // Boost forms dn as a ratio of two cosines that both vanish where cn = 0, losing digits
  // near u = K (where dn = k' is smallest); dn² = k'² + k² cn² adds positive terms instead.
  j.dn = std::sqrt(kc2_ + k_ * k_ * j.cn * j.cn);
  return j;
}

ExactRotation::Jacobi ExactRotation::jacobi_boost(long double u) const {
  if (case_ != ExactCase::separatrix) u -= period_ * std::floor(u / period_);
  Jacobi j{};
  j.sn = boost::math::jacobi_elliptic(k_, u, &j.cn, &j.dn);
  j.dn = std::sqrt(kc2_ + k_ * k_ * j.cn * j.cn);
  return j;
}

std::array<long double, 3> ExactRotation::sorted_omega_long(const Jacobi& j) const {
  std::array<Real, 3> w{};
  w[cn_axis_] = amplitude_[cn_axis_] * j.cn;
  w[1] = amplitude_[1] * j.sn;
  w[dn_axis_] = amplitude_[dn_axis_] * j.dn;
  return w;
}

Eigen::Vector3d ExactRotation::sorted_omega(const Jacobi& j) const {
  Eigen::Vector3d w;
  w[cn_axis_] = static_cast<double>(amplitude_[cn_axis_] * j.cn);
  w[1] = static_cast<double>(amplitude_[1] * j.sn);
  w[dn_axis_] = static_cast<double>(amplitude_[dn_axis_] * j.dn);
  return w;
}

ExactOmegaForm ExactRotation::omega_form() const {
  if (case_ == ExactCase::steady || case_ == ExactCase::separatrix)
    throw std::logic_error("ExactRotation: a steady or separatrix motion has no omega_form");
  ExactOmegaForm form;
  const Eigen::Matrix3d back = to_sorted_.transpose();
  form.A.col(0) = back.col(cn_axis_) * static_cast<double>(amplitude_[cn_axis_]);
  form.A.col(1) = back.col(1) * static_cast<double>(amplitude_[1]);
  form.A.col(2) = back.col(dn_axis_) * static_cast<double>(amplitude_[dn_axis_]);
  form.lambda = static_cast<double>(lambda_);
  form.u0 = static_cast<double>(u0_);
  form.k = static_cast<double>(k_);
  form.kc2 = static_cast<double>(kc2_);
  form.K = static_cast<double>(K_);
  return form;
}

Eigen::Vector3d ExactRotation::omega_body(double t) const {
  check_horizon(t);
  if (case_ == ExactCase::steady) return omega0_;
  return to_sorted_.transpose() * sorted_omega(jacobi_at(t));
}

Eigen::Vector3d ExactRotation::omega_dot_body(double t) const {
  check_horizon(t);
  if (case_ == ExactCase::steady) return Eigen::Vector3d::Zero();
  const Jacobi j = jacobi_at(t);
  Eigen::Vector3d w_dot;
  w_dot[cn_axis_] = static_cast<double>(-amplitude_[cn_axis_] * lambda_ * j.sn * j.dn);
  w_dot[1] = static_cast<double>(amplitude_[1] * lambda_ * j.cn * j.dn);
  w_dot[dn_axis_] = static_cast<double>(-amplitude_[dn_axis_] * lambda_ * k_ * k_ * j.sn * j.cn);
  return to_sorted_.transpose() * w_dot;
}

Eigen::Vector3d ExactRotation::angular_momentum_body(double t) const {
  return moments_.cwiseProduct(omega_body(t));
}

// P: rows are the momentum frame's axes in sorted body coordinates. z = L/|L|,
// y = (L × e_r)/|L × e_r| (its components are ±L_i or 0, so no cancellation), x = y × z.
// I ω (sorted axes) formed in long double and divided by its largest component: |L| itself may
// lie beyond a double's range where ω and I do not (moments 1e-190, ω 1e-179: |L| 1e-369), and
// the squares in normalized() overflow or underflow a double from |L| ~ 1e±154.
Eigen::Vector3d ExactRotation::scaled_momentum(const std::array<long double, 3>& w_sorted) const {
  std::array<Real, 3> L{};
  Real largest = 0.0L;
  for (int i = 0; i < 3; ++i) {
    L[i] = static_cast<Real>(I_[i]) * w_sorted[i];
    largest = std::max(largest, std::abs(L[i]));
  }
  return {static_cast<double>(L[0] / largest), static_cast<double>(L[1] / largest),
          static_cast<double>(L[2] / largest)};
}

Eigen::Matrix3d ExactRotation::momentum_frame(const Eigen::Vector3d& L_sorted) const {
  const Eigen::Vector3d z = L_sorted.normalized();
  const Eigen::Vector3d y = L_sorted.cross(Eigen::Vector3d::Unit(dn_axis_)).normalized();
  Eigen::Matrix3d p;
  p.row(0) = y.cross(z);
  p.row(1) = y;
  p.row(2) = z;
  return p;
}

Eigen::Matrix3d ExactRotation::rotation_from(const Eigen::Vector3d& L_sorted, double psi) const {
  return anchor_ * rotation_z(psi) * momentum_frame(L_sorted) * to_sorted_;
}

// One Jacobi evaluation serves R(t) and ω(t) alike.
ExactState ExactRotation::state(double t) const {
  check_horizon(t);
  ExactState state;
  state.t = t;
  Eigen::Matrix3d R;
  if (case_ == ExactCase::steady) {
    R = orientation(t);
    state.omega_body = omega0_;
  } else {
    if (parts_ == ExactParts::omega_only)
      throw std::logic_error("ExactRotation: built for omega alone, it has no orientation");
    const Jacobi j = jacobi_at(t);
    R = orientation_at(t, j, Evaluation::fast, psi_S0_);
    state.omega_body = to_sorted_.transpose() * sorted_omega(j);
    // L and E from ω in long double: a component of ω may round to 0 (or a subnormal) while its
    // I_i ω_i is a fair share of L (moments 1e267 and 1e-153 in one body).
    const std::array<Real, 3> w = sorted_omega_long(j);
    Eigen::Vector3d L_sorted;
    Real E = 0.0L;
    for (int i = 0; i < 3; ++i) {
      L_sorted[i] = static_cast<double>(static_cast<Real>(I_[i]) * w[i]);
      E += 0.5L * static_cast<Real>(I_[i]) * w[i] * w[i];
    }
    state.L = R * (to_sorted_.transpose() * L_sorted);
    state.E = static_cast<double>(E);
  }
  Eigen::Quaterniond q(R);
  q.normalize();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  state.q = Eigen::Vector4d(q.w(), q.x(), q.y(), q.z());
  state.omega_world = R * state.omega_body;
  if (case_ == ExactCase::steady) {
    state.L = R * moments_.cwiseProduct(state.omega_body);
    state.E = 0.5 * state.omega_body.dot(moments_.cwiseProduct(state.omega_body));
  }
  return state;
}

Eigen::Matrix3d ExactRotation::orientation(double t) const {
  check_horizon(t);
  if (case_ == ExactCase::steady) {
    if (rate_long_ == 0.0L) return Eigen::Matrix3d::Identity();
    const Eigen::Vector3d axis = omega0_ / static_cast<double>(rate_long_);
    return Eigen::AngleAxisd(reduced_angle(rate_long_ * t), axis.normalized()).toRotationMatrix();
  }
  if (parts_ == ExactParts::omega_only)
    throw std::logic_error("ExactRotation: built for omega alone, it has no orientation");
  return orientation_at(t, jacobi_at(t), Evaluation::fast, psi_S0_);
}

Eigen::Matrix3d ExactRotation::orientation_at(double t, const Jacobi& j, Evaluation how,
                                              long double S0) const {
  const Eigen::Vector3d L_sorted = scaled_momentum(sorted_omega_long(j));
  return rotation_from(L_sorted, reduced_angle(precession_at(t, j, how, S0)));
}

double ExactRotation::period() const {
  if (case_ == ExactCase::steady || case_ == ExactCase::separatrix) return kInfinity;
  return static_cast<double>(4.0L * K_ / lambda_);
}

double ExactRotation::flip_period() const { return 0.5 * period(); }

}  // namespace bookspin::physics
