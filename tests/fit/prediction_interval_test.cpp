// The predicted half periods' intervals, measured (docs/phone-lab.md, "Prediction intervals"):
// over the synthetic recordings the measured half period within 2σ of the prediction for at
// least 90 % of the tosses with both (a calibrated interval), over the development recordings
// too; the median interval's width printed for the docs' table.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "fit/flights.hpp"
#include "fit/pool.hpp"
#include "fit/recording.hpp"
#include "fit/toss_fit.hpp"
#include "real_recordings.hpp"
#include "synthetic_recording.hpp"

namespace bookspin::fit {
namespace {

namespace fs = std::filesystem;

/// The tosses with a measured and a predicted half period: how many, how many within 2σ (one
/// with no σ is not), and each interval's relative half width 2σ/T.
struct Calibration {
  int tosses = 0, within = 0, withheld = 0, uncalibrated = 0;
  std::vector<double> widths;
  void add(const FitResult& fit, const std::string& what) {
    for (const TossFit& t : fit.tosses) {
      if (!t.half_period_predicted) {
        if (t.half_period_measured) {
          ++withheld;
          std::cout << what << " " << t.flight.t_start << " s: measured " << *t.half_period_measured
                    << ", not predicted: " << t.not_predicted << "\n";
        }
        continue;
      }
      if (!t.half_period_measured) continue;
      // Shown with no interval (uncalibrated: too few other tosses to calibrate it on): said in
      // words, and not counted.
      if (!t.half_period_predicted_sigma) {
        ++uncalibrated;
        EXPECT_EQ(t.prediction_interval.rfind("uncalibrated: ", 0), 0u) << t.prediction_interval;
        continue;
      }
      ++tosses;
      const double off = std::abs(*t.half_period_measured - *t.half_period_predicted);
      const double sigma = t.half_period_predicted_sigma.value_or(0.0);
      within += t.half_period_predicted_sigma && off <= 2.0 * sigma;
      if (t.half_period_predicted_sigma) widths.push_back(2.0 * sigma / *t.half_period_predicted);
      std::cout << what << " " << t.flight.t_start << " s: measured " << *t.half_period_measured
                << ", predicted " << *t.half_period_predicted << " ± " << sigma << " ("
                << off / std::max(sigma, 1e-12) << " σ) from its first " << *t.predicted_window
                << " s\n";
    }
  }
  double median_width() {
    if (widths.empty()) return 0.0;
    std::sort(widths.begin(), widths.end());
    return widths[widths.size() / 2];
  }
};

TEST(PredictionIntervals, RealRecordingsHoldTheMeasuredHalfPeriodWithinTwoSigma) {
  if (!fs::is_directory(real_dir())) GTEST_SKIP() << "no real recordings at " << real_dir();
  Calibration c;
  // Each body's recordings pooled (the bare phone, the plate), and each recording alone.
  const std::vector<std::vector<std::string>> pools = {
      {"12-10-56", "12-13-01", "12-13-51"}, {"12-22-44", "12-29-59", "12-38-00", "12-44-51"}};
  for (const std::vector<std::string>& names : pools) {
    std::vector<GyroRecording> recordings;
    for (const std::string& name : names) {
      recordings.push_back(read_recording(real_dir() / name));
      const GyroRecording alone = pool_recordings({recordings.back()});
      c.add(fit_recording(alone, find_flights(alone)), name);
    }
    const GyroRecording pooled = pool_recordings(recordings);
    c.add(fit_recording(pooled, find_flights(pooled)), names.front() + "+");
  }
  std::cout << "real: " << c.within << " of " << c.tosses << " within 2σ; median 2σ/T "
            << c.median_width() << "\n";
  std::cout << "real: " << c.withheld << " with a measured T/2 not predicted\n";
  std::cout << "real: " << c.uncalibrated << " shown uncalibrated, with no interval\n";
  // Calibrated by the other tosses of each fit (docs/phone-lab.md, "Prediction intervals"),
  // 2026-11-27: 1 shown with an interval, within 2σ; 1 uncalibrated; 9 withheld (the bare
  // phone's throws, calibrated on the 2 other throws alone, widened past ±25 %).
  ASSERT_GE(c.tosses, 1);
  EXPECT_GE(c.within, 0.9 * c.tosses);
}

TEST(PredictionIntervals, SyntheticRecordingsHoldTheMeasuredHalfPeriodWithinTwoSigma) {
  Calibration c;
  for (unsigned seed = 1; seed <= 12; ++seed) {
    const double spin = 14.0 + 0.5 * seed;
    const std::vector<test::SyntheticToss> tosses = {
        {{1.0, spin, 1.2}, 1.2}, {{-0.7, spin - 2.0, 1.5}, 1.0}, {{0.5, -spin + 1.0, -0.9}, 1.1}};
    const test::SyntheticRecording synthetic = test::make_recording(
        seed % 2 ? test::phone_alone() : test::phone_on_book(), tosses, 500 + seed, 0.02);
    const GyroRecording recording = test::as_recording(synthetic);
    c.add(fit_recording(recording, find_flights(recording)), "seed " + std::to_string(seed));
  }
  std::cout << "synthetic: " << c.within << " of " << c.tosses << " within 2σ; median 2σ/T "
            << c.median_width() << "\n";
  ASSERT_GE(c.tosses, 12);
  EXPECT_GE(c.within, 0.9 * c.tosses);
}

}  // namespace
}  // namespace bookspin::fit
