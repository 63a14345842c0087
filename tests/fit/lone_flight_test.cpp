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
    cut.omega.push_back(test::interpolated(whole, t));
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

/// A phone's lone flight whose stamps lie off its samples, as an Android phone delivering its
/// gyroscope stamps them: about 100 stamps over 0.65 s, 1.4 to 21 ms apart (median about 4.3 ms),
/// as android_lone_flight's; each sample the exact motion of the bare phone (|ω| 19–25 rad/s) at
/// its own measuring time, up to 40 % of the median step before or after its stamp (so that each
/// step between stamps is off the steps between samples by up to ±80 % of the median), in order;
/// a bias and 0.02 rad/s of noise.
GyroRecording stamped_off_lone_flight(unsigned seed) {
  const test::SyntheticBody body = test::phone_alone();
  std::mt19937 random(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> stamps;
  for (double t = 0.0; t <= 0.65;) {
    stamps.push_back(t);
    const double u = unit(random);
    t += u < 0.55   ? 0.0014 + 0.0029 * unit(random)
         : u < 0.85 ? 0.0043 + 0.0057 * unit(random)
                    : 0.010 + 0.011 * unit(random);
  }
  GyroRecording recording;
  recording.source = "stamped-off-lone-flight.csv";
  Eigen::Vector3d w(1.0, 20.0, 1.2);
  double measured = 0.0;
  for (double stamp : stamps) {
    const double at = std::max(measured, stamp + 0.4 * 0.0043 * (2.0 * unit(random) - 1.0));
    w = test::rk4(body.moments, w, at - measured, test::SyntheticDrag{});
    measured = at;
    recording.t.push_back(stamp);
    recording.omega.push_back(body.axes * w + Eigen::Vector3d(0.02, -0.01, 0.015) +
                              0.02 * Eigen::Vector3d(gauss(random), gauss(random), gauss(random)));
  }
  return pool_recordings({recording});
}

// The held-out lone flight's kind with its stamps off its samples (docs/phone-lab.md, "Stamps
// off their samples"): the derivative over such stamps crosses the bound |ω̇| ≤ 0.6 |ω|² here and
// there, which cut the flight into pieces under 0.3 s ("no torque-free stretch of 0.300 s or
// longer") though it fits under 5 % of |ω| by hand; found whole without a hand range, and fitted
// under 5 % of |ω|, through the report every door takes.
TEST(LoneFlight, StampsOffTheirSamplesAsAnAndroidPhoneDeliversThemAreFoundWithoutAHandRange) {
  for (unsigned seed = 1; seed <= 12; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const GyroRecording recording = stamped_off_lone_flight(seed);
    std::vector<double> steps;
    for (std::size_t i = 1; i < recording.t.size(); ++i)
      steps.push_back(recording.t[i] - recording.t[i - 1]);
    std::sort(steps.begin(), steps.end());
    EXPECT_GT(steps.front(), 0.0013);
    EXPECT_GT(steps.back(), 0.015);
    EXPECT_NEAR(steps[steps.size() / 2], 0.0043, 0.0008);
    EXPECT_NEAR(static_cast<double>(recording.t.size()), 100.0, 30.0);
    FitReport report;
    try {
      report = fit_report(recording, {});
    } catch (const InputError& e) {
      ADD_FAILURE() << e.what();
      continue;
    }
    ASSERT_EQ(report.result.tosses.size(), 1u);
    const Flight& flight = report.result.tosses[0].flight;
    EXPECT_GT(flight.t_end - flight.t_start, 0.55);
    EXPECT_LT(report.result.tosses[0].residual_rms, 0.05 * mean_speed(recording));
  }
}

/// `recording` (a lone flight) re-stamped: each stamp moved by up to ±80 % of the median step
/// (seeded), a stamp that would then fall at or before the one before it set 0.2 ms after it
/// (samples delivered together), the samples as they were; or, with `drop`, a random fifth of its
/// samples left out, the others as they were. `kept` gets each sample's index in `recording`.
GyroRecording restamped(const GyroRecording& recording, unsigned seed, bool drop,
                        std::vector<int>& kept) {
  std::vector<double> steps;
  for (std::size_t i = 1; i < recording.t.size(); ++i)
    steps.push_back(recording.t[i] - recording.t[i - 1]);
  std::nth_element(steps.begin(), steps.begin() + steps.size() / 2, steps.end());
  const double median = steps[steps.size() / 2];
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> jitter(-0.8, 0.8);
  GyroRecording out;
  out.name = recording.name;
  out.source = recording.source;
  kept.clear();
  for (std::size_t i = 0; i < recording.t.size(); ++i) {
    if (drop && random() % 5 == 0) continue;
    double t = drop ? recording.t[i] : recording.t[i] + jitter(random) * median;
    if (!out.t.empty() && t <= out.t.back()) t = out.t.back() + 0.0002;
    out.t.push_back(t), out.omega.push_back(recording.omega[i]);
    kept.push_back(static_cast<int>(i));
  }
  return pool_recordings({out});
}

/// The flights the report finds in `recording` and their body; fails the test where there is none.
FitResult found(const GyroRecording& recording) {
  try {
    return fit_report(recording, {}).result;
  } catch (const InputError& e) {
    ADD_FAILURE() << e.what();
  }
  return {};
}

// The relation "the stamps do not make the flight" (docs/phone-lab.md, "Stamps off their
// samples"): a lone flight re-stamped with each stamp moved by up to ±80 % of its median step, or
// with a random fifth of its samples dropped, is found as the same flight (each end within
// 4 samples of the flight found as recorded) and gives the same body (each ratio within twice
// its σ and the recorded one's together: measured, up to 1.5 times, the stamps' error in the fit
// itself, which its σ from the noise leaves out); on the exact motion of a bare phone at an
// even 4.3 ms, on the held-out kind (android_lone_flight: stamps 1.4–21 ms apart) and on a flight
// cut from six of the seven real recordings at its own 100 Hz (12-38-00's plate flexes: flagged as
// recorded).
TEST(LoneFlight, ReStampedOrThinnedALoneFlightIsTheSameFlightAndBody) {
  std::vector<std::pair<std::string, GyroRecording>> flights;
  {
    const test::SyntheticBody body = test::phone_alone();
    std::mt19937 random(11);
    std::normal_distribution<double> gauss(0.0, 1.0);
    GyroRecording even;
    even.source = "even-lone-flight.csv";
    Eigen::Vector3d w(1.0, 20.0, 1.2);
    for (int i = 0; i * 0.0043 <= 0.65; ++i) {
      even.t.push_back(i * 0.0043);
      even.omega.push_back(body.axes * w +
                           0.02 * Eigen::Vector3d(gauss(random), gauss(random), gauss(random)));
      w = test::rk4(body.moments, w, 0.0043, test::SyntheticDrag{});
    }
    flights.emplace_back("exact motion at 4.3 ms", pool_recordings({even}));
  }
  flights.emplace_back("android stamps", android_lone_flight(3));
  if (fs::is_directory(real_dir()))
    for (const char* name :
         {"12-10-56", "12-13-01", "12-13-51", "12-22-44", "12-29-59", "12-44-51"})
      flights.emplace_back(name, lone_real_flight(name, 7, false));
  for (const auto& [name, recording] : flights) {
    const FitResult as_recorded = found(recording);
    ASSERT_EQ(as_recorded.tosses.size(), 1u) << name;
    ASSERT_TRUE(as_recorded.body.ratio_sigma.has_value()) << name;
    const Flight& a = as_recorded.tosses[0].flight;
    for (unsigned seed = 1; seed <= 4; ++seed)
      for (const bool drop : {false, true}) {
        SCOPED_TRACE(name + (drop ? ": a fifth dropped" : ": re-stamped") + ", seed " +
                     std::to_string(seed));
        std::vector<int> kept;
        const FitResult again = found(restamped(recording, seed, drop, kept));
        EXPECT_EQ(again.tosses.size(), 1u);
        if (again.tosses.size() != 1u) continue;
        const Flight& b = again.tosses[0].flight;
        EXPECT_LE(std::abs(kept[b.first] - a.first), 4) << b.t_start << " against " << a.t_start;
        EXPECT_LE(std::abs(kept[b.last] - a.last), 4) << b.t_end << " against " << a.t_end;
        ASSERT_TRUE(again.body.ratio_sigma.has_value());
        for (int i = 0; i < 2; ++i)
          EXPECT_LT(
              std::abs(again.body.ratios[i] - as_recorded.body.ratios[i]),
              2.0 * std::hypot((*again.body.ratio_sigma)[i], (*as_recorded.body.ratio_sigma)[i]))
              << "I" << i + 1 << "/I3 " << again.body.ratios[i] << " ± "
              << (*again.body.ratio_sigma)[i] << " against " << as_recorded.body.ratios[i] << " ± "
              << (*as_recorded.body.ratio_sigma)[i];
      }
  }
}

// 12-13-01 as the explorer page records it, re-timed by Chromium at 53 Hz
// (tests/fit/recordings/12-13-01-browser-53Hz.csv: the page's recorder fed the recording's
// samples at their own rate, Browser.ExplorerRecordsItsGyroscope; median step 18.7 ms). Its
// flight, 2.135–3.052 s with T/2 0.462 s as the original's, ends where the catch starts, and the
// bounce after the catch, 3.218–3.519 s, is a flight of its own (as 12-13-01's): a catch at
// 53 Hz is two or three samples, and a finder that bridged fast samples among uneven stamps by
// their count merged it into 2.04–3.54 s, T/2 0.390 s, 47 % of |ω| unexplained. The catch
// changes |I ω| by 79 % within 31 ms: never bridged as a stamp's error (docs/phone-lab.md,
// "Stamps off their samples").
TEST(LoneFlight, ABrowserTimedRecordingKeepsItsFlightApartFromItsCatch) {
  const fs::path file =
      fs::path(BOOKSPIN_SOURCE_DIR) / "tests" / "fit" / "recordings" / "12-13-01-browser-53Hz.csv";
  const GyroRecording recording = pool_recordings({read_recording(file)});
  const FitResult fit = found(recording);
  ASSERT_EQ(fit.tosses.size(), 2u);
  const TossFit& toss = fit.tosses[0];
  EXPECT_NEAR(toss.flight.t_start, 2.135, 0.0015);
  EXPECT_NEAR(toss.flight.t_end, 3.052, 0.0015);
  ASSERT_TRUE(toss.half_period_measured.has_value());
  EXPECT_NEAR(*toss.half_period_measured, 0.462, 0.0015);
  // The bounce after the catch, at 5 rad/s without a flip, a flight of its own.
  EXPECT_NEAR(fit.tosses[1].flight.t_start, 3.218, 0.0015);
  EXPECT_NEAR(fit.tosses[1].flight.t_end, 3.519, 0.0015);
  for (const TossFit& other : fit.tosses) {
    SCOPED_TRACE("toss from " + std::to_string(other.flight.t_start) + " s");
    EXPECT_LT(other.residual_share, 0.05);
  }
}

}  // namespace
}  // namespace bookspin::fit
