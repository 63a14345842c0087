// The fit's σ calibrated (docs/phone-lab.md, "Error bars"): seeded synthetic recordings at
// 25 Hz to 10 kHz, with and without drag, the truth (the moment ratios the recording was made
// with, and each toss's drag rate) within 2σ of the fitted value in 90–99 % of them at every
// rate: neither over- nor under-confident. The recordings are tests/fit/synthetic_recording.hpp's
// (Euler's equations by RK4, the rest a hand's slow wobble plus white noise), shorter at the high
// rates to keep the run short.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "coverage_tally.hpp"
#include "fit/flights.hpp"
#include "fit/toss_fit.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

struct RateCase {
  double rate;     ///< Hz
  int recordings;  ///< seeds per drag setting
  double flight;   ///< s per toss
};

using test::Tally;

/// `count` (2 or 3) tosses near the intermediate axis (they flip), each seed's ω0 turned a
/// little. Two tosses give the body's σ from the covariance alone (no jackknife under three
/// folds), three the larger of it and the jackknife's.
std::vector<test::SyntheticToss> tosses_for(unsigned seed, double flight, int count) {
  std::mt19937 random(seed * 7919u + 1u);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  std::vector<test::SyntheticToss> tosses = {
      {{0.5 + jitter(random), 12.0, 0.4 + jitter(random)}, flight},
      {{-0.3 + jitter(random), 11.0, 0.7 + jitter(random)}, flight + 0.1},
      {{0.6 + jitter(random), -13.0, -0.5 + jitter(random)}, flight - 0.1}};
  tosses.resize(count);
  return tosses;
}

TEST(SigmaCalibration, TruthWithinTwoSigmaInNinetyToNinetyNinePercentAtEveryRate) {
  const RateCase cases[] = {{25.0, 12, 1.2}, {100.0, 12, 1.2}, {1000.0, 8, 0.9}, {10000.0, 6, 0.8}};
  const test::SyntheticBody body = test::phone_on_book();
  const Eigen::Vector3d truth = body.moments / body.moments[2];
  std::printf("rate (Hz)  recordings  moments within 2σ  drag within 2σ  all\n");
  for (const RateCase& c : cases) {
    Tally moments, drag, all;
    for (int n = 0; n < 2 * c.recordings; ++n) {
      const unsigned seed = 100u + static_cast<unsigned>(n);
      const double rate = n % 2 ? 0.05 : 0.0;  // 1/s, isotropic linear drag, or none
      // Three tosses, then two, in turn.
      const test::SyntheticRecording s = test::make_recording(
          body, tosses_for(seed, c.flight, n % 4 < 2 ? 3 : 2), seed, 0.01, 0.15, 4.0, rate, c.rate);
      const GyroRecording recording = test::as_recording(s);
      std::vector<std::pair<double, double>> ranges;
      for (const test::TrueToss& t : s.tosses) ranges.emplace_back(t.t_start, t.t_end);
      FitSettings settings;
      settings.drag = rate > 0.0 ? physics::DragLaw::linear : physics::DragLaw::none;
      const FitResult fit = fit_recording(recording, hand_flights(recording, ranges), settings);
      ASSERT_TRUE(fit.body.ratio_sigma.has_value()) << c.rate << " Hz, seed " << seed;
      for (int i = 0; i < 2; ++i) {
        moments.add(fit.body.ratios[i] - truth[i], (*fit.body.ratio_sigma)[i]);
        all.add(fit.body.ratios[i] - truth[i], (*fit.body.ratio_sigma)[i]);
      }
      for (const TossFit& toss : fit.tosses) {
        if (!toss.drag_rate_sigma) continue;
        drag.add(toss.drag_rate - rate, *toss.drag_rate_sigma);
        all.add(toss.drag_rate - rate, *toss.drag_rate_sigma);
      }
    }
    std::printf("%9.0f  %10d  %7d/%-3d %5.1f %%  %5d/%-3d %5.1f %%  %5.1f %%\n", c.rate,
                2 * c.recordings, moments.within, moments.count, 100 * moments.fraction(),
                drag.within, drag.count, 100 * drag.fraction(), 100 * all.fraction());
    EXPECT_GE(all.fraction(), 0.90) << c.rate << " Hz: the σ are too small (over-confident)";
    EXPECT_LE(all.fraction(), 0.99) << c.rate << " Hz: the σ are too large (under-confident)";
  }
}

}  // namespace
}  // namespace bookspin::fit
