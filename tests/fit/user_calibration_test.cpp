// The fit's σ calibrated as a user runs the fit (docs/phone-lab.md, "Error bars"): the flights
// found by the finder and trimmed by the fitted motion (fit_report, never handed the true
// ranges), on seeded synthetic recordings at 25 Hz, 100 Hz, 1 kHz and 10 kHz with a 0.15 s
// throw and a 0.12 s catch that push (spikes of 4 and 6 rad/s), with and without drag: the truth
// (the moment ratios the recording was made with, each toss's drag rate) within 2σ of the fitted
// value in 90–99 % of the cases at each rate and over every rate together. Each rate has 36 to
// 96 cases, enough that one case more or less moves its share by under 3 points; values the fit
// itself flags as not to be trusted are not counted (a flagged toss's drag rate, the moments
// where it says they are poorly determined), and at most 10 % of them may be flagged.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "coverage_tally.hpp"
#include "fit/report.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

using test::Tally;

/// Two tosses near the intermediate axis (they flip), each seed's ω0 turned a little.
std::vector<test::SyntheticToss> two_tosses(unsigned seed, double flight) {
  std::mt19937 random(seed * 7919u + 3u);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  return {{{0.5 + jitter(random), 12.0, 0.4 + jitter(random)}, flight},
          {{-0.3 + jitter(random), -11.0, 0.7 + jitter(random)}, flight + 0.1}};
}

TEST(UserCalibration, FoundFlightsHoldTheTruthWithinTwoSigmaAtEveryRate) {
  struct RateCase {
    double rate;     ///< Hz
    int recordings;  ///< seeds
    double flight;   ///< s, the first toss's
  };
  const RateCase cases[] = {
      {25.0, 24, 1.2}, {100.0, 24, 1.2}, {1000.0, 32, 0.9}, {10000.0, 12, 0.8}};
  const test::SyntheticBody body = test::phone_on_book();
  const Eigen::Vector3d truth = body.moments / body.moments[2];
  Tally every;
  std::printf("rate (Hz)  recordings  moments within 2σ  drag within 2σ  all  flagged\n");
  for (const RateCase& c : cases) {
    Tally moments, drag, all;
    int flagged = 0, values = 0;
    for (int n = 0; n < c.recordings; ++n) {
      const unsigned seed = 900u + static_cast<unsigned>(n);
      const double rate = n % 2 ? 0.05 : 0.0;  // 1/s, isotropic linear drag, or none
      const test::SyntheticRecording s = test::make_recording(body, two_tosses(seed, c.flight),
                                                              seed, 0.01, 0.15, 4.0, rate, c.rate);
      FitRequest request;
      request.settings.drag = rate > 0.0 ? physics::DragLaw::linear : physics::DragLaw::none;
      const FitReport report = fit_report(test::as_recording(s), request);
      const FitResult& fit = report.result;
      ASSERT_EQ(fit.tosses.size(), 2u) << c.rate << " Hz, seed " << seed;
      ASSERT_TRUE(fit.body.ratio_sigma) << c.rate << " Hz, seed " << seed;
      values += 2;
      if (!fit.body.moments_determined) {
        flagged += 2;
      } else {
        for (int i = 0; i < 2; ++i) {
          moments.add(fit.body.ratios[i] - truth[i], (*fit.body.ratio_sigma)[i]);
          all.add(fit.body.ratios[i] - truth[i], (*fit.body.ratio_sigma)[i]);
          every.add(fit.body.ratios[i] - truth[i], (*fit.body.ratio_sigma)[i]);
        }
      }
      for (const TossFit& toss : fit.tosses) {
        if (!toss.drag_rate_sigma) continue;
        ++values;
        if (toss.poor_fit) {
          ++flagged;
          continue;
        }
        drag.add(toss.drag_rate - rate, *toss.drag_rate_sigma);
        all.add(toss.drag_rate - rate, *toss.drag_rate_sigma);
        every.add(toss.drag_rate - rate, *toss.drag_rate_sigma);
      }
    }
    std::printf("%9.0f  %10d  %7d/%-3d %5.1f %%  %5d/%-3d %5.1f %%  %5.1f %%  %d/%d\n", c.rate,
                c.recordings, moments.within, moments.count, 100 * moments.fraction(), drag.within,
                drag.count, 100 * drag.fraction(), 100 * all.fraction(), flagged, values);
    EXPECT_GE(all.fraction(), 0.90) << c.rate << " Hz: the σ are too small (over-confident)";
    EXPECT_LE(all.fraction(), 0.99) << c.rate << " Hz: the σ are too large (under-confident)";
    EXPECT_LE(flagged, values / 10) << c.rate << " Hz: most values flagged, few judged";
  }
  std::printf("every rate: %d/%d, %.1f %%\n", every.within, every.count, 100 * every.fraction());
  EXPECT_GE(every.fraction(), 0.90) << "the σ are too small (over-confident)";
  EXPECT_LE(every.fraction(), 0.99) << "the σ are too large (under-confident)";
}

// The ends' term (docs/phone-lab.md, "Error bars"): the flights the finder found, fitted as it
// found them, carry a σ that the same flights given by hand (fitted as given: no finder's ends to
// doubt) do not; the difference is the spread of the body refitted with the ends moved in,
// which the test measures itself with the flights by hand moved in by 20 ms.
TEST(UserCalibration, FoundFlightsCarryTheSpreadOfTheirEndsMovedIn) {
  const test::SyntheticRecording s = test::make_recording(
      test::phone_on_book(), two_tosses(905, 0.9), 905, 0.01, 0.15, 4.0, 0.0, 1000.0);
  const GyroRecording recording = test::as_recording(s);
  FitRequest found;
  found.settings.drag = physics::DragLaw::none;
  const FitResult fit = fit_report(recording, found).result;
  ASSERT_EQ(fit.tosses.size(), 2u);
  ASSERT_TRUE(fit.body.ratio_sigma);
  // The same flights by hand: the same fit, without the ends' term.
  FitRequest by_hand = found;
  for (const TossFit& t : fit.tosses) by_hand.tosses.emplace_back(t.flight.t_start, t.flight.t_end);
  const FitResult hand = fit_report(recording, by_hand).result;
  ASSERT_TRUE(hand.body.ratio_sigma);
  for (int i = 0; i < 2; ++i) EXPECT_DOUBLE_EQ(hand.body.ratios[i], fit.body.ratios[i]) << i;
  // The spread, measured here: every start moved in by 20 ms, then every end.
  Eigen::Vector2d spread2 = Eigen::Vector2d::Zero();
  for (int side = 0; side < 2; ++side) {
    FitRequest moved = by_hand;
    for (auto& [a, b] : moved.tosses) (side == 0 ? a : b) += side == 0 ? 0.02 : -0.02;
    const FitResult m = fit_report(recording, moved).result;
    for (int i = 0; i < 2; ++i) spread2[i] += std::pow(m.body.ratios[i] - hand.body.ratios[i], 2);
  }
  for (int i = 0; i < 2; ++i) {
    const double with = (*fit.body.ratio_sigma)[i], without = (*hand.body.ratio_sigma)[i];
    std::printf("I%d/I3: σ %.3g found, %.3g by hand; the ends' spread %.3g\n", i + 1, with, without,
                std::sqrt(spread2[i]));
    EXPECT_GT(with, without) << "I" << i + 1 << "/I3: no ends' term";
    // σ² found − σ² by hand is the spread², within a factor of 3 (the test's refits take the
    // bias rule again, the term's refit the joint fit's corrections within their bounds).
    const double added = with * with - without * without;
    EXPECT_GT(added, spread2[i] / 3.0) << i;
    EXPECT_LT(added, spread2[i] * 3.0) << i;
  }
}

}  // namespace
}  // namespace bookspin::fit
