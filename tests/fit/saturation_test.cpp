// A gyroscope's saturation (fit/saturation.hpp, docs/phone-lab.md "Saturation"): samples flat at
// the recording's largest |ω_i| found, and left out of the fit. The recordings are synthetic
// tosses (synthetic_recording.hpp) clipped by hand at a chosen range, as a phone's gyroscope
// clips them: the truth is the unclipped motion.
#include "fit/saturation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fit/flights.hpp"
#include "fit/pool.hpp"
#include "fit/recording.hpp"
#include "fit/toss_fit.hpp"
#include "real_recordings.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

/// `recording` with every component clipped to ±range, as a gyroscope at its range reads.
GyroRecording clipped(GyroRecording recording, double range) {
  for (Eigen::Vector3d& w : recording.omega) w = w.cwiseMax(-range).cwiseMin(range);
  return recording;
}

const std::vector<test::SyntheticToss> kTosses{
    {{0.3, 14.0, 0.5}, 1.2}, {{-0.4, 13.0, 0.6}, 1.1}, {{0.5, -15.0, -0.3}, 1.3}};

TEST(Saturation, FlatRunsAtTheTopAreTheRangeAndASmoothPeakIsNot) {
  const GyroRecording recording =
      test::as_recording(test::make_recording(test::phone_alone(), kTosses, 11));
  // As measured: the largest |ω_i| is one sample's peak, nothing is flat there.
  const Saturation none = find_saturation(recording);
  EXPECT_FALSE(none.range.has_value());
  EXPECT_EQ(std::count(none.at_range.begin(), none.at_range.end(), true), 0);
  // Clipped at 12 rad/s (the tosses turn at 13–15 about their intermediate axis).
  const GyroRecording clip = clipped(recording, 12.0);
  const Saturation found = find_saturation(clip);
  ASSERT_TRUE(found.range.has_value());
  EXPECT_DOUBLE_EQ(*found.range, 12.0);
  std::size_t expected = 0;
  for (std::size_t i = 0; i < clip.omega.size(); ++i) {
    const bool flat = clip.omega[i].cwiseAbs().maxCoeff() == 12.0;
    expected += flat;
    EXPECT_EQ(found.at_range[i], flat) << "sample " << i;
  }
  EXPECT_GT(expected, 30u);
  // Two samples at the top are a peak, three a range (kMinFlatSamples).
  GyroRecording two = recording;
  two.omega[100] = Eigen::Vector3d(0, 50.0, 0);
  two.omega[101] = Eigen::Vector3d(0, -50.0, 0);
  EXPECT_FALSE(find_saturation(two).range.has_value());
  two.omega[102] = Eigen::Vector3d(0, 50.0, 0);
  EXPECT_TRUE(find_saturation(two).range.has_value());
}

// Clipped at 93 % of the fastest |ω_i| (the intermediate axis's component flat for tens of
// samples at each toss's start, as a fast throw reads on a phone at ±2000 °/s): the samples at
// the range are counted and left out, the flights found through them, and the body comes out as
// from the unclipped recording (1 % in the ratios; 0.06 % measured), the residual at the noise
// (0.017 rad/s). With the clipped samples fitted as data: 2.8 % and 0.38 rad/s.
TEST(Saturation, ClippedSamplesAreLeftOutAndTheBodyIsRecovered) {
  const test::SyntheticBody body = test::phone_alone();
  const GyroRecording recording = test::as_recording(test::make_recording(body, kTosses, 11));
  const FlightSearch flights = find_flights(recording);
  std::vector<double> tops;
  for (const Flight& f : flights.flights)
    for (int i = f.first; i <= f.last; ++i)
      tops.push_back(recording.omega[i].cwiseAbs().maxCoeff());
  std::sort(tops.begin(), tops.end());
  const double range = 0.93 * tops.back();
  const GyroRecording clip = clipped(recording, range);
  const FitResult fit = fit_recording(clip, find_flights(clip));
  ASSERT_TRUE(fit.saturation_range.has_value());
  EXPECT_DOUBLE_EQ(*fit.saturation_range, range);
  ASSERT_EQ(fit.tosses.size(), kTosses.size());
  const Eigen::Vector3d ratios = body.moments / body.moments[2];
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(fit.body.ratios[i], ratios[i], 0.01 * ratios[i]);
  int saturated = 0;
  for (const TossFit& toss : fit.tosses) {
    saturated += toss.saturated;
    EXPECT_LT(toss.residual_rms, 0.05) << toss.flag;
    EXPECT_FALSE(toss.poor_fit) << toss.flag;
  }
  EXPECT_GT(saturated, 0);
  EXPECT_TRUE(std::any_of(fit.body.notes.begin(), fit.body.notes.end(), [](const std::string& n) {
    return n.find("the gyroscope saturated") != std::string::npos;
  }));
}

// Clipped at 3 rad/s, most of each flight reads the range: the toss (its flight given by hand:
// the finder sees no torque-free stretch in such a recording) is flagged naming saturation, and
// its `saturated` counts the samples its flag counts, whether they were left out or kept.
TEST(Saturation, AFlightMostlyAtTheRangeIsFlaggedForIt) {
  const test::SyntheticRecording synthetic = test::make_recording(test::phone_alone(), kTosses, 11);
  const GyroRecording clip = clipped(test::as_recording(synthetic), 3.0);
  std::vector<std::pair<double, double>> ranges;
  for (const test::TrueToss& t : synthetic.tosses) ranges.emplace_back(t.t_start, t.t_end);
  const FitResult fit = fit_recording(clip, hand_flights(clip, ranges));
  ASSERT_FALSE(fit.tosses.empty());
  for (const TossFit& toss : fit.tosses) {
    EXPECT_TRUE(toss.poor_fit);
    EXPECT_NE(toss.flag.find("gyroscope saturated"), std::string::npos) << toss.flag;
    int at_range = 0;
    for (int i = toss.flight.first; i <= toss.flight.last; ++i)
      at_range += clip.omega[i].cwiseAbs().maxCoeff() == 3.0;
    EXPECT_GT(at_range, 0);
    EXPECT_EQ(toss.saturated, at_range) << toss.flag;
    EXPECT_NE(toss.flag.find("gyroscope saturated: " + std::to_string(at_range) + " of"),
              std::string::npos)
        << toss.flag;
  }
}

}  // namespace
}  // namespace bookspin::fit

namespace bookspin::fit {
namespace {

// A clipped iPhone axis without a stated range (docs/phone-lab.md, "Saturation"): x reads a
// plateau drifting 35.600 → 35.545 rad/s over 12 samples while y and z swing through 10 rad/s
// (as the held-out clipped throw does); no sample is flat to 1e-6. The plateau is found at the
// standard ±2000 °/s and its 12 samples marked, none else. The same motion with x a smooth
// peak topping at 34.7 rad/s (a component turning at 20 rad/s, sampled at 100 Hz) is no clip.
TEST(Saturation, ADriftingPlateauAtAStandardFullScaleIsFound) {
  GyroRecording plateau, smooth;
  for (int i = 0; i < 60; ++i) {
    const double t = 0.01 * i;
    const double swing = 5.0 * std::sin(8.0 * t);
    double x = 34.7 * std::cos(20.0 * (t - 0.3));
    smooth.t.push_back(t);
    smooth.omega.emplace_back(x, 3.0 + swing, 2.0 - swing);
    // Beside the plateau x stays near it (33 rad/s, not a spike's low neighbours): only the
    // plateau's drift against the swing marks it.
    x = i >= 24 && i < 36 ? 35.600 - 0.005 * (i - 24) : 33.0 - 0.1 * std::abs(i - 30);
    plateau.t.push_back(t);
    plateau.omega.emplace_back(x, 3.0 + swing, 2.0 - swing);
  }
  const Saturation found = find_saturation(pool_recordings({plateau}));
  ASSERT_TRUE(found.range.has_value());
  EXPECT_NEAR(*found.range, 2000.0 * M_PI / 180.0, 1e-12);
  for (int i = 0; i < 60; ++i) EXPECT_EQ(found.at_range[i], i >= 24 && i < 36) << i;
  EXPECT_FALSE(find_saturation(pool_recordings({smooth})).range.has_value());
}

}  // namespace
}  // namespace bookspin::fit

namespace bookspin::fit {
namespace {

/// Every `every`-th sample of `recording` from sample `phase` on, between `from` and `to` s,
/// pooled.
GyroRecording thinned(const GyroRecording& recording, int every, int phase, double from,
                      double to) {
  GyroRecording out;
  out.name = recording.name;
  out.source = recording.source;
  for (std::size_t i = static_cast<std::size_t>(phase); i < recording.t.size(); i += every)
    if (recording.t[i] >= from && recording.t[i] <= to)
      out.t.push_back(recording.t[i]), out.omega.push_back(recording.omega[i]);
  return pool_recordings({out});
}

// The relation "fewer samples make no clip" (docs/phone-lab.md, "Saturation"): 12-13-51's flight
// alone (2.241–3.234 s, its largest |ω_i| 17.6 rad/s, in the band of ±1000 °/s) holds a smooth
// peak of ω_x, 17.3 → 17.52 → 17.3 rad/s over 0.17 s while y and z swing through 4 rad/s: at
// 100 Hz it changes by 5.1 % of their swing, no plateau; every second or third sample of it (a
// browser's 50 or 33 Hz, each phase) catches fewer of its low ends and changed by under 5 %, read
// as a clip at 1000 °/s (8 samples of the flight left out of the fit, and the flight cut where a
// late stamp fell beside them). A smooth peak stands above both ends of its run; a clip does not:
// no thinning of the flight is a clip, and the drifting plateau of
// ADriftingPlateauAtAStandardFullScaleIsFound, thinned alike, still is.
TEST(Saturation, FewerSamplesOfASmoothPeakAreNoClip) {
  REQUIRE_REAL_RECORDINGS();
  const GyroRecording whole = read_recording(real_dir() / "12-13-51");
  ASSERT_FALSE(find_saturation(thinned(whole, 1, 0, 2.241, 3.234)).range.has_value());
  for (int every : {2, 3})
    for (int phase = 0; phase < every; ++phase)
      EXPECT_FALSE(find_saturation(thinned(whole, every, phase, 2.241, 3.234)).range.has_value())
          << "every " << every << ", from " << phase;
  GyroRecording plateau;
  plateau.source = "plateau.csv";
  for (int i = 0; i < 60; ++i) {
    const double t = 0.01 * i, swing = 5.0 * std::sin(8.0 * t);
    plateau.t.push_back(t);
    plateau.omega.emplace_back(
        i >= 24 && i < 36 ? 35.600 - 0.005 * (i - 24) : 33.0 - 0.1 * std::abs(i - 30), 3.0 + swing,
        2.0 - swing);
  }
  for (int every : {2, 3})
    for (int phase = 0; phase < every; ++phase)
      EXPECT_TRUE(find_saturation(thinned(plateau, every, phase, 0.0, 1.0)).range.has_value())
          << "every " << every << ", from " << phase;
}

}  // namespace
}  // namespace bookspin::fit
