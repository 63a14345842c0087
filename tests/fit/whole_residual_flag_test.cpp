// The whole-residual flag (docs/phone-lab.md, "Flags"): a toss whose ω no rigid body follows,
// smoothly and throughout (no 50 ms stretch stands out), is flagged past 5 % of |ω|; the clean
// tosses of the same recording are not.
#include <gtest/gtest.h>

#include <cmath>

#include "fit/flights.hpp"
#include "fit/recording.hpp"
#include "fit/toss_fit.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

TEST(WholeResidualFlag, ATossThatNoRigidBodyFollowsIsFlaggedPastFivePercent) {
  const test::SyntheticBody body = test::phone_alone();
  test::SyntheticRecording synthetic = test::make_recording(
      body, {{{1.0, 18.0, 1.2}, 1.2}, {{-1.2, 17.0, 1.5}, 1.2}, {{0.8, 16.0, -1.0}, 1.2}}, 81);
  // Toss 2's |ω| breathes by ±10 % every 0.25 s (a body that flexes): a residual of about
  // 0.1/√2 ≈ 7 % of |ω| spread evenly over the flight, whatever rigid body is fitted.
  const test::TrueToss& truth = synthetic.tosses[1];
  for (std::size_t i = 0; i < synthetic.t.size(); ++i) {
    const double s = synthetic.t[i] - truth.t_start;
    if (s < 0.0 || synthetic.t[i] > truth.t_end) continue;
    const Eigen::Vector3d w = synthetic.omega[i] - synthetic.bias;
    synthetic.omega[i] = synthetic.bias + w * (1.0 + 0.1 * std::sin(2.0 * M_PI * s / 0.25));
  }
  std::vector<std::pair<double, double>> ranges;
  for (const test::TrueToss& t : synthetic.tosses) ranges.emplace_back(t.t_start, t.t_end);
  const GyroRecording recording = test::as_recording(synthetic);
  const FitResult fit = fit_recording(recording, hand_flights(recording, ranges));
  ASSERT_EQ(fit.tosses.size(), 3u);
  double mean_omega = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < recording.t.size(); ++i)
    if (recording.t[i] >= truth.t_start && recording.t[i] <= truth.t_end)
      mean_omega += (recording.omega[i] - synthetic.bias).norm(), ++n;
  mean_omega /= n;
  // Between the old limit (10 %) and the new (5 %).
  EXPECT_GT(fit.tosses[1].residual_rms, 0.05 * mean_omega);
  EXPECT_LT(fit.tosses[1].residual_rms, 0.10 * mean_omega);
  EXPECT_TRUE(fit.tosses[1].poor_fit);
  EXPECT_EQ(
      fit.tosses[1].flag.rfind("a body that flexes, or not a free flight: the residual is ", 0), 0u)
      << fit.tosses[1].flag;
  EXPECT_FALSE(fit.tosses[0].poor_fit) << fit.tosses[0].flag;
  EXPECT_FALSE(fit.tosses[2].poor_fit) << fit.tosses[2].flag;
}

}  // namespace
}  // namespace bookspin::fit
