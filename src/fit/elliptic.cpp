#include "fit/elliptic.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace bookspin::fit {

JacobiAgm::JacobiAgm(double k, double kc2) : k_(k), kc2_(std::min(kc2, 1.0)) {
  // k'² a rounding above 1 (a tiny k formed from the motion's invariants) is 1.
  if (!(k >= 0.0 && k < 1.0 && kc2 > 0.0 && kc2 <= 1.0 + 1e-12))
    throw std::invalid_argument("JacobiAgm: the modulus must lie in [0, 1)");
  kc2 = kc2_;
  // The AGM scale (Abramowitz & Stegun 16.4, 17.6): c_n = c_{n−1}²/(4 a_n) rather than
  // (a_{n−1} − b_{n−1})/2, which cancels as a and b meet.
  double a = 1.0, b = std::sqrt(kc2), c = k;
  a_[0] = a;
  c_[0] = c;
  double sum = 0.0, power = 1.0;  // ½ Σ_{n≥1} 2^n c_n²
  int n = 0;
  while (c > std::numeric_limits<double>::epsilon() * 0.25 * a) {
    if (n == kMaxSteps) throw std::invalid_argument("JacobiAgm: the AGM did not converge");
    const double next_a = 0.5 * (a + b);
    b = std::sqrt(a * b);
    c = c * c / (4.0 * next_a);
    a = next_a;
    ++n;
    a_[n] = a;
    c_[n] = c;
    power *= 2.0;
    sum += 0.5 * power * c * c;
  }
  steps_ = n;
  K_ = std::numbers::pi / (2.0 * a);
  e_minus_kc2_ = 0.5 * k * k - sum;
}

JacobiAgm::Values JacobiAgm::operator()(double u) const {
  const double period = 4.0 * K_;
  const double r = u - period * std::floor(u / period);
  // φ_N = 2^N a_N u, then down to φ_0 (A&S 16.4); Z = Σ_{n≥1} c_n sin φ_n (A&S 17.6).
  double phi = std::ldexp(a_[steps_], steps_) * r;
  double zeta = 0.0;
  for (int n = steps_; n >= 1; --n) {
    const double s = std::sin(phi);
    zeta += c_[n] * s;
    phi = 0.5 * (phi + std::asin(c_[n] / a_[n] * s));
  }
  Values v;
  v.sn = std::sin(phi);
  v.cn = std::cos(phi);
  // dn² = k'² + k² cn² adds positive terms (cos φ0 / cos(φ1 − φ0) loses digits near u = K).
  v.dn = std::sqrt(kc2_ + k_ * k_ * v.cn * v.cn);
  v.zeta = zeta;
  return v;
}

}  // namespace bookspin::fit
