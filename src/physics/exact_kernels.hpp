#pragma once
// The long-double kernels of the exact motion's evaluation (exact_solution.cpp, docs/physics.md
// §8, "How the code evaluates ω(t)"): sine and cosine, the arctangent, Carlson's R_C and R_J,
// each to about 1e-19 relative, faster than glibc's and Boost's on the arguments they get.
// Inline: they are the inner loop of every row.
#include <array>
#include <cmath>
#include <numbers>

namespace bookspin::physics::exact_kernels {

// Boost's Jacobi functions evaluated in double lose up to ~1e-13 even on a reduced argument;
// in long double (Boost's default promotion) they are good to ~1e-17, at ~2 µs a call.
using Real = long double;

/// 1/n! for n = 0…22 (n! itself is exact in long double up to 25!).
inline constexpr std::array<Real, 23> kInverseFactorial = [] {
  std::array<Real, 23> inverse{};
  Real factorial = 1;
  for (int n = 0; n < 23; ++n) {
    if (n > 0) factorial *= n;
    inverse[n] = 1 / factorial;
  }
  return inverse;
}();

/// sin v and cos v for 0 ≤ v ≤ 8 in long double: v less the nearest multiple j of π/2 (π/2 in
/// two parts, the first's product with j exact), then Taylor series on |r| ≤ π/4 to r²¹ and
/// r²², whose next terms are below 1e-23 relative. glibc's sincosl reduces every argument by
/// Payne–Hanek, which cost more than the rest of a row.
inline void sin_cos(Real v, Real& sin_v, Real& cos_v) {
  constexpr Real kHalfPiHi = 1.5707963267341256141662597656250L;              // 32 significant bits
  constexpr Real kHalfPiLo = 6.077100506506192601475144209858469968755e-11L;  // π/2 − kHalfPiHi
  // Rounded through a double: a long double's conversion to an integer sets the x87 control
  // word twice, which costs more than the series (any j within one of v/(π/2) would do).
  const long quadrant =
      static_cast<long>(static_cast<double>(v * (2 / std::numbers::pi_v<Real>)) + 0.5);
  const Real j = static_cast<Real>(quadrant);
  const Real r = (v - j * kHalfPiHi) - j * kHalfPiLo, r2 = r * r;
  Real s = kInverseFactorial[21];
  for (int n = 19; n >= 1; n -= 2) s = kInverseFactorial[n] - r2 * s;
  const Real sin_r = r * s;
  Real c = kInverseFactorial[22];
  for (int n = 20; n >= 0; n -= 2) c = kInverseFactorial[n] - r2 * c;
  const Real cos_r = c;
  switch (quadrant & 3) {
    case 0:
      sin_v = sin_r, cos_v = cos_r;
      break;
    case 1:
      sin_v = cos_r, cos_v = -sin_r;
      break;
    case 2:
      sin_v = -sin_r, cos_v = -cos_r;
      break;
    default:
      sin_v = -cos_r, cos_v = sin_r;
      break;
  }
}

/// atan x for x ≥ 0: atan x = π/2 − atan(1/x) above 1, then atan x = atan c + atan y with c
/// the nearest multiple of 1/8 (its arctangent tabulated), y = (x − c)/(1 + x c), |y| ≤ 1/16
/// (x − c exact), and atan y's Taylor series to y¹⁷ (next term below 1e-22 relative).
inline Real atan_nonnegative(Real x) {
  static constexpr std::array<Real, 9> kAtanEighths{0.0L,
                                                    0.124354994546761435031354849164L,
                                                    0.244978663126864154172082481211L,
                                                    0.358770670270572220395920063926L,
                                                    0.463647609000806116214256231461L,
                                                    0.558599315343562435971508216402L,
                                                    0.643501108793284386802809228717L,
                                                    0.718829999621624505417014151526L,
                                                    0.78539816339744830961566084582L};
  const bool inverted = x > 1;
  if (inverted) x = 1 / x;
  const int j = static_cast<int>(static_cast<double>(x) * 8 + 0.5);  // a double: see sin_cos
  const Real c = j / 8.0L, y = (x - c) / (1 + x * c), y2 = y * y;
  Real series = 1.0L / 17;
  for (int n = 15; n >= 1; n -= 2) series = 1.0L / n - y2 * series;
  const Real angle = kAtanEighths[j] + y * series;
  return inverted ? std::numbers::pi_v<Real> / 2 - angle : angle;
}

/// R_C(1, 1 + e) = atan(√e)/√e for e ≥ 0 (DLMF 19.2.19); below 1e-3 its series
/// Σ (−e)^j/(2j + 1), whose eighth term is under 1e-25.
inline Real carlson_rc1p(Real e) {
  if (e >= 1e-3L) {
    const Real r = std::sqrt(e);
    return atan_nonnegative(r) / r;
  }
  return 1 -
         e * (1.0L / 3 -
              e * (1.0L / 5 -
                   e * (1.0L / 7 - e * (1.0L / 9 - e * (1.0L / 11 - e * (1.0L / 13 - e / 15))))));
}

/// Carlson's R_J(x, y, z, p) for x, y, z ≥ 0, at most one of them 0, and p ≥ max(x, y, z), so
/// that every R_C of the duplication has a nonnegative argument: the duplication of DLMF
/// 19.36(i) with the seventh-order series of Boost.Math's ellint_rj, which it follows step for
/// step, but each R_C(1, 1 + E_m) by its series once E_m (falling 64-fold per step) is small,
/// and A^{−3/2} by a square root rather than pow: an arctangent only while E_m ≥ 1e-3, the
/// first step or two (near |sn| = 1 close to the separatrix, where x and y are both tiny, a few
/// more: docs/physics.md §8). It stops once the series' truncation, of the order of Q_m⁸ (Q_m the
/// arguments' spread about their mean after m steps, relative), is below 10 ε of x86's long double
/// (2⁻⁶³, its 64-bit significand's), still a hundred times below a double's ε (Boost asks ε/5: one
/// step more, a fifth of the time). That ε is fixed, not the compiler's long double's: in
/// WebAssembly long double is binary128 (ε = 2⁻¹¹²), in software, and asking 10⁻¹⁵ more of the
/// series took three steps more a call (docs/performance-build.md, "The npm package against the
/// command line"). rx, ry, rz are √x, √y, √z, which the caller has at hand.
inline Real carlson_rj(Real x, Real y, Real z, Real p, Real rx, Real ry, Real rz) {
  static const Real kQ = std::pow(10 * std::ldexp(Real{1}, -63), -1.0L / 8);
  Real A = (x + y + z + 2 * p) / 5;
  const Real A0 = A, x0 = x, y0 = y, z0 = z;
  Real delta = (p - x) * (p - y) * (p - z);
  const Real Q = kQ * std::max(std::max(std::abs(A - x), std::abs(A - y)),
                               std::max(std::abs(A - z), std::abs(A - p)));
  Real fmn = 1, rc_sum = 0;  // fmn = 4^−m
  for (int m = 0; m < 100; ++m) {
    const Real rp = std::sqrt(p);
    const Real inverse_D = 1 / ((rp + rx) * (rp + ry) * (rp + rz));
    rc_sum += fmn * inverse_D * carlson_rc1p(delta * inverse_D * inverse_D);
    const Real lambda = rx * ry + rx * rz + ry * rz;
    A = (A + lambda) / 4;
    fmn /= 4;
    if (fmn * Q < A) break;
    x = (x + lambda) / 4;
    y = (y + lambda) / 4;
    z = (z + lambda) / 4;
    p = (p + lambda) / 4;
    delta /= 64;
    rx = std::sqrt(x);
    ry = std::sqrt(y);
    rz = std::sqrt(z);
  }
  const Real f = fmn / A, X = f * (A0 - x0), Y = f * (A0 - y0), Z = f * (A0 - z0);
  const Real P = (-X - Y - Z) / 2;
  const Real E2 = X * Y + X * Z + Y * Z - 3 * P * P;
  const Real E3 = X * Y * Z + 2 * E2 * P + 4 * P * P * P;
  const Real E4 = (2 * X * Y * Z + E2 * P + 3 * P * P * P) * P;
  const Real E5 = X * Y * Z * P * P;
  const Real series = 1 - 3 * E2 / 14 + E3 / 6 + 9 * E2 * E2 / 88 - 3 * E4 / 22 - 9 * E2 * E3 / 52 +
                      3 * E5 / 26 - E2 * E2 * E2 / 16 + 3 * E3 * E3 / 40 + 3 * E2 * E4 / 20 +
                      45 * E2 * E2 * E3 / 272 - 9 * (E3 * E4 + E2 * E5) / 68;
  return fmn / (A * std::sqrt(A)) * series + 6 * rc_sum;
}

}  // namespace bookspin::physics::exact_kernels
