// The prediction under drag (docs/phone-lab.md, "The fit"; docs/physics.md §21): each toss's
// half_period_predicted uses the body of the other folds and, as its drag rate, the mean of
// their tosses' rates. These tosses flip less than twice in flight (T/2 of 1.5–1.9 s), so the
// prediction is the damped T/2 at the flight's middle m: under the linear law of rate r,
// s(t) = (1 − e^{−rt})/r and the next flip comes at t' = −ln(1 − r (s(m) + T/2))/r, so
// T/2(m) = t' − m, with T/2 = 2K(k)/λ the closed form of the generator (synthetic_recording.hpp).
// At r = 0.15 /s that is ~30 % over T/2: a prediction without the folds' rate, or with their
// sum, misses it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "fit/flights.hpp"
#include "fit/recording.hpp"
#include "fit/toss_fit.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

TEST(HeldOutDrag, EachPredictionIsTheDampedHalfPeriodAtTheFlightsMiddle) {
  const double r = 0.15;
  const test::SyntheticBody body = test::phone_on_book();
  const std::vector<test::SyntheticToss> tosses{
      {{0.5, 12.0, 0.4}, 1.2}, {{-0.3, 11.0, 0.7}, 1.3}, {{0.6, -13.0, -0.5}, 1.1}};
  test::SyntheticDrag air;
  air.rate = r;
  const test::SyntheticRecording synthetic =
      test::make_recording(body, tosses, 41, 0.01, 0.15, 4.0, 0.0, 100.0, air);
  std::vector<std::pair<double, double>> ranges;
  for (const test::TrueToss& t : synthetic.tosses) ranges.emplace_back(t.t_start, t.t_end);
  const GyroRecording recording = test::as_recording(synthetic);
  const FitResult fit = fit_recording(recording, hand_flights(recording, ranges));
  ASSERT_EQ(fit.tosses.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const double half = synthetic.tosses[k].half_period;
    ASSERT_GT(half, tosses[k].flight) << "toss " << k << " flips twice in flight";
    // The middle of the flight's samples, from its start.
    double first = -1.0, last = -1.0;
    for (double t : recording.t)
      if (t >= ranges[k].first && t <= ranges[k].second) {
        if (first < 0) first = t;
        last = t;
      }
    const double m = 0.5 * (first + last) - ranges[k].first;
    const double s = (1.0 - std::exp(-r * m)) / r;
    ASSERT_LT(r * (s + half), 1.0);
    const double expected = -std::log(1.0 - r * (s + half)) / r - m;
    ASSERT_GT(expected, 1.2 * half);  // the drag shows
    ASSERT_TRUE(fit.tosses[k].half_period_predicted.has_value()) << "toss " << k;
    EXPECT_NEAR(*fit.tosses[k].half_period_predicted, expected, 0.02 * expected) << "toss " << k;
  }
}

}  // namespace
}  // namespace bookspin::fit
