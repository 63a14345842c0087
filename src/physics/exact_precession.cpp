// The precession angle ψ(t) of the exact torque-free motion in closed form (docs/physics.md §8):
// ExactRotation's set_precession and the S(u) it rests on, through Carlson's R_J (periodic,
// from a table of base points, and on the separatrix elementary). The rest of ExactRotation is
// exact_solution.cpp's.
#include <algorithm>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <cmath>
#include <numbers>

#include "physics/exact_kernels.hpp"
#include "physics/exact_solution.hpp"

namespace bookspin::physics {

namespace {

using exact_kernels::carlson_rc1p;
using exact_kernels::carlson_rj;
using exact_kernels::Real;
using exact_kernels::sin_cos;

/// Half the step of the precession's table of base points, in u (table_S).
constexpr long double kBaseHalfStep = 0.25L;

}  // namespace

// The precession angle in closed form (docs/physics.md §8). With c the cn axis, s = 2 the sn
// axis and r the dn axis, ψ̇ = |L| (2E − I_r ω_r²) / (|L|² − I_r² ω_r²) is a ratio of two
// linear functions of sn² u, equal to |L|/I_c at sn = 0 and |L|/I_s at sn² = 1, with its pole at
// sn² = 1/n:
//   ψ̇ = |L|/I_c + |L| (1/I_s − 1/I_c) (1 − n) sn²/(1 − n sn²),
//   n = −(I_r a_r k / (I_c a_c))² ≤ 0,  1 − n = (I_s a_s / (I_c a_c))²  (a: amplitudes),
// so ψ(t) = |L| t / I_c + g (S(u(t)) − S(u0)), g = |L| (1/I_s − 1/I_c)(1 − n)/λ, where
// S(u) = ∫_0^u sn²/(1 − n sn²) du = (Π(n; am u | k) − u)/n is given by Carlson's R_J.
void ExactRotation::set_precession() {
  if (case_ == ExactCase::steady) return;
  const int c = cn_axis_, r = dn_axis_;
  const Real Ic = I_[c], Is = I_[1], Ir = I_[r];
  const Real ratio_r = Ir * amplitude_[r] * k_ / (Ic * amplitude_[c]);
  const Real ratio_s = Is * amplitude_[1] / (Ic * amplitude_[c]);
  char_n_ = -ratio_r * ratio_r;
  const Real one_minus_n = ratio_s * ratio_s;
  const Real L = L_long_;
  psi_rate_ = L / Ic;
  psi_gain_ = L * ((Ic - Is) / (Ic * Is)) * one_minus_n / lambda_;
  if (case_ == ExactCase::separatrix) return;  // S(u) − S(u0) at once (separatrix_S)
  // Over one period 2K of sn²: 2 S(K) = (2/3) R_J(0, k'², 1, 1 − n).
  psi_kc2_ = (1.0L - k_) * (1.0L + k_);
  psi_S_half_ = 2.0L / 3.0L * boost::math::ellint_rj(0.0L, psi_kc2_, 1.0L, one_minus_n);
  psi_rho2_ = -char_n_ * (k_ * k_ - char_n_) * one_minus_n;
  // The table of base points b_i = i K/N, |h| ≤ K/(2N) ≤ kBaseHalfStep (table_S). K here is the
  // Landen chain's, (π/2)(1 + k_N²/4)/∏(1 + k_n) (DLMF 19.8.12), that of the sn, cn, dn the
  // table holds: Boost's K differs from it in its last digits near the separatrix (its 1 − k²
  // cancels). sn, cn, dn of b_i up to K/2 by the Landen chain, above it by the reflection about K
  // of b_{N−i} = K − b_i (sn(K − w) = cn w/dn w, cn(K − w) = k' sn w/dn w, dn(K − w) = k'/dn w:
  // DLMF 22.4(iii), no cancellation); S(b_i) from S(b_{i−1}) by the addition theorem with h = K/N.
  const Real K = std::numbers::pi_v<Real> / 2 * (1 + landen_.m_last / 4) / landen_.scale;
  const int steps = std::max(1, static_cast<int>(std::ceil(K / (2 * kBaseHalfStep))));
  psi_inverse_step_ = steps / K;
  psi_base_.resize(steps + 1);
  psi_base_[0] = {0.0L, 1.0L, 1.0L, 0.0L};
  const Real kc = std::sqrt(psi_kc2_);
  const Jacobi h = jacobi(K / steps);
  const Real h_dn = std::sqrt(psi_kc2_ + k_ * k_ * h.cn * h.cn), h_sn2 = h.sn * h.sn;
  const Real S_h = h.sn * h_sn2 / 3.0L *
                   carlson_rj(h.cn * h.cn, h_dn * h_dn, 1.0L, 1.0L - char_n_ * h_sn2,
                              std::abs(h.cn), h_dn, 1.0L);
  for (int i = 1; i <= steps; ++i) {
    const BasePoint& previous = psi_base_[i - 1];
    BasePoint& b = psi_base_[i];
    const Real u = K * i / steps;
    if (2 * i <= steps) {
      const Jacobi j = jacobi(u);
      b.sn = j.sn;
      b.cn = j.cn;
      b.dn = std::sqrt(psi_kc2_ + k_ * k_ * j.cn * j.cn);
    } else {
      const BasePoint& w = psi_base_[steps - i];
      const Real inverse_dn = 1 / w.dn;
      b.sn = w.cn * inverse_dn;
      b.cn = kc * w.sn * inverse_dn;
      b.dn = kc * inverse_dn;
    }
    const Real P = 1 - char_n_ * b.sn * b.sn + char_n_ * previous.sn * h.sn * b.cn * b.dn;
    const Real X = previous.sn * h.sn * b.sn / P;
    b.S = P > 0.25L ? previous.S + S_h + X * carlson_rc1p(psi_rho2_ * X * X)
                    : periodic_S(u, jacobi(u), Evaluation::fast);
  }
  // S(K) = S(2K)/2, which the recurrence meets to 4e-19 relative (39 steps at k'² = 1e-17).
  psi_base_[steps].S = psi_S_half_ / 2;
  psi_S0_ = table_S(u0_, jacobi_at(0.0));
}

// S(u) for |u| ≤ K (DLMF 19.25.14, homogeneous form: sin φ = sn u, cos φ = cn u,
// √(1 − k² sin² φ) = dn u): S = (1/3) sn³ R_J(cn², dn², 1, 1 − n sn²); beyond, S(u + 2K) =
// S(u) + S(2K). `j` holds sn, cn, dn at u (any u): u = m·2K + v with |v| ≤ K, and sn(v) =
// (−1)^m sn(u), cn(v) = (−1)^m cn(u), dn unchanged. Returns m, and (sn, cn) of v.
long double ExactRotation::half_periods(long double u, const Jacobi& j, long double& sn,
                                        long double& cn) const {
  const Real period = 2.0L * K_;
  // m = round(u/period), its parity by an integer where it fits in one.
  const Real ratio = u / period;
  Real m, flip;
  if (std::abs(ratio) < 1e18L) {
    // Through a double, as in sin_cos: the callers hold for an m one off at ±K.
    const double r = static_cast<double>(ratio);
    const long long whole = static_cast<long long>(r + (r < 0.0 ? -0.5 : 0.5));
    m = static_cast<Real>(whole);
    flip = whole % 2 == 0 ? 1.0L : -1.0L;
  } else {
    m = std::round(ratio);
    flip = std::fmod(m, 2.0L) == 0.0L ? 1.0L : -1.0L;
  }
  sn = flip * j.sn;
  cn = flip * j.cn;
  return m;
}

// The branch is taken from the sign of cn(v), not from v alone: within ~1e-10 of ±K (near
// the separatrix) Boost's sn and cn may already be past the quarter period where v is not,
// and φ = am v past ±π/2 has S = ±S(2K) − (1/3) sn³ R_J(…) (S(π − φ) = S(2K) − S(φ)).
long double ExactRotation::periodic_S(long double u, const Jacobi& j, Evaluation how) const {
  Real sn, cn;
  const Real m = half_periods(u, j, sn, cn);
  const Real cn2 = cn * cn, dn2 = psi_kc2_ + k_ * k_ * cn2, sn2 = sn * sn;
  Real part = 0.0L;
  if (sn != 0.0L)
    part = sn * sn2 / 3.0L *
           (how == Evaluation::fast ? carlson_rj(cn2, dn2, 1.0L, 1.0L - char_n_ * sn2, std::abs(cn),
                                                 std::sqrt(dn2), 1.0L)
                                    : boost::math::ellint_rj(cn2, dn2, 1.0L, 1.0L - char_n_ * sn2));
  if (cn < 0.0L) part = (sn < 0.0L ? -psi_S_half_ : psi_S_half_) - part;
  return m * psi_S_half_ + part;
}

// S(u) from the nearest base point b of the table on [0, K] (docs/physics.md §8, "S from a base
// point"): with h = v − b, by the addition theorem (derived from Jacobi's for Π(u, a); the
// symmetric form is DLMF 19.26.9),
//   S(b + h) = S(b) + S(h) + atan(ρ X)/ρ,  X = sn b sn h sn v / P,
//   P = 1 − n sn² v + n sn b sn h cn v dn v,  ρ² = −n (k² − n)(1 − n),
// and sn h, cn h, dn h by the subtraction formulas (DLMF 22.8.1–22.8.3) over
// 1 − k² sn² v sn² b = cn² b + sn² b dn² v (positive terms). |h| ≤ half the table's step, so
// R_J(cn² h, dn² h, 1, 1 − n sn² h) has its arguments near 1 whatever k: a few duplication steps
// and no arctangent, where S(v) itself near |sn v| = 1 close to the separatrix took log₄(1/cn²)
// steps with an arctangent each. S is odd, so v < 0 is −S(−v).
long double ExactRotation::table_S(long double u, const Jacobi& j) const {
  Real sn, cn;
  const Real m = half_periods(u, j, sn, cn);
  const Real sign = sn < 0.0L ? -1.0L : 1.0L;
  const Real s = sign * sn, c = cn, d = std::sqrt(psi_kc2_ + k_ * k_ * c * c);
  const Real v = std::abs(u - m * 2.0L * K_);
  const int last = static_cast<int>(psi_base_.size()) - 1;
  const int index =
      std::min(last, static_cast<int>(static_cast<double>(v * psi_inverse_step_) + 0.5));
  const BasePoint& b = psi_base_[index];
  const Real inverse_D = 1 / (b.cn * b.cn + b.sn * b.sn * d * d);
  const Real sh = (s * b.cn * b.dn - b.sn * c * d) * inverse_D;
  const Real ch = (c * b.cn + s * d * b.sn * b.dn) * inverse_D;
  const Real dh = (d * b.dn + k_ * k_ * s * c * b.sn * b.cn) * inverse_D;
  const Real sh2 = sh * sh;
  const Real P = 1 - char_n_ * s * s + char_n_ * b.sn * sh * c * d;
  // P ≥ 1 at h = 0 and stayed above 0.6 for |h| ≤ 1/4 on 30,000 random bodies with moments over
  // twelve decades; should it come near 0 (the arctangent's branch), S(v) directly instead.
  if (!(P > 0.25L)) return periodic_S(u, j, Evaluation::fast);
  Real S_h = 0.0L;
  if (sh != 0.0L)
    S_h = sh * sh2 / 3.0L *
          carlson_rj(ch * ch, dh * dh, 1.0L, 1.0L - char_n_ * sh2, std::abs(ch), dh, 1.0L);
  const Real X = b.sn * sh * s / P;
  const Real S_v = b.S + S_h + X * carlson_rc1p(psi_rho2_ * X * X);
  return m * psi_S_half_ + sign * S_v;
}

// On the separatrix (k = 1, sn = tanh u) S is elementary: sn²/(1 − n sn²) = sinh²/(1 + a sinh²)
// with a = 1 − n, and with τ = tanh u and m = √(−n),
//   S(u) − S(u0) = (u − u0 − (A(u) − A(u0))/m) / a,   A(u) = atan(m τ)  (A/m → τ as m → 0),
// u − u0 = λt given as `du` (exact where u0 is infinite: ω0 with no cn component, so ω stays on
// axis 2 and S grows as λt/a).
// τ rounds to ±1 once |u| > ~22, where ω is still far from axis 2's, so A is formed from
// δ = 1 − |τ| = 2e^{−2|u|}/(1 + e^{−2|u|}): A(u) = ±(atan m − atan(m δ/(1 + m² |τ|))).
long double ExactRotation::separatrix_S(long double u, long double u_start, long double du) const {
  const Real m = std::sqrt(-char_n_);
  // atan(m x)/m, x for m = 0.
  auto atan_over_m = [m](Real x) { return m > 0.0L ? std::atan(m * x) / m : x; };
  // atan(m δ/(1 + m² |τ|))/m at |u|: what A(u)/m falls short of atan(m)/m.
  auto shortfall = [&](Real v) {
    const Real e = std::exp(-2.0L * std::abs(v)), delta = 2.0L * e / (1.0L + e);
    return atan_over_m(delta / (1.0L + m * m * (1.0L - delta)));
  };
  Real A_diff;  // (A(u) − A(u0))/m
  if ((u >= 0.0L) == (u_start >= 0.0L))
    A_diff = (u >= 0.0L ? 1.0L : -1.0L) * (shortfall(u_start) - shortfall(u));
  else
    A_diff = atan_over_m(std::tanh(u)) - atan_over_m(std::tanh(u_start));
  return (du - A_diff) / (1.0L - char_n_);
}

double ExactRotation::precession_angle(double t) const {
  check_horizon(t);
  if (case_ == ExactCase::steady) return static_cast<double>(rate_long_ * t);
  if (parts_ == ExactParts::omega_only)
    throw std::logic_error("ExactRotation: built for omega alone, it has no orientation");
  return static_cast<double>(precession_at(t, jacobi_at(t), Evaluation::fast, psi_S0_));
}

long double ExactRotation::precession_at(double t, const Jacobi& j, Evaluation how,
                                         long double S0) const {
  const Real u = phase(t);
  const Real dS = case_ == ExactCase::separatrix
                      ? separatrix_S(u, u0_, lambda_ * static_cast<Real>(t))
                      : (how == Evaluation::fast ? table_S(u, j) : periodic_S(u, j, how)) - S0;
  return psi_rate_ * static_cast<Real>(t) + psi_gain_ * dS;
}

}  // namespace bookspin::physics
