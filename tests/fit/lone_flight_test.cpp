// A recording that is one free flight: no rest before or after, uneven timestamps (an app that
// delivers the gyroscope in bursts), docs/phone-lab.md, "How the flights are found".
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "fit/flights.hpp"
#include "fit/pool.hpp"
#include "fit/recording.hpp"
#include "fit/report.hpp"
#include "fit/toss_fit.hpp"
#include "real_recordings.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

/// 0.65 s of a bare phone's flight at about 20 rad/s, sampled in bursts: two thirds of the steps
/// 2 ms, one third 12 ms (each ±20 %), about 190 Hz on average; a bias and 0.02 rad/s of noise;
/// the recording starts and ends in flight.
/// With `android`, the steps of a nominal 415 Hz instead: most 1.4–2.8 ms, one in thirty 8–21 ms.
GyroRecording lone_flight(unsigned seed, Eigen::Vector3d* omega0_phone = nullptr,
                          bool android = false) {
  const test::SyntheticBody body = test::phone_alone();
  const Eigen::Vector3d w0(1.0, 20.0, 1.2);
  const Eigen::Vector3d bias(0.02, -0.01, 0.015);
  std::mt19937 random(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  GyroRecording recording;
  recording.source = "lone-flight.csv";
  Eigen::Vector3d w = w0;
  double t = 0.0;
  while (t <= 0.65) {
    recording.t.push_back(t);
    recording.omega.push_back(body.axes * w + bias +
                              0.02 * Eigen::Vector3d(gauss(random), gauss(random), gauss(random)));
    const double step = android
                            ? (random() % 30 == 0 ? 0.0145 + 0.0065 * uniform(random)
                                                  : 0.0021 + 0.0007 * uniform(random))
                            : (random() % 3 == 2 ? 0.012 : 0.002) * (1.0 + 0.2 * uniform(random));
    w = test::rk4(body.moments, w, step, test::SyntheticDrag{});
    t += step;
  }
  if (omega0_phone) *omega0_phone = body.axes * w0;
  return pool_recordings({recording});
}

TEST(LoneFlight, IsFoundWithNoRestAndUnevenTimestampsAndFitsWithinFivePercent) {
  for (unsigned seed : {1u, 2u, 3u, 4u, 5u, 6u}) {
    // Seeds 4–6: the nominal 415 Hz with steps of 1.4 to 21 ms.
    const GyroRecording recording = lone_flight(seed, nullptr, seed > 3);
    const FlightSearch search = find_flights(recording);
    EXPECT_EQ(recording.parts.at(0).rest.samples, 0) << seed;
    ASSERT_EQ(search.flights.size(), 1u) << seed;
    // Nearly all of it: the finder trims at most a few samples at each end.
    EXPECT_GT(search.flights[0].t_end - search.flights[0].t_start, 0.55) << seed;
    const FitResult fit = fit_recording(recording, search);
    ASSERT_EQ(fit.tosses.size(), 1u);
    double mean_omega = 0.0;
    for (const Eigen::Vector3d& w : recording.omega) mean_omega += w.norm();
    mean_omega /= static_cast<double>(recording.omega.size());
    EXPECT_LT(fit.tosses[0].residual_rms, 0.05 * mean_omega) << seed;
    EXPECT_FALSE(fit.tosses[0].poor_fit) << seed << ": " << fit.tosses[0].flag;
  }
}

namespace fs = std::filesystem;

/// ω of `recording` at time `at` (within its samples): a cubic Hermite curve through the samples
/// with each one's slope from its neighbours and their own times.
Eigen::Vector3d interpolated(const GyroRecording& recording, double at) {
  const std::vector<double>& t = recording.t;
  const std::vector<Eigen::Vector3d>& w = recording.omega;
  const std::size_t n = t.size();
  std::size_t i = static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), at) - t.begin());
  i = std::clamp<std::size_t>(i, 1, n - 1) - 1;  // at in [t[i], t[i + 1]]
  const auto slope = [&](std::size_t k) -> Eigen::Vector3d {
    const std::size_t a = k == 0 ? 0 : k - 1, b = std::min(n - 1, k + 1);
    return (w[b] - w[a]) / (t[b] - t[a]);
  };
  const double h = t[i + 1] - t[i], s = (at - t[i]) / h;
  const double h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s;
  const double h01 = -2 * s * s * s + 3 * s * s, h11 = s * s * s - s * s;
  return h00 * w[i] + h10 * h * slope(i) + h01 * w[i + 1] + h11 * h * slope(i + 1);
}

/// The middle 0.65 s cut from the longest flight the finder finds in real recording `name`,
/// resampled at a nominal 415 Hz as some Android phones deliver it: most steps 1.4–2.8 ms, one in
/// thirty 8–21 ms (seeded); or at its own 100 Hz stamps with `resample` false.
GyroRecording lone_real_flight(const std::string& name, unsigned seed, bool resample) {
  const GyroRecording whole = pool_recordings({read_recording(real_dir() / name)});
  const FlightSearch search = find_flights(whole);
  EXPECT_FALSE(search.flights.empty()) << name;
  if (search.flights.empty()) return whole;
  const Flight longest = *std::max_element(
      search.flights.begin(), search.flights.end(),
      [](const Flight& a, const Flight& b) { return a.t_end - a.t_start < b.t_end - b.t_start; });
  // Its middle 0.65 s: a student's cut keeps clear of the hands.
  const double from = std::max(longest.t_start, 0.5 * (longest.t_start + longest.t_end) - 0.325);
  const double to = std::min(longest.t_end, from + 0.65);
  GyroRecording cut;
  cut.name = name + "-flight";
  cut.source = cut.name + ".csv";
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (double t = from; t <= to;) {
    cut.t.push_back(t);
    cut.omega.push_back(interpolated(whole, t));
    t += random() % 30 == 0 ? 0.008 + 0.013 * unit(random) : 0.0014 + 0.0014 * unit(random);
  }
  if (!resample) {
    cut.t.clear(), cut.omega.clear();
    for (std::size_t i = 0; i < whole.t.size(); ++i)
      if (whole.t[i] >= from && whole.t[i] <= to)
        cut.t.push_back(whole.t[i]), cut.omega.push_back(whole.omega[i]);
  }
  return pool_recordings({cut});
}

// The relation "cut down to one flight" on real recordings (docs/phone-lab.md, "How the
// flights are found"): a flight cut from a real throw, alone, with no rest, is found again and
// fitted within 5 % of |ω|, at its own 100 Hz stamps and resampled at uneven stamps of 1.4 to
// 21 ms.
TEST(LoneFlight, ARealFlightCutAndResampledUnevenlyIsFoundAndFitsWithinFivePercent) {
  if (!fs::is_directory(real_dir())) GTEST_SKIP() << "no real recordings at " << real_dir();
  for (const char* name :
       {"12-10-56", "12-13-01", "12-13-51", "12-22-44", "12-29-59", "12-38-00", "12-44-51"})
    for (const bool resample : {false, true}) {
      SCOPED_TRACE(std::string(name) + (resample ? " resampled" : " at 100 Hz"));
      const GyroRecording recording = lone_real_flight(name, 7, resample);
      double longest_step = 0.0;
      for (std::size_t i = 1; i < recording.t.size(); ++i)
        longest_step = std::max(longest_step, recording.t[i] - recording.t[i - 1]);
      if (resample) {
        EXPECT_GT(longest_step, 0.015);
      }
      const FlightSearch search = find_flights(recording);
      ASSERT_EQ(search.flights.size(), 1u);
      const double span = recording.t.back() - recording.t.front();
      EXPECT_GT(search.flights[0].t_end - search.flights[0].t_start, 0.8 * span);
      const FitResult fit = fit_recording(recording, search);
      ASSERT_EQ(fit.tosses.size(), 1u);
      double mean_omega = 0.0;
      for (const Eigen::Vector3d& w : recording.omega) mean_omega += w.norm();
      mean_omega /= static_cast<double>(recording.omega.size());
      // 12-38-00's plate flexes (docs/phone-lab.md, "The development recordings": 11.6 % in
      // the whole recording, flagged so): its middle fits at 6 %.
      const double limit = std::string(name) == "12-38-00" ? 0.07 : 0.05;
      EXPECT_LT(fit.tosses[0].residual_rms, limit * mean_omega);
    }
}

/// `stamps` 0: bursts of 2 and 12 ms; 1: steps uniform in 1.4–21 ms; 2: most 1.4–2.8 ms, one in
/// five 8–21 ms.
double uneven_step(int stamps, std::mt19937& random) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  if (stamps == 1) return 0.0014 + 0.0196 * unit(random);
  const bool long_step = random() % (stamps == 0 ? 3 : 5) == 0;
  if (stamps == 0) return (long_step ? 0.012 : 0.002) * (1.0 + 0.2 * (2.0 * unit(random) - 1.0));
  return long_step ? 0.008 + 0.013 * unit(random) : 0.0014 + 0.0014 * unit(random);
}

// A real gyroscope's gain and cross-axis errors (a sensitivity matrix S = 1 + ε G, G's entries
// standard normal, ε 4–8 %) on a phone's lone flight cut at 2.929–3.579 s with uneven stamps and
// no rest: a flat body's flip brings |ω̇|/|ω|² near the bound of docs/physics.md §8, which such
// errors exceed for a while. Every flight that fits under 5 % of |ω| by hand is found whole
// (one flight, 0.55 s or more) and fits as well, however its stamps fall (docs/phone-lab.md,
// "How the flights are found").
TEST(LoneFlight, AGyroscopesGainAndCrossAxisErrorsLeaveTheFlightWhole) {
  const test::SyntheticBody body = test::phone_alone();
  int fitting = 0;
  for (double epsilon : {0.04, 0.06, 0.08})
    for (int stamps = 0; stamps < 3; ++stamps)
      for (unsigned seed = 1; seed <= 12; ++seed) {
        SCOPED_TRACE("ε " + std::to_string(epsilon) + ", stamps " + std::to_string(stamps) +
                     ", seed " + std::to_string(seed));
        std::mt19937 random(seed);
        std::normal_distribution<double> gauss(0.0, 1.0);
        Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b) S(a, b) += epsilon * gauss(random);
        GyroRecording cut;
        cut.source = "cut.csv";
        Eigen::Vector3d w(1.0, 20.0, 1.2);
        for (double t = 2.929; t <= 3.579;) {
          cut.t.push_back(t);
          cut.omega.push_back(S * (body.axes * w) +
                              0.02 * Eigen::Vector3d(gauss(random), gauss(random), gauss(random)));
          const double step = uneven_step(stamps, random);
          w = test::rk4(body.moments, w, step, test::SyntheticDrag{});
          t += step;
        }
        const GyroRecording recording = pool_recordings({cut});
        double mean_omega = 0.0;
        for (const Eigen::Vector3d& x : recording.omega) mean_omega += x.norm();
        mean_omega /= static_cast<double>(recording.omega.size());
        const FitResult by_hand = fit_recording(
            recording, hand_flights(recording, {{recording.t.front(), recording.t.back()}}));
        if (!(by_hand.tosses.at(0).residual_rms < 0.05 * mean_omega)) continue;
        ++fitting;
        const FlightSearch search = find_flights(recording);
        ASSERT_EQ(search.flights.size(), 1u);
        EXPECT_GT(search.flights[0].t_end - search.flights[0].t_start, 0.55);
        const FitResult found = fit_recording(recording, search);
        EXPECT_LT(found.tosses.at(0).residual_rms, 0.05 * mean_omega);
      }
  // Most of the 108 fit under 5 % by hand (the rest are over it, or the fit's other minimum).
  EXPECT_GE(fitting, 80);
}

/// A phone's lone flight as some Android phones stamp it: 0.65 s of the bare phone's flight at
/// about 20 rad/s (|ω| 19–24), about 100 samples whose stamps lie 1.4 to 21 ms apart (median
/// about 4.3 ms), each sample the motion at its stamp; a bias and 0.02 rad/s of noise (stamps off
/// their samples: restamped below).
GyroRecording android_lone_flight(unsigned seed) {
  const test::SyntheticBody body = test::phone_alone();
  std::mt19937 random(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  GyroRecording recording;
  recording.source = "android-lone-flight.csv";
  Eigen::Vector3d w(1.0, 20.0, 1.2);
  double t = 0.0;
  while (t <= 0.65) {
    recording.t.push_back(t);
    recording.omega.push_back(body.axes * w + Eigen::Vector3d(0.02, -0.01, 0.015) +
                              0.02 * Eigen::Vector3d(gauss(random), gauss(random), gauss(random)));
    const double u = unit(random);
    const double step = u < 0.55   ? 0.0014 + 0.0029 * unit(random)
                        : u < 0.85 ? 0.0043 + 0.0057 * unit(random)
                                   : 0.010 + 0.011 * unit(random);
    w = test::rk4(body.moments, w, step, test::SyntheticDrag{});
    t += step;
  }
  return pool_recordings({recording});
}

/// The mean |ω| of `recording` (rad/s).
double mean_speed(const GyroRecording& recording) {
  double sum = 0.0;
  for (const Eigen::Vector3d& w : recording.omega) sum += w.norm();
  return sum / static_cast<double>(recording.omega.size());
}

// The held-out lone flight's kind: one free flight and nothing else, about 100 samples over
// 0.65 s with stamps 1.4–21 ms apart, no rest, no throw or catch: found without a hand range, and
// fitted under 5 % of |ω|, through the report every door takes.
TEST(LoneFlight, AHundredSamplesAtAnAndroidPhonesStampsAreFoundWithoutAHandRange) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const GyroRecording recording = android_lone_flight(seed);
    std::vector<double> steps;
    for (std::size_t i = 1; i < recording.t.size(); ++i)
      steps.push_back(recording.t[i] - recording.t[i - 1]);
    std::sort(steps.begin(), steps.end());
    EXPECT_GT(steps.back(), 0.015);
    EXPECT_GT(steps[steps.size() / 2], 0.0035);
    const FitReport report = fit_report(recording, {});
    ASSERT_EQ(report.result.tosses.size(), 1u);
    const Flight& flight = report.result.tosses[0].flight;
    EXPECT_GT(flight.t_end - flight.t_start, 0.45);
    EXPECT_LT(report.result.tosses[0].residual_rms, 0.05 * mean_speed(recording));
  }
}

}  // namespace
}  // namespace bookspin::fit
