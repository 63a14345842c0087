// The bias correction held within its rest's bound (docs/phone-lab.md, "The bias") where the
// flights pull it onto the bound: the fit must still reach the least squares' minimum there, so
// that a flight three samples shorter (of about a thousand) moves the body by a small part of
// its σ: under 0.4σ (the fit reaching its minimum moves it by 0.21σ at most on these ten
// recordings). A solve that stalls on the bound's wall stops wherever its steps happen to
// shrink, which those few samples moved by up to 0.6σ here and 3σ on other recordings.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "fit/report.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

TEST(BoundedBias, AFlightAFewSamplesShorterMovesTheBodyByLittleOfItsSigma) {
  const test::SyntheticBody body = test::phone_on_book();
  int on_bound = 0;
  for (unsigned seed = 7001; seed < 7021; seed += 2) {
    std::mt19937 random(seed * 7919u + 3u);
    std::uniform_real_distribution<double> jitter(-0.2, 0.2);
    const std::vector<test::SyntheticToss> tosses = {
        {{0.5 + jitter(random), 12.0, 0.4 + jitter(random)}, 0.9},
        {{-0.3 + jitter(random), -11.0, 0.7 + jitter(random)}, 1.0}};
    // 1 kHz, a linear drag of 0.05/s: the rest turns 0.03 rad/s about y, twice the hand's
    // allowance (fit/rest.hpp, kHandTurn), which puts its y bias about its bound off.
    const test::SyntheticRecording s =
        test::make_recording(body, tosses, seed, 0.01, 0.15, 4.0, 0.05, 1000.0, std::nullopt,
                             Eigen::Vector3d(0.0, 0.03, 0.0));
    const GyroRecording recording = test::as_recording(s);
    FitRequest whole;
    whole.settings.drag = physics::DragLaw::linear;
    for (const test::TrueToss& t : s.tosses) whole.tosses.emplace_back(t.t_start, t.t_end);
    const FitResult a = fit_report(recording, whole).result;
    ASSERT_TRUE(a.body.ratio_sigma) << seed;
    const RecordingPart& part = a.parts.at(0);
    for (int i = 0; i < 3; ++i)
      on_bound += std::abs(std::abs(part.bias_correction[i]) - part.rest.bound()[i]) < 1e-9;
    {
      const double shorter = 0.003;  // s: 3 samples less at each start
      FitRequest cut = whole;
      for (auto& range : cut.tosses) range.first += shorter;
      const FitResult b = fit_report(recording, cut).result;
      ASSERT_TRUE(b.body.ratio_sigma) << seed;
      for (int i = 0; i < 2; ++i) {
        const double moved = (b.body.ratios[i] - a.body.ratios[i]) / (*a.body.ratio_sigma)[i];
        std::printf("seed %u, starts %.0f ms later: I%d/I3 moved %+.2fσ\n", seed, 1e3 * shorter,
                    i + 1, moved);
        EXPECT_LT(std::abs(moved), 0.4) << "seed " << seed << ", I" << i + 1 << "/I3";
      }
    }
  }
  // The case the test is for: some corrections end on their bound.
  EXPECT_GE(on_bound, 1);
}

}  // namespace
}  // namespace bookspin::fit
