// A toss is stable when ω stays within 25° of the axis it circles (docs/phone-lab.md): two
// wobbles about the largest axis, one reaching ~35° from it and one ~11°, beside two flipping
// tosses that fix the body. The largest angle is measured on the generator's own RK4
// (synthetic_recording.hpp), not on the fit.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "fit/flights.hpp"
#include "fit/recording.hpp"
#include "fit/toss_fit.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

/// The largest angle (degrees) between ω and principal axis 3 over `flight` s from ω0.
double largest_angle(const Eigen::Vector3d& moments, const Eigen::Vector3d& omega0, double flight) {
  double largest = 0.0;
  Eigen::Vector3d w = omega0;
  for (int i = 0; i * 1e-3 <= flight; ++i) {
    largest = std::max(largest, std::acos(std::abs(w[2]) / w.norm()) * 180.0 / M_PI);
    w = test::rk4(moments, w, 1e-3);
  }
  return largest;
}

TEST(StableTosses, AWobbleBeyondTwentyFiveDegreesIsNotStableAndOneWithinIs) {
  const test::SyntheticBody body = test::phone_on_book();
  const std::vector<test::SyntheticToss> tosses{{{0.5, 12.0, 0.4}, 1.2},
                                                {{-0.3, 11.0, 0.7}, 1.3},
                                                {{5.0, 0.0, 9.0}, 1.5},
                                                {{2.0, 0.0, 10.0}, 1.5}};
  const double wide = largest_angle(body.moments, tosses[2].omega0_principal, 1.5);
  const double narrow = largest_angle(body.moments, tosses[3].omega0_principal, 1.5);
  ASSERT_GT(wide, 30.0) << wide;
  ASSERT_LT(wide, 40.0) << wide;
  ASSERT_LT(narrow, 20.0);
  const test::SyntheticRecording synthetic = test::make_recording(body, tosses, 9);
  std::vector<std::pair<double, double>> ranges;
  for (const test::TrueToss& t : synthetic.tosses) ranges.emplace_back(t.t_start, t.t_end);
  const GyroRecording recording = test::as_recording(synthetic);
  FitSettings settings;
  settings.drag = physics::DragLaw::none;
  const FitResult fit = fit_recording(recording, hand_flights(recording, ranges), settings);
  ASSERT_EQ(fit.tosses.size(), 4u);
  EXPECT_FALSE(fit.tosses[0].stable);
  EXPECT_FALSE(fit.tosses[1].stable);
  EXPECT_FALSE(fit.tosses[2].stable) << "ω reaches " << wide << "° from its axis";
  EXPECT_TRUE(fit.tosses[3].stable) << "ω reaches " << narrow << "° from its axis";
}

}  // namespace
}  // namespace bookspin::fit
