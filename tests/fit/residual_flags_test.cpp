// The flags' noise floor (docs/phone-lab.md, "Flags"): a 50 ms block of the residual is a knock
// only when its RMS |r| is over four times the flight's median block and over the gyroscope's
// scatter at rest, 5σ per component (|r| = 5√3 σ). Hand-made noise: σ = 0.02 rad/s at rest,
// 0.002 rad/s in flight, and a 0.1 s burst in the middle of one flight: ±b on each component,
// alternating from sample to sample (no smooth motion can follow it), so its |r| is √3·b.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "fit/flights.hpp"
#include "fit/pool.hpp"
#include "fit/recording.hpp"
#include "fit/toss_fit.hpp"
#include "real_recordings.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

constexpr double kRestSigma = 0.02;     // rad/s per component, at rest
constexpr double kFlightSigma = 0.002;  // rad/s per component, in flight

/// Three noiseless flights of a phone on a book; at rest (|ω − bias| < 0.25 rad/s outside the
/// flights) the bias plus white noise of kRestSigma, in flight kFlightSigma, and in toss 2's
/// flight from `from` to `to` s (0.5 to 0.6 s by default) a burst of ±`burst` rad/s per
/// component on top, alternating.
struct Made {
  GyroRecording recording;
  std::vector<std::pair<double, double>> ranges;
};
Made with_burst(double burst, double from = 0.5, double to = 0.6) {
  const test::SyntheticRecording s = test::make_recording(
      test::phone_on_book(),
      {{{0.5, 12.0, 0.4}, 1.2}, {{-0.3, 11.0, 0.7}, 1.3}, {{0.6, -13.0, -0.5}, 1.1}}, 5, 0.0);
  Made made{test::as_recording(s), {}};
  for (const test::TrueToss& t : s.tosses) made.ranges.emplace_back(t.t_start, t.t_end);
  std::mt19937 random(11);
  std::normal_distribution<double> gauss(0.0, 1.0);
  int burst_samples = 0;
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    const double t = s.t[i];
    const Eigen::Vector3d e(gauss(random), gauss(random), gauss(random));
    int in = -1;
    for (std::size_t k = 0; k < made.ranges.size(); ++k)
      if (t >= made.ranges[k].first && t <= made.ranges[k].second) in = static_cast<int>(k);
    Eigen::Vector3d& w = made.recording.omega[i];
    if (in < 0) {
      if ((w - s.bias).norm() < 0.25) w = s.bias + kRestSigma * e;
      continue;
    }
    w += kFlightSigma * e;
    const double tau = t - made.ranges[in].first;
    if (in == 1 && tau >= from && tau < to)
      w += burst * ((burst_samples++ % 2) ? 1.0 : -1.0) * Eigen::Vector3d(1.0, -1.0, 1.0);
  }
  return made;
}

FitResult fit_of(const Made& made) {
  FitSettings settings;
  settings.drag = physics::DragLaw::none;
  return fit_recording(made.recording, hand_flights(made.recording, made.ranges), settings);
}

// A burst of 0.03 rad/s per component (|r| ≈ 0.05) is ~15 times the flight's typical block
// but under the floor 5√3 · 0.02 ≈ 0.17 rad/s: not flagged. One of 0.13 rad/s (|r| ≈ 0.23) is
// over both: flagged, as a knock (the middle of the flight).
TEST(ResidualFlags, ABurstUnderFiveSigmaOfTheRestNoiseIsNotAKnockAndOneOverItIs) {
  const double floor = 5.0 * std::sqrt(3.0) * kRestSigma;
  const FitResult quiet = fit_of(with_burst(0.03));
  ASSERT_EQ(quiet.tosses.size(), 3u);
  ASSERT_LT(std::sqrt(3.0) * 0.03, 0.5 * floor);  // the burst's |r| well under the floor
  for (const TossFit& toss : quiet.tosses) EXPECT_FALSE(toss.poor_fit) << toss.flag;
  const FitResult loud = fit_of(with_burst(0.13));
  ASSERT_EQ(loud.tosses.size(), 3u);
  // Over it by 30 %; under a floor counted per vector (5√3·√3 σ) it would not be.
  ASSERT_GT(std::sqrt(3.0) * 0.13, 1.25 * floor);
  ASSERT_LT(std::sqrt(3.0) * 0.13, 0.8 * floor * std::sqrt(3.0));
  EXPECT_FALSE(loud.tosses[0].poor_fit) << loud.tosses[0].flag;
  EXPECT_TRUE(loud.tosses[1].poor_fit);
  EXPECT_NE(loud.tosses[1].flag.find("a knock"), std::string::npos) << loud.tosses[1].flag;
  EXPECT_FALSE(loud.tosses[2].poor_fit) << loud.tosses[2].flag;
}

// The residual's 50 ms blocks over the flight's samples: a burst within the second block is
// "the throw", within the second-to-last "a catch" (docs/phone-lab.md, "Flags": near the start,
// near the end), as the flight's samples place the blocks here.
TEST(ResidualFlags, ABurstNearTheStartIsTheThrowAndNearTheEndACatch) {
  const Made plain = with_burst(0.0);
  double first = -1.0, last = -1.0;  // toss 2's first and last sample, s from its start
  for (double t : plain.recording.t)
    if (t >= plain.ranges[1].first && t <= plain.ranges[1].second) {
      if (first < 0) first = t - plain.ranges[1].first;
      last = t - plain.ranges[1].first;
    }
  const int blocks = static_cast<int>((last - first) / 0.05);
  const double width = (last - first) / blocks;
  ASSERT_GE(blocks, 20);
  const auto burst_in = [&](int block) {
    const double start = first + block * width;
    return fit_of(with_burst(0.3, start + 0.05 * width, start + 0.95 * width)).tosses.at(1);
  };
  const TossFit near_start = burst_in(1), near_end = burst_in(blocks - 2);
  EXPECT_EQ(near_start.flag.rfind("the throw inside the flight?", 0), 0u) << near_start.flag;
  EXPECT_EQ(near_end.flag.rfind("a catch inside the flight?", 0), 0u) << near_end.flag;
}

// 12-13-51's main throw as the finder gives it (2.241–3.234 s, fitted as given): the fitted
// motion's residual in its last 50 ms is over 4 times its median 50 ms block, yet Euler's
// torque on the samples there (ω̇ from the finder's quadratic, the fitted body) stays within 3
// times the flight's median until the landing, 30 ms after the flight's end, where it passes 30
// times it: the fit drifting off near the separatrix, not a catch; not flagged.
TEST(ResidualFlags, ARealFitDriftingOffAtAFreeEndIsNotACatch) {
  REQUIRE_REAL_RECORDINGS();
  const GyroRecording r = pool_recordings({read_recording(real_dir() / "12-13-51")});
  const FitResult fit = fit_recording(r, hand_flights(r, {{2.241, 3.234}}));
  ASSERT_EQ(fit.tosses.size(), 1u);
  std::vector<double> t;
  std::vector<Eigen::Vector3d> omega;
  measured_omega(r, fit, 0, t, omega);
  // The residual's 50 ms blocks (the flag's), independently of it.
  const int blocks = static_cast<int>((t.back() - t.front()) / 0.05);
  std::vector<double> sum2(blocks, 0.0), count(blocks, 0.0);
  for (std::size_t i = 0; i < t.size(); ++i) {
    const int b = std::min(blocks - 1,
                           static_cast<int>((t[i] - t.front()) / (t.back() - t.front()) * blocks));
    sum2[b] += (omega[i] - fitted_omega(fit, 0, t[i])).squaredNorm();
    count[b] += 1.0;
  }
  std::vector<double> block(blocks);
  for (int b = 0; b < blocks; ++b) block[b] = std::sqrt(sum2[b] / count[b]);
  std::vector<double> sorted = block;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_GT(block.back(), 4.0 * sorted[blocks / 2]);
  // Euler's torque |I ω̇ + ω × Iω| / |ω|² on the samples, from the flight to 0.1 s past it.
  const Eigen::Matrix3d I =
      fit.body.axes * fit.body.ratios.asDiagonal() * fit.body.axes.transpose();
  const std::vector<Eigen::Vector3d> rate = omega_rate(r.t, r.omega);
  std::vector<double> inside;
  double last_100ms = 0.0, landing = 0.0;
  for (std::size_t i = 0; i < r.t.size(); ++i) {
    const Eigen::Vector3d& w = r.omega[i];
    const double torque = (I * rate[i] + w.cross(I * w)).norm() / w.squaredNorm();
    if (r.t[i] >= 2.241 && r.t[i] <= 3.234) inside.push_back(torque);
    if (r.t[i] >= 3.134 && r.t[i] <= 3.234) last_100ms = std::max(last_100ms, torque);
    if (r.t[i] > 3.234 && r.t[i] <= 3.334) landing = std::max(landing, torque);
  }
  std::sort(inside.begin(), inside.end());
  const double median = inside[inside.size() / 2];
  EXPECT_LT(last_100ms, 3.0 * median);
  EXPECT_GT(landing, 30.0 * median);
  EXPECT_EQ(fit.tosses[0].flag, "");
}

}  // namespace
}  // namespace bookspin::fit
