// A hand that turns slowly at rest (docs/phone-lab.md, "The bias"): the mean ω where the phone
// lies "still" is the gyroscope's bias plus the hand's turn, which no rest alone tells apart. On
// seeded synthetic recordings at 25 Hz, 100 Hz, 1 kHz and 10 kHz whose rests turn 0–0.02 rad/s
// about x, y or z (the bias zero or a phone's), with throws and catches that push and the
// flights found by the finder as a user runs the fit (fit_report), the truth (the moment ratios,
// each toss's drag rate) lies within 2σ in 90–99 % of the cases at each rate.
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

TEST(HandAtRest, TruthWithinTwoSigmaWhenTheRestTurnsUpToTwoHundredthsOfARadianASecond) {
  struct RateCase {
    double rate;     ///< Hz
    int recordings;  ///< seeds
    double flight;   ///< s, the first toss's
  };
  const RateCase cases[] = {
      {25.0, 48, 1.2}, {100.0, 36, 1.2}, {1000.0, 24, 0.9}, {10000.0, 12, 0.8}};
  const test::SyntheticBody body = test::phone_on_book();
  const Eigen::Vector3d truth = body.moments / body.moments[2];
  std::printf("rate (Hz)  recordings  moments within 2σ  drag within 2σ  all  flagged\n");
  for (const RateCase& c : cases) {
    Tally moments, drag, all;
    int flagged = 0, values = 0;
    for (int n = 0; n < c.recordings; ++n) {
      const unsigned seed = 1700u + static_cast<unsigned>(n);
      std::mt19937 random(seed);
      std::uniform_real_distribution<double> unit(0.0, 1.0), jitter(-0.2, 0.2);
      // The hand's turn: 0–0.02 rad/s about one axis, either sense.
      Eigen::Vector3d turn = Eigen::Vector3d::Zero();
      turn[n % 3] = (n % 2 ? -1.0 : 1.0) * 0.02 * unit(random);
      const Eigen::Vector3d bias =
          n % 4 < 2 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(0.021, -0.014, 0.008);
      const double rate = n % 2 ? 0.05 : 0.0;  // 1/s, isotropic linear drag, or none
      const std::vector<test::SyntheticToss> tosses = {
          {{0.5 + jitter(random), 12.0, 0.4 + jitter(random)}, c.flight},
          {{-0.3 + jitter(random), -11.0, 0.7 + jitter(random)}, c.flight + 0.1}};
      const test::SyntheticRecording s = test::make_recording(
          body, tosses, seed, 0.01, 0.15, 4.0, rate, c.rate, std::nullopt, turn, bias);
      FitRequest request;
      request.settings.drag = rate > 0.0 ? physics::DragLaw::linear : physics::DragLaw::none;
      const FitResult fit = fit_report(test::as_recording(s), request).result;
      ASSERT_EQ(fit.tosses.size(), 2u) << c.rate << " Hz, seed " << seed;
      ASSERT_TRUE(fit.body.ratio_sigma) << c.rate << " Hz, seed " << seed;
      values += 2;
      if (!fit.body.moments_determined) {
        flagged += 2;
      } else {
        for (int i = 0; i < 2; ++i) {
          const double error = fit.body.ratios[i] - truth[i], sigma = (*fit.body.ratio_sigma)[i];
          moments.add(error, sigma);
          all.add(error, sigma);
          if (std::getenv("HAND_AT_REST_VERBOSE"))
            std::printf("  %g Hz seed %u turn %g axis %d: I%d/I3 off %.2fσ\n", c.rate, seed,
                        turn[n % 3], n % 3, i + 1, error / sigma);
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
      }
    }
    std::printf("%9.0f  %10d  %7d/%-3d %5.1f %%  %5d/%-3d %5.1f %%  %5.1f %%  %d/%d\n", c.rate,
                c.recordings, moments.within, moments.count, 100 * moments.fraction(), drag.within,
                drag.count, 100 * drag.fraction(), 100 * all.fraction(), flagged, values);
    EXPECT_GE(all.fraction(), 0.90) << c.rate << " Hz: the σ are too small (over-confident)";
    EXPECT_LE(all.fraction(), 0.99) << c.rate << " Hz: the σ are too large (under-confident)";
    EXPECT_LE(flagged, values / 10) << c.rate << " Hz: most values flagged, few judged";
  }
}

}  // namespace
}  // namespace bookspin::fit
