// How far in time the exact motion is evaluated (docs/physics.md §8, "How far in time"):
// ExactRotation's horizon and the reason it gives past it.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include "physics/exact_solution.hpp"

namespace bookspin::physics {

namespace {

/// `x`'s shortest round-trip text, for a message: the fewest significant digits (1 to 17) that
/// read back as `x` (printf's, since the page's emscripten libc++ has no floating to_chars).
std::string short_text(double x) {
  char text[40];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, x);
    if (std::strtod(text, nullptr) == x) break;
  }
  return text;
}

}  // namespace

// The largest |t| whose angles stay within kExactMaxAngle (docs/physics.md §8, "How far in
// time"): |u| ≤ λ|t| + |u0|, and ψ̇ lies between |L|/I_c and |L|/I_s (ψ(0) = 0), so
// |ψ(t)| ≤ max(|L|/I_c, |L|/I_s)·|t|.
void ExactRotation::set_horizon() {
  using Real = long double;
  const Real max_angle = kExactMaxAngle;
  Real horizon = std::numeric_limits<Real>::infinity();
  horizon_by_phase_ = false;
  if (case_ == ExactCase::steady) {
    if (rate_long_ > 0.0L) horizon = max_angle / rate_long_;
  } else {
    if (parts_ == ExactParts::omega_and_orientation)
      horizon = max_angle * std::min(I_[cn_axis_], I_[1]) / L_long_;
    if (case_ != ExactCase::separatrix) {
      const Real by_phase = (max_angle - std::abs(u0_)) / lambda_;
      if (by_phase < horizon) {
        horizon = by_phase;
        horizon_by_phase_ = true;
      }
    }
  }
  horizon_ = static_cast<double>(horizon);
}

std::string ExactRotation::horizon_reason(double t) const {
  const char* angle = case_ == ExactCase::steady
                          ? "the rotation angle |ω0|·t passes"
                          : (horizon_by_phase_ ? "the phase λt + u0 of ω's Jacobi functions passes"
                                               : "the precession angle ψ about L may pass");
  return "t = " + short_text(t) + " is beyond the exact motion's time horizon, |t| ≤ " +
         short_text(horizon_) + " time units for these moments and ω0: past it " + angle +
         " 2^40 ≈ 1.1e12 rad, more than a long double carries to 1e-6 rad";
}

}  // namespace bookspin::physics
