// The fit against synthetic recordings made independently (synthetic_recording.hpp): the
// moment ratios within 1 %, the principal axes within 1°, half_period_predicted within 2 % of
// the closed form.
#include "fit/toss_fit.hpp"

#include <gtest/gtest.h>

#include "fit/flights.hpp"
#include "fit/recording.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

using test::SyntheticBody;
using test::SyntheticToss;

GyroRecording as_recording(const test::SyntheticRecording& synthetic) {
  GyroRecording recording;
  recording.name = "synthetic";
  recording.source = "synthetic.csv";
  recording.t = synthetic.t;
  recording.omega = synthetic.omega;
  recording.pauses = synthetic.pauses;
  return recording;
}

/// Angle (degrees) between two axes, sign ignored.
double axis_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::min(1.0, std::abs(a.normalized().dot(b.normalized())))) * 180.0 / M_PI;
}

void expect_body_recovered(const SyntheticBody& body, const std::vector<SyntheticToss>& tosses,
                           unsigned seed) {
  const test::SyntheticRecording synthetic = test::make_recording(body, tosses, seed);
  const GyroRecording recording = as_recording(synthetic);
  const FitResult fit = fit_recording(recording, find_flights(recording));
  ASSERT_EQ(fit.tosses.size(), tosses.size());
  const Eigen::Vector3d ratios = body.moments / body.moments[2];
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(fit.body.ratios[i], ratios[i], 0.01 * ratios[i]) << "ratio " << i;
    EXPECT_LT(axis_angle(fit.body.axes.col(i), body.axes.col(i)), 1.0) << "axis " << i;
  }
  ASSERT_TRUE(fit.body.ratio_sigma.has_value());
  for (std::size_t k = 0; k < tosses.size(); ++k) {
    const TossFit& toss = fit.tosses[k];
    const double truth = synthetic.tosses[k].half_period;
    EXPECT_FALSE(toss.stable);
    ASSERT_TRUE(toss.half_period_predicted.has_value()) << "toss " << k;
    EXPECT_NEAR(*toss.half_period_predicted, truth, 0.02 * truth) << "toss " << k;
    ASSERT_TRUE(toss.half_period_fitted.has_value());
    EXPECT_NEAR(*toss.half_period_fitted, truth, 0.01 * truth) << "toss " << k;
    EXPECT_LT(toss.residual_rms, 0.05);       // the noise is 0.01 rad/s a component
    EXPECT_LT(std::abs(toss.L_decay), 0.02);  // no drag in the synthetic flights
  }
}

TEST(TossFit, RecoversAPhoneAlone) {
  expect_body_recovered(
      test::phone_alone(),
      {{{0.3, 14.0, 0.5}, 1.2}, {{-0.4, 13.0, 0.6}, 1.1}, {{0.5, -15.0, -0.3}, 1.3}}, 11);
}

TEST(TossFit, RecoversAPhoneOnABook) {
  expect_body_recovered(
      test::phone_on_book(),
      {{{0.5, 12.0, 0.4}, 1.2}, {{-0.3, 11.0, 0.7}, 1.2}, {{0.6, -13.0, -0.5}, 1.1}}, 12);
}

TEST(TossFit, RecoversARacquetWithTwoNearlyEqualMoments) {
  expect_body_recovered(
      test::racquet(),
      {{{0.4, 14.0, 0.8}, 1.2}, {{-0.6, 12.0, 0.9}, 1.3}, {{0.5, -13.0, -0.7}, 1.2}}, 13);
}

}  // namespace
}  // namespace bookspin::fit
