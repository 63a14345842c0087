#pragma once
// The exact motion's property over its whole input space (docs/physics.md §8, "How far in
// time"), shared by the seeded test (tests/physics/exact_fuzz_test.cpp) and the libFuzzer target
// (tests/fuzz/exact_fuzzer.cpp): for any moments, ω0 and t, physics::ExactRotation either gives
// a finite state that keeps its invariants, or refuses for its true cause: a bad argument
// (std::invalid_argument), an energy, |L| or largest |ω| beyond a double (its energy(),
// angular_momentum_norm() or peak_rate() not finite, as the doors refuse it), or a t past its time
// horizon (ExactHorizonError). The causes are judged here independently of the code under test: the
// overflow from the invariants summed in long double, the horizon against the bounds
// |L|/I_max ≤ every angle's rate ≤ |L|/I_min (ψ̇ lies between |L|/I_c and |L|/I_s; λ ≤ |L|/I_1
// from §8's formulas; a steady |ω0| between the two).
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "physics/exact_solution.hpp"

namespace bookspin::test_support {

/// One drawn input: moments, ω0 and the times to evaluate.
struct ExactInput {
  Eigen::Vector3d moments;
  Eigen::Vector3d omega0;
  std::vector<double> t;
};

inline std::string describe(const ExactInput& in) {
  std::ostringstream s;
  s.precision(17);
  s << "moments (" << in.moments.transpose() << "), omega0 (" << in.omega0.transpose() << "), t:";
  for (double t : in.t) s << ' ' << t;
  return s.str();
}

/// Independent invariants in long double: |L| and E of the start.
struct LongInvariants {
  long double L = 0.0L, E = 0.0L;
};
inline LongInvariants long_invariants(const Eigen::Vector3d& I, const Eigen::Vector3d& w) {
  LongInvariants v;
  long double L2 = 0.0L;
  for (int i = 0; i < 3; ++i) {
    const long double Li = static_cast<long double>(I[i]) * w[i];
    L2 += Li * Li;
    v.E += 0.5L * static_cast<long double>(I[i]) * w[i] * w[i];
  }
  v.L = std::sqrt(L2);
  return v;
}

/// Bounds on the largest |ω| of the motion, in long double: |ω0| below, and above
/// √Σ_i min(2E/I_i, L²/I_i²) (each ½I_iω_i² ≤ E and |I_iω_i| ≤ |L|).
struct PeakRateBounds {
  long double start = 0.0L, upper = 0.0L;
};
inline PeakRateBounds peak_rate_bounds(const Eigen::Vector3d& I, const Eigen::Vector3d& w,
                                       const LongInvariants& inv) {
  long double upper2 = 0.0L, start2 = 0.0L;
  for (int i = 0; i < 3; ++i) {
    const long double I_i = I[i], by_L = inv.L / I_i;
    upper2 += std::min(2 * inv.E / I_i, by_L * by_L);
    start2 += static_cast<long double>(w[i]) * w[i];
  }
  return {std::sqrt(start2), std::sqrt(upper2)};
}

/// Whether `s` (at t = 0) is the identity and ω0 to rounding, for any body: q = (1, 0, 0, 0)
/// within 1e-12 and each component of ω within 2 ε |ω0| (docs/physics.md §8, "The phase by
/// quarter periods": the phase's offset from its nearest quarter period is carried on its own, so
/// a component a hair from a zero of its Jacobi function keeps its digits however far its
/// amplitude lies above it; moments 1e-50, 1, 1e50 gave ω_x(0) = −25083 for 1), and E, |L| and
/// |ω| within 8 ε of the invariants summed in long double.
inline bool starts_at(const physics::ExactState& s, const ExactInput& in,
                      const LongInvariants& inv) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  // Rounding below the normal range is absolute: a subnormal's last place is denorm_min, and
  // ε |ω0| underflows to 0 there (|ω0| = 5e-310: two stableNorm()s of one vector differed by it).
  constexpr double last_place = std::numeric_limits<double>::denorm_min();
  if (std::abs(s.q[0] - 1.0) > 1e-12) return false;
  const double size = in.omega0.stableNorm();
  for (int i = 0; i < 3; ++i)
    if (std::abs(s.omega_body[i] - in.omega0[i]) > std::max(2 * eps * size, 2 * last_place))
      return false;
  if (std::abs(s.omega_body.stableNorm() - size) > std::max(8 * eps * size, 8 * last_place))
    return false;
  // (Where they are normal doubles: E and |L| of ω0 as small as 1e-300 underflow.)
  if (inv.E > 1e-290L && std::abs(s.E / static_cast<double>(inv.E) - 1.0) > 8 * eps) return false;
  if (inv.L > 1e-290L && std::abs(s.L.stableNorm() / static_cast<double>(inv.L) - 1.0) > 8 * eps)
    return false;
  return true;
}

/// "" where the property holds for `in`, else what broke. `max_rows` bounds the states
/// evaluated (the fuzzer's time per input).
inline std::string check_exact_property(const ExactInput& in) {
  const Eigen::Vector3d& I = in.moments;
  const Eigen::Vector3d& w = in.omega0;
  const bool valid = I.allFinite() && (I.array() > 0.0).all() && w.allFinite();
  std::optional<physics::ExactRotation> exact;
  try {
    exact.emplace(I, w);
  } catch (const std::invalid_argument&) {
    if (valid) return "refused valid arguments as invalid: " + describe(in);
    return {};
  }
  if (!valid) return "accepted an invalid argument: " + describe(in);
  const LongInvariants inv = long_invariants(I, w);
  // Beyond a double: the doors refuse by energy() and angular_momentum_norm() (within a part in
  // 1e12 of DBL_MAX either answer is right).
  const long double top = DBL_MAX;
  const bool over = inv.E > top * (1 + 1e-12L) || inv.L > top * (1 + 1e-12L);
  const bool under = inv.E < top * (1 - 1e-12L) && inv.L < top * (1 - 1e-12L);
  // Past a double the doors refuse by peak_rate().
  const auto [start, upper] = peak_rate_bounds(I, w, inv);
  const bool rate_over = start > top * (1 + 1e-12L);
  const bool rate_under = upper < top * (1 - 1e-12L);
  const bool reported = !std::isfinite(exact->energy()) ||
                        !std::isfinite(exact->angular_momentum_norm()) ||
                        !std::isfinite(exact->peak_rate());
  if ((over || rate_over) && !reported)
    return "an energy, |L| or |ω| beyond a double not reported: " + describe(in);
  if (under && rate_under && reported)
    return "a finite energy, |L| and |ω| reported overflowing: " + describe(in);
  if (reported) return {};
  const double peak = exact->peak_rate();
  if (peak < static_cast<double>(start * (1 - 1e-9L)) ||
      peak > static_cast<double>(upper * (1 + 1e-9L))) {
    std::ostringstream s;
    s.precision(17);
    s << "largest |ω| " << peak << " outside [" << static_cast<double>(start) << ", "
      << static_cast<double>(upper) << "]: " << describe(in);
    return s.str();
  }
  // The horizon between the two bounds (a part in 1e9 for u0 and rounding).
  const double I_min = I.minCoeff(), I_max = I.maxCoeff();
  const long double max_angle = physics::kExactMaxAngle;
  const double horizon = exact->time_horizon();
  if (inv.L > 0.0L) {
    const long double low = max_angle * I_min / inv.L, high = max_angle * I_max / inv.L;
    // (As doubles: past 1.8e308 a bound is infinite, as the horizon then is.)
    if (horizon < static_cast<double>(low * (1 - 1e-9L)) ||
        horizon > static_cast<double>(high * (1 + 1e-9L))) {
      std::ostringstream s;
      s << "horizon " << horizon << " outside [" << static_cast<double>(low) << ", "
        << static_cast<double>(high) << "]: " << describe(in);
      return s.str();
    }
  } else if (!std::isinf(horizon)) {
    return "a body at rest has a finite horizon: " + describe(in);
  }
  for (double t : in.t) {
    if (!std::isfinite(t)) continue;  // the doors refuse it before the core sees it
    physics::ExactState s;
    try {
      s = exact->state(t);
    } catch (const physics::ExactHorizonError& e) {
      if (std::abs(t) <= horizon) return "refused a t within the horizon: " + describe(in);
      const std::string what = e.what();
      if (what.find("time horizon") == std::string::npos || what.find("t = ") != 0)
        return "a horizon refusal that does not say so: " + what;
      continue;
    }
    if (!(std::abs(t) <= horizon)) return "evaluated a t beyond the horizon: " + describe(in);
    std::ostringstream why;
    why.precision(17);
    const bool finite = s.q.allFinite() && s.omega_body.allFinite() && s.omega_world.allFinite() &&
                        s.L.allFinite() && std::isfinite(s.E) && s.t == t;
    if (!finite) {
      why << "a row not finite at t = " << t;
    } else if (std::abs(s.q.norm() - 1.0) > 1e-12) {
      why << "|q| = " << s.q.norm() << " at t = " << t;
    } else if (s.omega_body.stableNorm() > peak * (1 + 1e-9) + 1e-300) {
      why << "|ω| = " << s.omega_body.stableNorm() << " above its largest, " << peak
          << ", at t = " << t;
    } else if (inv.E > 1e-280L && std::abs(s.E / static_cast<double>(inv.E) - 1.0) > 1e-9) {
      why << "E = " << s.E << ", not " << static_cast<double>(inv.E) << " at t = " << t;
    } else if (inv.L > 1e-280L &&
               std::abs(s.L.stableNorm() / static_cast<double>(inv.L) - 1.0) > 1e-9) {
      why << "|L| = " << s.L.stableNorm() << ", not " << static_cast<double>(inv.L)
          << " at t = " << t;
    } else if (t == 0.0 && !starts_at(s, in, inv)) {
      why << "the start is not ω0 at the identity: ω = " << s.omega_body.transpose();
    }
    if (!why.str().empty()) return why.str() + ": " + describe(in);
  }
  return {};
}

/// A value drawn from the whole double range: sign, then a power of ten uniform in [lo, hi].
inline double log_uniform(std::mt19937_64& rng, double lo_exp, double hi_exp) {
  std::uniform_real_distribution<double> e(lo_exp, hi_exp);
  return std::pow(10.0, e(rng));
}

/// One seeded input: moments across 1e-300…1e300 (or within a few decades of each other),
/// near-symmetric bodies (two moments a relative 1e-16…1e-3 apart), ω0 of either sign from
/// 1e-300 to 1e6 (some components 0), on the separatrix (L² = 2E·I2) for some, and times
/// across ±1e-300…1e300, near the horizon and 0.
inline ExactInput draw_exact_input(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> pick(0, 9);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  ExactInput in;
  const int body = pick(rng);
  const double base = log_uniform(rng, -300, 300);
  for (int i = 0; i < 3; ++i)
    in.moments[i] =
        body < 3 ? log_uniform(rng, -300, 300) : base * (1.0 + (body < 6 ? unit(rng) * 3.0 : 0.0));
  if (body >= 6) {  // near-symmetric: one moment a hair from another
    const int a = pick(rng) % 3;
    in.moments[a] = in.moments[(a + 1) % 3] * (1.0 + log_uniform(rng, -16, -3));
    in.moments[(a + 2) % 3] *= 0.5 + unit(rng) * 3.0;
  }
  const double scale = log_uniform(rng, -300, 6);
  for (int i = 0; i < 3; ++i) {
    const int kind = pick(rng);
    double w = kind == 0 ? 0.0 : scale * (kind < 7 ? unit(rng) : log_uniform(rng, -20, 0));
    if (pick(rng) < 5) w = -w;
    in.omega0[i] = std::clamp(w, -1e6, 1e6);
  }
  if (pick(rng) < 2) {  // onto the separatrix: I3(I3 − I2) ω3² = I1(I2 − I1) ω1² (sorted axes)
    std::array<int, 3> axis{0, 1, 2};
    std::sort(axis.begin(), axis.end(),
              [&](int a, int b) { return in.moments[a] < in.moments[b]; });
    const double I1 = in.moments[axis[0]], I2 = in.moments[axis[1]], I3 = in.moments[axis[2]];
    const double ratio = std::sqrt(I1 * (I2 - I1) / (I3 * (I3 - I2)));
    if (std::isfinite(ratio) && ratio > 0.0)
      in.omega0[axis[2]] = std::copysign(std::abs(in.omega0[axis[0]]) * ratio, in.omega0[axis[2]]);
  }
  const int times = 1 + pick(rng) % 4;
  for (int n = 0; n < times; ++n) {
    const int kind = pick(rng);
    double t = kind == 0 ? 0.0 : log_uniform(rng, -300, 300);
    if (kind >= 7) {  // about the horizon's bound: |t| |L|/I within a decade of 2^40
      const LongInvariants inv = long_invariants(in.moments, in.omega0);
      const double rate = static_cast<double>(inv.L) / in.moments.minCoeff();
      if (rate > 0.0 && std::isfinite(rate))
        t = physics::kExactMaxAngle / rate * log_uniform(rng, -1, 1);
    }
    if (pick(rng) < 5) t = -t;
    in.t.push_back(t);
  }
  return in;
}

}  // namespace bookspin::test_support
