// The kinds of fault planted in the lab that its earlier tests let through: each rule stated
// by a case that only the rule passes (docs/phone-lab.md).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>

#include "common/errors.hpp"
#include "common/number_text.hpp"
#include "fit/flights.hpp"
#include "fit/pool.hpp"
#include "fit/recording.hpp"
#include "fit/rest.hpp"
#include "fit/saturation.hpp"
#include "fit/toss_fit.hpp"
#include "support/scratch.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

// A folder given with a trailing slash, as shell completion writes it, keeps its own name.
TEST(PlantedKinds, AFolderWithATrailingSlashIsNamedAfterItself) {
  const auto dir = bookspin::test::fresh_dir("fit/trailing-slash");
  const test::SyntheticRecording rec =
      test::make_recording(test::phone_alone(), {{{0.3, 14.0, 0.5}, 1.0}});
  test::write_export(dir / "anna", rec, test::Dialect::comma);
  EXPECT_EQ(read_recording((dir / "anna").string() + "/").name, "anna");
  EXPECT_EQ(read_recording(dir / "anna").name, "anna");
  // A folder of one CSV (phyphox's single-CSV export) likewise.
  std::filesystem::create_directories(dir / "ben");
  std::ofstream(dir / "ben" / "Gyroscope rotation rate 2022-05-03.csv")
      << test::raw_data_csv(rec, test::Dialect::comma);
  EXPECT_EQ(read_recording((dir / "ben").string() + "/").name, "ben");
  EXPECT_EQ(read_recording(dir / "ben").name, "ben");
}

// Two recordings are one only when their times and their samples both agree: two students'
// plain CSVs on one clock (the same times, other samples) are two, and so are the same
// samples at other times.
TEST(PlantedKinds, TwoRecordingsAreOneOnlyWhenTimesAndSamplesBothAgree) {
  const test::SyntheticRecording a =
      test::make_recording(test::phone_alone(), {{{0.3, 14.0, 0.5}, 1.0}}, 1);
  test::SyntheticRecording b = a;
  for (Eigen::Vector3d& w : b.omega) w *= 1.01;
  EXPECT_NO_THROW(pool_recordings({test::as_read(a, "anna"), test::as_read(b, "ben")}));
  test::SyntheticRecording c = a;
  for (double& t : c.t) t += 0.5;
  EXPECT_NO_THROW(pool_recordings({test::as_read(a, "anna"), test::as_read(c, "chloe")}));
  EXPECT_THROW(pool_recordings({test::as_read(a, "anna"), test::as_read(a, "copy")}), InputError);
}

// The bias in flight may leave its still rest's mean by 3 standard errors of that mean plus the
// drift, not by 3 times the samples' scatter: 2 s of white noise of 0.01 rad/s at 100 Hz is
// a mean known to 0.0007 rad/s.
TEST(PlantedKinds, TheBiasBoundIsTheStandardErrorOfTheRestsMeanNotItsScatter) {
  std::mt19937 random(3);
  std::normal_distribution<double> gauss(0.0, 0.01);
  std::vector<double> t;
  std::vector<Eigen::Vector3d> omega;
  for (int i = 0; i < 200; ++i) {
    t.push_back(0.01 * i);
    omega.emplace_back(0.005 + gauss(random), gauss(random), gauss(random));
  }
  const Rest rest = find_rest(t, omega, {{0, 200}});
  ASSERT_GT(rest.samples, 150);
  for (int c = 0; c < 3; ++c) {
    const double standard_error = 0.01 / std::sqrt(rest.samples);
    const double from_the_mean = rest.bound()[c] - kBiasDrift - kHandTurn;
    EXPECT_NEAR(from_the_mean, 3.0 * standard_error, 1.5 * standard_error) << c;
    EXPECT_LT(from_the_mean, 0.5 * 3.0 * rest.sigma[c]) << c;
  }
}

// σ's decimal place comes from σ rounded to two significant digits, as the page's rule: 0.0096
// keeps four decimals, 0.000097 six.
TEST(PlantedKinds, SigmasDecimalPlaceIsFromTwoSignificantDigits) {
  EXPECT_EQ(plus_minus(0.2197, 0.0096), "0.2197 ± 0.0096");
  EXPECT_EQ(plus_minus(0.7965123, 0.000097), "0.796512 ± 0.000097");
  EXPECT_EQ(plus_minus(0.5, 0.096), "0.500 ± 0.096");
}

}  // namespace
}  // namespace bookspin::fit

namespace bookspin::fit {
namespace {

// One axis in °/s, two in rad/s (each axis in turn): refused naming that cause, or fitted with
// every toss flagged for it; never "the fit did not converge" alone.
TEST(PlantedKinds, MixedUnitsAreNamedAsTheCause) {
  for (int c = 0; c < 3; ++c) {
    test::SyntheticRecording rec = test::make_recording(
        test::phone_alone(), {{{1.0, 18.0, 1.2}, 1.3}, {{-1.2, 17.0, 1.5}, 1.2}}, 91);
    for (Eigen::Vector3d& w : rec.omega) w[c] *= 180.0 / 3.14159265358979323846;
    const GyroRecording recording = test::as_recording(rec);
    try {
      const FitResult fit = fit_recording(recording, find_flights(recording));
      for (const TossFit& toss : fit.tosses)
        EXPECT_NE(toss.flag.find("°/s"), std::string::npos) << "axis " << c << ": " << toss.flag;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("°/s"), std::string::npos) << c << ": " << e.what();
    }
  }
}

}  // namespace
}  // namespace bookspin::fit

namespace bookspin::fit {
namespace {

// A clipped spike has both neighbours low; a steep unclipped peak in the full scale's band with
// one neighbour low (a fast rise, a slower fall) is the motion, kept: no range found.
TEST(PlantedKinds, ASteepPeakWithOneNeighbourLowIsNoClip) {
  std::vector<double> t;
  std::vector<Eigen::Vector3d> omega;
  const double peak[] = {20.0, 25.0, 30.0, 35.0, 33.5, 32.0, 28.0, 22.0};
  for (int i = 0; i < 40; ++i) {
    t.push_back(0.01 * i);
    const double x = i >= 10 && i < 18 ? peak[i - 10] : 0.0;
    omega.emplace_back(x, 1.0 + 0.01 * i, -0.5);
  }
  const GyroRecording steep = pool_recordings({samples_recording("steep", t, omega)});
  EXPECT_FALSE(find_saturation(steep).range.has_value());
  // The same peak cut flat, both neighbours low: a clip at ±2000 °/s.
  omega[14][0] = 29.0;
  const GyroRecording cut = pool_recordings({samples_recording("cut", t, omega)});
  const Saturation clipped = find_saturation(cut);
  ASSERT_TRUE(clipped.range.has_value());
  EXPECT_NEAR(*clipped.range, 2000.0 * 3.14159265358979323846 / 180.0, 1e-9);
  EXPECT_TRUE(clipped.at_range[13]);
}

}  // namespace
}  // namespace bookspin::fit
