#include "physics/exact_solution.hpp"

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace bookspin::physics {

namespace {

// Boost's Jacobi functions evaluated in double lose up to ~1e-13 even on a reduced argument;
// in long double (Boost's default promotion) they are good to ~1e-17, at ~2 µs a call.
using Real = long double;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
constexpr int kChebyshevDegree = 20;
constexpr int kFirstPanels = 8;
constexpr int kMaxPanels = 4096;
constexpr Real kPanelWidth = 0.3L;
// A panel is accepted when its last Chebyshev coefficients are this small relative to the
// integrand: the interpolant, and so ψ, is then accurate to about that relative level.
constexpr Real kTailTolerance = 1e-16L;

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

/// Rotation by ψ about the z axis.
Eigen::Matrix3d rotation_z(double psi) {
  const double c = std::cos(psi), s = std::sin(psi);
  Eigen::Matrix3d r;
  r << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, 1.0;
  return r;
}

/// The n + 1 Chebyshev points of the first kind on [−1, 1] and the cosines of the discrete
/// cosine transform that takes values there to Chebyshev coefficients, the same for every
/// panel: computed once per table (in long double each is a software cosine in WebAssembly).
struct ChebyshevBasis {
  explicit ChebyshevBasis(int n) : n(n), x(n + 1), cosines((n + 1) * (n + 1)) {
    const int points = n + 1;
    for (int m = 0; m < points; ++m)
      x[m] = std::cos(std::numbers::pi_v<Real> * (m + 0.5L) / points);
    for (int j = 0; j < points; ++j)
      for (int m = 0; m < points; ++m)
        cosines[j * points + m] = std::cos(std::numbers::pi_v<Real> * j * (m + 0.5L) / points);
  }
  int n;
  std::vector<Real> x, cosines;
};

/// Chebyshev coefficients c_0..c_n of the degree-n interpolant of f on [a, a + h] at the
/// n + 1 Chebyshev points of the first kind (f ≈ Σ c_j T_j(x), x ∈ [−1, 1]).
template <class F>
std::vector<Real> chebyshev_fit(F& f, Real a, Real h, const ChebyshevBasis& basis) {
  const int points = basis.n + 1;
  std::vector<Real> values(points);
  for (int m = 0; m < points; ++m) values[m] = f(a + 0.5L * (basis.x[m] + 1.0L) * h);
  std::vector<Real> c(points, 0.0L);
  for (int j = 0; j < points; ++j) {
    for (int m = 0; m < points; ++m) c[j] += values[m] * basis.cosines[j * points + m];
    c[j] *= 2.0L / points;
  }
  c[0] *= 0.5L;
  return c;
}

/// Coefficients (n + 2 of them) of ∫_{a}^{a + (x+1)h/2} f, given f's Chebyshev coefficients
/// c_0..c_n: ∫T_0 = T_1, ∫T_j = T_{j+1}/(2(j+1)) − T_{j−1}/(2(j−1)); the constant term makes
/// the antiderivative vanish at x = −1.
std::vector<Real> chebyshev_antiderivative(const std::vector<Real>& c, Real h) {
  const int n = static_cast<int>(c.size()) - 1;
  auto coeff = [&](int j) { return j <= n ? c[j] : 0.0L; };
  std::vector<Real> b(n + 2, 0.0L);
  b[1] = coeff(0) - 0.5L * coeff(2);
  for (int j = 2; j <= n + 1; ++j) b[j] = (coeff(j - 1) - coeff(j + 1)) / (2.0L * j);
  Real at_minus_one = 0.0L;
  for (int j = 1; j <= n + 1; ++j) at_minus_one += (j % 2 ? -b[j] : b[j]);
  b[0] = -at_minus_one;
  for (Real& v : b) v *= 0.5L * h;
  return b;
}

/// Σ a_j T_j(x) by Clenshaw's recurrence.
Real chebyshev_sum(const double* a, int count, Real x) {
  Real b1 = 0.0L, b2 = 0.0L;
  for (int j = count - 1; j >= 1; --j) {
    const Real b0 = a[j] + 2.0L * x * b1 - b2;
    b2 = b1;
    b1 = b0;
  }
  return a[0] + x * b1 - b2;
}

/// Tabulates ∫_0^w f for w ∈ [0, length] with `panels` equal panels; false if some panel's
/// Chebyshev tail is above tolerance.
template <class F>
bool fill_table(F& f, Real length, int panels, PrecessionTable& table) {
  table.degree = kChebyshevDegree;
  table.width = static_cast<double>(length / panels);
  table.start.assign(1, 0.0);
  table.coeffs.clear();
  const Real h = length / panels;
  bool converged = true;
  Real total = 0.0L;
  const ChebyshevBasis basis(kChebyshevDegree);
  for (int p = 0; p < panels; ++p) {
    const std::vector<Real> c = chebyshev_fit(f, p * h, h, basis);
    Real scale = 0.0L, tail = 0.0L;
    for (int j = 0; j <= kChebyshevDegree; ++j) scale = std::max(scale, std::abs(c[j]));
    for (int j = kChebyshevDegree - 2; j <= kChebyshevDegree; ++j)
      tail = std::max(tail, std::abs(c[j]));
    converged = converged && tail <= kTailTolerance * scale;
    const std::vector<Real> b = chebyshev_antiderivative(c, h);
    Real panel_integral = 0.0L;  // the antiderivative at x = 1, where every T_j is 1
    for (Real v : b) {
      table.coeffs.push_back(static_cast<double>(v));
      panel_integral += v;
    }
    total += panel_integral;
    table.start.push_back(static_cast<double>(total));
  }
  return converged;
}

/// The table of ∫_0^w f on [0, length], halving the panels until every panel converges.
template <class F>
PrecessionTable build_table(F&& f, Real length) {
  PrecessionTable table;
  // First guess: panels at most kPanelWidth wide in u (the integrand's singularities lie
  // about that far from the real axis for near-separatrix motion); refined below if needed.
  int first = kFirstPanels;
  while (first < kMaxPanels && length / first > kPanelWidth) first *= 2;
  for (int panels = first; panels <= kMaxPanels; panels *= 2)
    if (fill_table(f, length, panels, table)) break;
  return table;
}

/// ∫_0^w of the tabulated function, w ∈ [0, panels·width].
Real table_integral(const PrecessionTable& table, Real w) {
  const int count = table.degree + 2;
  const Real width = table.width;
  // fmax/fmin also send a NaN (from a non-finite t) to a valid panel before the int cast.
  const Real last = table.panels() - 1;
  const int p = static_cast<int>(std::fmin(std::fmax(std::floor(w / width), 0.0L), last));
  const Real x = std::clamp(2.0L * (w - p * width) / width - 1.0L, -1.0L, 1.0L);
  return table.start[p] + chebyshev_sum(table.coeffs.data() + p * count, count, x);
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
  L_norm_ = L_world_.norm();
  energy_ = 0.5 * omega0_body.dot(L_world_);
  const Eigen::Vector3d w = to_sorted_ * omega0_body;
  classify(w);
  if (case_ == ExactCase::steady) return;
  set_phase(w);
  if (case_ != ExactCase::separatrix && parts_ == ExactParts::omega_and_orientation) {
    table_ = build_table([this](Real u) { return precession_rate_u(u); }, 2.0L * K_);
    psi_half_ = table_.start.back();
    psi_u0_ = precession_integral(u0_);
  }
  anchor_ = (momentum_frame(I_.cwiseProduct(w)) * to_sorted_).transpose();
}

ExactRotation::ExactRotation(const Eigen::Vector3d& moments, const Eigen::Vector3d& omega0_body,
                             PrecessionTable table)
    : ExactRotation(moments, omega0_body, ExactParts::omega_only) {
  parts_ = ExactParts::omega_and_orientation;
  const bool needed = case_ != ExactCase::steady && case_ != ExactCase::separatrix;
  const bool shaped = table.degree >= 0 && table.panels() >= 1 && table.width > 0.0 &&
                      table.coeffs.size() == static_cast<std::size_t>(table.panels()) *
                                                 static_cast<std::size_t>(table.degree + 2);
  if (needed != shaped)
    throw std::invalid_argument(needed ? "ExactRotation: the precession table has the wrong shape"
                                       : "ExactRotation: this motion has no precession table");
  if (!needed) return;
  table_ = std::move(table);
  psi_half_ = table_.start.back();
  psi_u0_ = precession_integral(u0_);
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
  // so either case's form holds).
  if (case_ == ExactCase::separatrix || k2 >= 1.0L || kc2_ <= 0.0L) {
    case_ = ExactCase::separatrix;
    k_ = 1.0L;
    kc2_ = 0.0L;
  } else {
    k_ = std::sqrt(k2);
  }
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
    u0_ = std::asinh(sn0 / cn0);  // sn = tanh u, cn = sech u
    K_ = std::numeric_limits<Real>::infinity();
  } else {
    u0_ = boost::math::ellint_1(k_, std::atan2(sn0, cn0));  // u0 = F(am u0 | k)
    K_ = boost::math::ellint_1(k_);
  }
}

ExactRotation::Jacobi ExactRotation::jacobi(long double u) const {
  if (case_ != ExactCase::separatrix) {
    // Reduce to one period 4K first: the functions lose accuracy with the argument's size.
    const Real period = 4.0L * K_;
    u -= period * std::floor(u / period);
  }
  Jacobi j{};
  j.sn = boost::math::jacobi_elliptic(k_, u, &j.cn, &j.dn);
  // Boost forms dn as a ratio of two cosines that both vanish where cn = 0, losing digits
  // near u = K (where dn = k' is smallest); dn² = k'² + k² cn² adds positive terms instead.
  j.dn = std::sqrt(kc2_ + k_ * k_ * j.cn * j.cn);
  return j;
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
  if (case_ == ExactCase::steady) return omega0_;
  return to_sorted_.transpose() * sorted_omega(jacobi(phase(t)));
}

Eigen::Vector3d ExactRotation::omega_dot_body(double t) const {
  if (case_ == ExactCase::steady) return Eigen::Vector3d::Zero();
  const Jacobi j = jacobi(phase(t));
  Eigen::Vector3d w_dot;
  w_dot[cn_axis_] = static_cast<double>(-amplitude_[cn_axis_] * lambda_ * j.sn * j.dn);
  w_dot[1] = static_cast<double>(amplitude_[1] * lambda_ * j.cn * j.dn);
  w_dot[dn_axis_] = static_cast<double>(-amplitude_[dn_axis_] * lambda_ * k_ * k_ * j.sn * j.cn);
  return to_sorted_.transpose() * w_dot;
}

Eigen::Vector3d ExactRotation::angular_momentum_body(double t) const {
  return moments_.cwiseProduct(omega_body(t));
}

// dψ/du = ψ̇/λ with ψ̇ = |L| Σ_{i≠r} I_i ω_i² / Σ_{i≠r} I_i² ω_i² (r = dn axis). The two
// other axes carry cn and sn, so the rate depends on sn² only and has period 2K in u.
long double ExactRotation::precession_rate_u(long double u) const {
  const Jacobi j = jacobi(u);
  const Real Ic = I_[cn_axis_], Is = I_[1];
  const Real wc2 = amplitude_[cn_axis_] * amplitude_[cn_axis_] * j.cn * j.cn;
  const Real ws2 = amplitude_[1] * amplitude_[1] * j.sn * j.sn;
  return L_norm_ * (Ic * wc2 + Is * ws2) / ((Ic * Ic * wc2 + Is * Is * ws2) * lambda_);
}

// ∫_0^u dψ/du, by whole periods 2K plus the table on the remainder.
long double ExactRotation::precession_integral(long double u) const {
  const Real period = 2.0L * K_;
  const Real n = std::floor(u / period);
  return n * psi_half_ + table_integral(table_, u - n * period);
}

double ExactRotation::precession_angle(double t) const {
  if (case_ == ExactCase::steady) return omega0_.norm() * t;
  if (parts_ == ExactParts::omega_only)
    throw std::logic_error("ExactRotation: built for omega alone, it has no orientation");
  if (case_ == ExactCase::separatrix) {
    // Not periodic: adaptive Gauss–Kronrod over [u0, u(t)] (slow, but a measure-zero case).
    const Real u = phase(t);
    auto rate = [this](Real v) { return precession_rate_u(v); };
    using Quadrature = boost::math::quadrature::gauss_kronrod<Real, 31>;
    if (!std::isfinite(u)) return std::numeric_limits<double>::quiet_NaN();
    if (u == u0_) return 0.0;
    const Real lo = std::min(u0_, u), hi = std::max(u0_, u);
    const Real integral = Quadrature::integrate(rate, lo, hi, 20, 1e-15L);
    return static_cast<double>(u >= u0_ ? integral : -integral);
  }
  return static_cast<double>(precession_integral(phase(t)) - psi_u0_);
}

// P: rows are the momentum frame's axes in sorted body coordinates. z = L/|L|,
// y = (L × e_r)/|L × e_r| (its components are ±L_i or 0, so no cancellation), x = y × z.
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

Eigen::Matrix3d ExactRotation::orientation(double t) const {
  if (case_ == ExactCase::steady) {
    const double rate = omega0_.norm();
    if (rate == 0.0) return Eigen::Matrix3d::Identity();
    return Eigen::AngleAxisd(rate * t, omega0_ / rate).toRotationMatrix();
  }
  const Eigen::Vector3d L_sorted = I_.cwiseProduct(sorted_omega(jacobi(phase(t))));
  return rotation_from(L_sorted, precession_angle(t));
}

double ExactRotation::period() const {
  if (case_ == ExactCase::steady || case_ == ExactCase::separatrix) return kInfinity;
  return static_cast<double>(4.0L * K_ / lambda_);
}

double ExactRotation::flip_period() const { return 0.5 * period(); }

}  // namespace bookspin::physics
