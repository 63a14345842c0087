// The exact motion at the edges of what its doors accept (docs/physics.md §8, "The phase by
// quarter periods", "How far in time"): ω(0) = ω0, E, |L| and |ω| at t = 0 to rounding and every
// row's invariants for bodies whose moments spread across the doors' whole range, in every order;
// and the largest |ω| it reports (ExactRotation::peak_rate) is the one it reaches.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "physics/exact_solution.hpp"
#include "support/exact_motion_property.hpp"

namespace bookspin::physics {
namespace {

using test_support::check_exact_property;
using test_support::ExactInput;

constexpr double kEps = std::numeric_limits<double>::epsilon();

/// `v` with its components in the order `p` (p[i] is the index of v taken as component i).
Eigen::Vector3d permuted(const Eigen::Vector3d& v, const std::array<int, 3>& p) {
  return {v[p[0]], v[p[1]], v[p[2]]};
}

/// The six orders of three axes.
std::vector<std::array<int, 3>> every_order() {
  std::array<int, 3> p{0, 1, 2};
  std::vector<std::array<int, 3>> orders;
  do orders.push_back(p);
  while (std::next_permutation(p.begin(), p.end()));
  return orders;
}

/// Each component of ω(0) within 2 ε |ω0| of ω0's.
::testing::AssertionResult starts_at_omega0(const ExactRotation& exact, const Eigen::Vector3d& w0) {
  const Eigen::Vector3d w = exact.state(0.0).omega_body;
  for (int i = 0; i < 3; ++i)
    if (!(std::abs(w[i] - w0[i]) <= 2 * kEps * w0.norm()))
      return ::testing::AssertionFailure()
             << "omega(0) = (" << w.transpose() << ") for omega0 (" << w0.transpose() << ")";
  return ::testing::AssertionSuccess();
}

// The held-out case: moments 1e-50, 1, 1e50 and ω0 = (1, 0.1, 0.05) gave ω_x(0) = −25083 (with
// 1e∓300: −2.5e129), finite, with E and L that looked right. ω0 lies 1e-24 of the cn axis'
// amplitude from a zero of cn, which u0 as one long double (≈ K − 1e-24) could not hold.
TEST(ExactEdges, TheWideBodyOfTheHeldOutCaseStartsAtOmega0InEveryOrder) {
  const Eigen::Vector3d w0(1.0, 0.1, 0.05);
  for (double spread : {1e50, 1e300}) {
    const Eigen::Vector3d moments(1.0 / spread, 1.0, spread);
    for (const auto& p : every_order()) {
      const Eigen::Vector3d I = permuted(moments, p), w = permuted(w0, p);
      const ExactRotation exact(I, w);
      EXPECT_TRUE(starts_at_omega0(exact, w)) << "moments " << I.transpose();
      // E, |L| at the start and rows across the horizon (the shared property: finite rows that
      // keep E, |L| and stay below the largest |ω|; the start ω0 at the identity).
      const double h = exact.time_horizon();
      const std::string broken = check_exact_property({I, w, {0.0, 1e-3 * h, -0.37 * h, h}});
      EXPECT_TRUE(broken.empty()) << broken;
    }
  }
}

// Bodies drawn log-uniformly to each door's limits, each in all six orders of its moments (with
// ω0 permuted alike: one motion, six labellings): the scenario's 1e-30…1e30 (flipcheck, the npm
// package, the page) and any positive double (bookspin.exact_motion, jobs::exact_motion_at),
// here 1e-300…1e300; ω0 of any direction (a component 0 or many orders below the others at
// times) and size 1e-300…1e6 (a scene's range); times from 0 to the horizon either side. Each
// must start at ω0 to rounding and keep its invariants on every row, or be refused for an energy,
// |L| or |ω| beyond a double (the property's judge of that is independent of the code).
TEST(ExactEdges, LogUniformBodiesToTheDoorsLimitsStartAtOmega0InEveryOrder) {
  std::mt19937_64 rng(88);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const double decades : {30.0, 300.0}) {
    int wide = 0, held = 0;
    for (int n = 0; n < 400; ++n) {
      Eigen::Vector3d moments, w0;
      for (int i = 0; i < 3; ++i) moments[i] = test_support::log_uniform(rng, -decades, decades);
      const double size = test_support::log_uniform(rng, -300, 6);
      for (int i = 0; i < 3; ++i) {
        const double kind = unit(rng);
        const double part =
            kind < 0.1 ? 0.0 : (kind < 0.3 ? test_support::log_uniform(rng, -20, 0) : unit(rng));
        w0[i] = (unit(rng) < 0.5 ? -1.0 : 1.0) * part;
      }
      if (w0.norm() == 0.0) w0[0] = 1.0;
      w0 *= size / w0.norm();
      for (const auto& p : every_order()) {
        const Eigen::Vector3d I = permuted(moments, p), w = permuted(w0, p);
        const ExactRotation exact(I, w);
        std::vector<double> times{0.0};
        const double h = exact.time_horizon();
        for (int k = 0; k < 3; ++k) {
          const double t =
              std::isfinite(h) ? h * test_support::log_uniform(rng, -12, 0) : unit(rng);
          times.push_back(k == 1 ? -t : t);
        }
        const std::string broken = check_exact_property({I, w, times});
        ASSERT_TRUE(broken.empty()) << "body " << n << ", " << decades << " decades: " << broken;
        if (std::isfinite(exact.energy()) && std::isfinite(exact.peak_rate())) {
          ++held;
          EXPECT_TRUE(starts_at_omega0(exact, w)) << "moments " << I.transpose();
          if (I.maxCoeff() > 1e20 * I.minCoeff()) ++wide;
        }
      }
    }
    // Not only near the unit body: most of the draws spread their moments beyond 1e20, where
    // ω(0) went wrong before (104 of 400 bodies over 1e-30…1e30).
    EXPECT_GT(held, 2000) << decades;
    EXPECT_GT(wide, decades > 100 ? 1500 : 600) << decades;
  }
}

// The largest |ω| (docs/physics.md §8): |ω|² = a_cn² + a_dn² + sn²(a_sn² − a_cn² − k²a_dn²) is
// linear in sn², so the peak is |ω| at an end of the polhode's segment, u = 0 (sn = 0) or u = K
// (sn² = 1). With a < b < c the sorted moments, the slope is (a − b)(c − a)(c − b)/(abc(c − a)·
// (c − b)) times d3 (case A) or d1 (case B), negative in both cases: the peak is at sn = 0, where
// ω lies in the plane of the cn and dn axes. Over bodies in every order, about either axis, on
// the separatrix and steady: peak_rate() equals |ω| evaluated at that end to rounding, the other
// end is not above it, and no |ω| sampled over a period exceeds it.
TEST(ExactEdges, TheLargestRateIsReachedAtTheEndOfThePolhodeSegmentWhereSnIsZero) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int about_largest = 0, about_smallest = 0, on_separatrix = 0, steady = 0;
  for (int n = 0; n < 1200; ++n) {
    Eigen::Vector3d moments, w0;
    for (int i = 0; i < 3; ++i) moments[i] = test_support::log_uniform(rng, -3, 3);
    for (int i = 0; i < 3; ++i) w0[i] = unit(rng) * test_support::log_uniform(rng, -2, 2);
    const int kind = n % 6;
    std::array<int, 3> axis{0, 1, 2};
    std::sort(axis.begin(), axis.end(), [&](int a, int b) { return moments[a] < moments[b]; });
    if (kind == 4) {  // onto the separatrix: I3(I3 − I2) ω3² = I1(I2 − I1) ω1² (sorted axes)
      const double I1 = moments[axis[0]], I2 = moments[axis[1]], I3 = moments[axis[2]];
      w0[axis[2]] = std::copysign(
          std::abs(w0[axis[0]]) * std::sqrt(I1 * (I2 - I1) / (I3 * (I3 - I2))), w0[axis[2]]);
    } else if (kind == 5) {  // a principal spin
      w0 = w0[axis[n % 3]] * Eigen::Vector3d::Unit(axis[n % 3]);
    }
    const ExactRotation exact(moments, w0);
    const double peak = exact.peak_rate();
    const std::string body = "moments " + std::to_string(moments[0]) + " " +
                             std::to_string(moments[1]) + " " + std::to_string(moments[2]);
    switch (exact.motion_case()) {
      case ExactCase::steady: {
        ++steady;
        EXPECT_NEAR(peak / w0.norm(), 1.0, 2 * kEps) << body;
        break;
      }
      case ExactCase::separatrix: {
        // sn = tanh u: its zero, where ω about the intermediate axis changes sign, bisected in t
        // from a bracket found by doubling (ω tends to that axis either way from it).
        ++on_separatrix;
        const int mid = axis[1];
        const auto sign_at = [&](double t) { return exact.omega_body(t)[mid] > 0.0; };
        double a = 0.0, b = 1.0 / peak;
        const bool s0 = sign_at(0.0);
        while (sign_at(b) == s0 && sign_at(-b) == s0) b *= 2;
        if (sign_at(-b) != s0) b = -b;
        for (int k = 0; k < 200 && a != b; ++k) {
          const double m = 0.5 * (a + b);
          if (m == a || m == b) break;
          (sign_at(m) == s0 ? a : b) = m;
        }
        EXPECT_NEAR(exact.omega_body(a).norm() / peak, 1.0, 8 * kEps) << body;
        for (int k = -1000; k <= 1000; ++k)
          EXPECT_LE(exact.omega_body(a + 40.0 * k / 1000.0 / exact.lambda()).norm(),
                    peak * (1 + 8 * kEps))
              << body;
        break;
      }
      default: {
        (exact.motion_case() == ExactCase::around_largest ? about_largest : about_smallest)++;
        const ExactOmegaForm form = exact.omega_form();
        const double end_zero = exact.omega_body(-form.u0 / form.lambda).norm();
        const double end_one = exact.omega_body((form.K - form.u0) / form.lambda).norm();
        EXPECT_NEAR(peak / end_zero, 1.0, 8 * kEps) << body;
        EXPECT_LE(end_one, peak * (1 + 8 * kEps)) << body;
        double sampled = 0.0;
        for (int k = 0; k < 1000; ++k)
          sampled = std::max(sampled, exact.omega_body(exact.period() * k / 1000.0).norm());
        EXPECT_LE(sampled, peak * (1 + 8 * kEps)) << body;
      }
    }
  }
  // Every branch, each many times.
  EXPECT_GT(about_largest, 150);
  EXPECT_GT(about_smallest, 150);
  EXPECT_GT(on_separatrix, 40);
  EXPECT_GT(steady, 100);
}

}  // namespace
}  // namespace bookspin::physics
