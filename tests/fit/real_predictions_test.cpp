// Every measured half period of the real recordings in ../shared/recordings-real/ against its
// prediction (docs/phone-lab.md, "Prediction intervals"), as a user fits them: the flights found
// by the finder, each body's recordings pooled and each recording alone. A prediction shown with
// an interval must hold its measurement within 2σ in at least 90 % of the cases; one shown with
// no interval says in words that it is uncalibrated; none wider than ±25 % is shown.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "fit/pool.hpp"
#include "fit/prediction_sigma.hpp"
#include "fit/recording.hpp"
#include "fit/report.hpp"
#include "real_recordings.hpp"

namespace bookspin::fit {
namespace {

struct Count {
  int measured = 0;       ///< tosses with a measured half period
  int with_interval = 0;  ///< of those, predicted with a calibrated interval
  int within = 0;         ///< of those, within 2σ
  int uncalibrated = 0;   ///< predicted, no interval (too few others to calibrate on)
  int withheld = 0;       ///< not predicted (why in not_predicted)
  void add(const Count& c) {
    measured += c.measured, with_interval += c.with_interval, within += c.within;
    uncalibrated += c.uncalibrated, withheld += c.withheld;
  }
};

/// The fit of `names` pooled (one: alone), each toss with a measured half period counted and
/// printed; the rules every shown prediction keeps checked.
Count count_fit(const std::vector<std::string>& names) {
  std::vector<GyroRecording> recordings;
  for (const std::string& name : names) recordings.push_back(read_recording(real_dir() / name));
  const FitReport report = fit_report(pool_recordings(recordings), {});
  Count c;
  for (std::size_t k = 0; k < report.result.tosses.size(); ++k) {
    const TossFit& t = report.result.tosses[k];
    const std::string who = report.tosses[k].chart.recording + " toss " + std::to_string(k + 1);
    SCOPED_TRACE(who);
    if (t.half_period_predicted && t.half_period_predicted_sigma) {
      EXPECT_LE(2.0 * *t.half_period_predicted_sigma / *t.half_period_predicted,
                kWidestInterval + 1e-12);
      EXPECT_GE(*t.half_period_predicted_sigma, *t.half_period_propagated_sigma);
    }
    if (t.half_period_predicted && !t.half_period_predicted_sigma) {
      EXPECT_EQ(t.prediction_interval.rfind("uncalibrated", 0), 0u) << t.prediction_interval;
    }
    if (!t.half_period_measured) continue;
    ++c.measured;
    if (!t.half_period_predicted) {
      ++c.withheld;
      std::printf("  %-22s T/2 %.4f s, not predicted: %s\n", who.c_str(), *t.half_period_measured,
                  t.not_predicted.c_str());
      continue;
    }
    if (!t.half_period_predicted_sigma) {
      ++c.uncalibrated;
      std::printf("  %-22s T/2 %.4f s, predicted %.4f s, %s\n", who.c_str(),
                  *t.half_period_measured, *t.half_period_predicted, t.prediction_interval.c_str());
      continue;
    }
    ++c.with_interval;
    const double off =
        (*t.half_period_measured - *t.half_period_predicted) / *t.half_period_predicted_sigma;
    c.within += std::abs(off) <= 2.0 ? 1 : 0;
    std::printf("  %-22s T/2 %.4f s, predicted %.4f ± %.4f s (propagated σ %.4f): %+.1fσ, %s\n",
                who.c_str(), *t.half_period_measured, *t.half_period_predicted,
                *t.half_period_predicted_sigma, *t.half_period_propagated_sigma, off,
                t.prediction_interval.c_str());
  }
  return c;
}

TEST(RealPredictions, EveryMeasuredHalfPeriodAgainstItsPredictionPooledAndAlone) {
  REQUIRE_REAL_RECORDINGS();
  const std::vector<std::vector<std::string>> fits = {
      {"12-10-56", "12-13-01", "12-13-51"},              // the bare phone, pooled
      {"12-22-44", "12-29-59", "12-38-00", "12-44-51"},  // the plate, pooled
      {"12-10-56"},
      {"12-13-01"},
      {"12-13-51"},
      {"12-22-44"},
      {"12-29-59"},
      {"12-38-00"},
      {"12-44-51"}};
  Count all;
  for (const std::vector<std::string>& names : fits) {
    std::printf("%s%s:\n", names.front().c_str(), names.size() > 1 ? " and the others" : " alone");
    const Count c = count_fit(names);
    std::printf("  measured %d, with an interval %d, within 2σ %d, uncalibrated %d, withheld %d\n",
                c.measured, c.with_interval, c.within, c.uncalibrated, c.withheld);
    all.add(c);
  }
  std::printf("all: measured %d, with an interval %d, within 2σ %d, uncalibrated %d, withheld %d\n",
              all.measured, all.with_interval, all.within, all.uncalibrated, all.withheld);
  ASSERT_GT(all.with_interval, 0) << "no measured half period has a calibrated interval";
  EXPECT_GE(all.within, 0.9 * all.with_interval)
      << all.within << " of " << all.with_interval << " within 2σ";
}

}  // namespace
}  // namespace bookspin::fit
