// ω̇ of the flight finder (docs/phone-lab.md, "How the flights are found"): the slope of a
// quadratic fitted by least squares to the samples within ±2 of each, or within ±5 ms where
// there are more. On ω = t³ sampled evenly at step h, a symmetric window of ±K samples gives
// the slope 3t² + h² Σk⁴/Σk² (the cubic's odd part projected on τ; k = 1..K), worked by hand:
// ±2 samples: Σk⁴/Σk² = 17/5 = 3.4; ±5 samples: 979/55 = 17.8. ω = t² and ω = t are exact.
// The steps are powers of two, so that which samples lie within 5 ms is never a rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "fit/flights.hpp"

namespace bookspin::fit {
namespace {

/// The rate at sample `at` of (t³, t², t) sampled every `h` s, `n` samples from t = 0.
Eigen::Vector3d rate_at(double h, int n, int at) {
  std::vector<double> t;
  std::vector<Eigen::Vector3d> omega;
  for (int i = 0; i < n; ++i) {
    const double ti = h * i;
    t.push_back(ti);
    omega.push_back(Eigen::Vector3d(ti * ti * ti, ti * ti, ti));
  }
  return omega_rate(t, omega)[at];
}

// 128 Hz (h = 2⁻⁷ s = 7.8 ms): no other sample within 5 ms, so ±2 samples.
TEST(RateWindow, AtOneHundredHertzItIsTwoSamplesEachSide) {
  const double h = std::ldexp(1.0, -7);
  const int at = 50;
  const double t = h * at;
  const Eigen::Vector3d rate = rate_at(h, 100, at);
  EXPECT_NEAR(rate[0], 3.0 * t * t + 3.4 * h * h, 1e-12);
  EXPECT_NEAR(rate[1], 2.0 * t, 1e-12);
  EXPECT_NEAR(rate[2], 1.0, 1e-12);
}

// 1024 Hz (h = 2⁻¹⁰ s = 0.98 ms): 5 h = 4.9 ms ≤ 5 ms < 6 h, so ±5 samples.
TEST(RateWindow, AtAKilohertzItIsEverySampleWithinFiveMilliseconds) {
  const double h = std::ldexp(1.0, -10);
  const int at = 500;
  const double t = h * at;
  const Eigen::Vector3d rate = rate_at(h, 1000, at);
  EXPECT_NEAR(rate[0], 3.0 * t * t + 17.8 * h * h, 1e-11);
  EXPECT_NEAR(rate[1], 2.0 * t, 1e-11);
  EXPECT_NEAR(rate[2], 1.0, 1e-11);
}

}  // namespace
}  // namespace bookspin::fit
