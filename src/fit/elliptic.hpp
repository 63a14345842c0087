#pragma once
// Jacobi's elliptic functions of one modulus in double precision by the arithmetic-geometric
// mean (docs/physics.md §8, "The fit's derivatives"), for the fit's millions of evaluations:
// physics::ExactRotation uses Boost's in long double (~2 µs a call), this ~0.2 µs.

#include <array>

namespace bookspin::fit {

/// sn, cn, dn and Jacobi's zeta function Z of modulus k at any real u.
/// Sources: Abramowitz & Stegun, Handbook of Mathematical Functions, 16.4 (sn, cn, dn by the
/// AGM scale: a0 = 1, b0 = k', c0 = k; φ_N = 2^N a_N u; sin(2φ_{n−1} − φ_n) = (c_n/a_n) sin φ_n;
/// sn = sin φ0, cn = cos φ0), 17.6 (K = π/(2 a_N); E/K = 1 − ½ Σ 2^n c_n²;
/// Z(u) = Σ_{n≥1} c_n sin φ_n).
class JacobiAgm {
 public:
  /// `k` in [0, 1) and `kc2` = 1 − k² (passed separately: near k = 1 it is known better than
  /// 1 − k² gives; a rounding above 1, up to 1 + 1e-12, is taken as 1). Throws
  /// std::invalid_argument outside 0 ≤ k < 1, or for kc2 ≤ 0 or beyond that.
  JacobiAgm(double k, double kc2);

  struct Values {
    double sn = 0.0, cn = 1.0, dn = 1.0;
    double zeta = 0.0;  ///< Z(u) = ℰ(u) − (E/K) u, period 2K
  };
  /// The functions at u (any real u; reduced modulo 4K first).
  Values operator()(double u) const;

  double K() const { return K_; }  ///< complete integral of the first kind K(k)
  /// E/K − k'², from the AGM's c_n without cancellation (½k² − ½ Σ_{n≥1} 2^n c_n²).
  double e_over_k_minus_kc2() const { return e_minus_kc2_; }
  double E_over_K() const { return e_minus_kc2_ + kc2_; }  ///< E(k)/K(k)

 private:
  static constexpr int kMaxSteps = 24;
  double k_ = 0.0, kc2_ = 1.0, K_ = 0.0, e_minus_kc2_ = 0.0;
  int steps_ = 0;  ///< N: c_N negligible
  std::array<double, kMaxSteps + 1> a_{}, c_{};
};

}  // namespace bookspin::fit
