// The predictions shown on the development recordings (docs/phone-lab.md, "Prediction
// intervals"): none with an interval wider than ±25 % (2σ/T), each one withheld says why in the
// CSV and the summary (its own width, over 25 %, where that is why), and a recording shifted in
// time gives the same predictions, σ, windows and reasons.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "fit/pool.hpp"
#include "fit/recording.hpp"
#include "fit/report.hpp"
#include "real_recordings.hpp"

namespace bookspin::fit {
namespace {

/// Each development recording alone, and each body's recordings pooled (the bare phone's three,
/// the plate's four); each recording's times `shift` s later.
std::vector<GyroRecording> real_fits(double shift = 0.0) {
  const std::vector<std::vector<std::string>> bodies = {
      {"12-10-56", "12-13-01", "12-13-51"}, {"12-22-44", "12-29-59", "12-38-00", "12-44-51"}};
  std::vector<GyroRecording> all;
  for (const std::vector<std::string>& names : bodies) {
    std::vector<GyroRecording> read;
    for (const std::string& name : names) {
      read.push_back(read_recording(real_dir() / name));
      for (double& t : read.back().t) t += shift;
      for (double& t : read.back().pauses) t += shift;
      all.push_back(pool_recordings({read.back()}));
    }
    all.push_back(pool_recordings(read));
  }
  return all;
}

/// The cells of CSV text `csv` (no quoted commas in the columns read here), row by row.
std::vector<std::vector<std::string>> cells(const std::string& csv) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream lines(csv);
  for (std::string line; std::getline(lines, line);) {
    rows.emplace_back();
    std::string cell;
    bool quoted = false;
    for (char c : line) {
      if (c == '"')
        quoted = !quoted;
      else if (c == ',' && !quoted)
        rows.back().push_back(cell), cell.clear();
      else
        cell += c;
    }
    rows.back().push_back(cell);
  }
  return rows;
}

std::size_t column(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  ADD_FAILURE() << "no column " << name;
  return 0;
}

TEST(PredictionIntervals, NoPredictionShownOnRealRecordingsIsWiderThanTwentyFivePercent) {
  REQUIRE_REAL_RECORDINGS();
  int shown = 0, measured_not_shown = 0;
  for (const GyroRecording& r : real_fits()) {
    const FitReport report = fit_report(r, {});
    for (const TossFit& t : report.result.tosses) {
      measured_not_shown += t.half_period_measured && !t.half_period_predicted;
      if (!t.half_period_predicted) continue;
      ++shown;
      // No interval only where too few other tosses calibrate it, and then said in words.
      if (!t.half_period_predicted_sigma) {
        EXPECT_EQ(t.prediction_interval.rfind("uncalibrated: ", 0), 0u)
            << r.name << " " << t.flight.t_start << ": " << t.prediction_interval;
        continue;
      }
      EXPECT_LE(2.0 * *t.half_period_predicted_sigma, 0.25 * *t.half_period_predicted)
          << r.name << " " << t.flight.t_start << " s: " << *t.half_period_predicted << " ± "
          << *t.half_period_predicted_sigma;
    }
  }
  // The bare phone's throws are shown; the plate's near the separatrix are not (2026-11-27:
  // 5 shown, 6 with a measured T/2 not).
  EXPECT_GE(shown, 4);
  EXPECT_GE(measured_not_shown, 1);
}

TEST(PredictionIntervals, AWithheldPredictionSaysWhyInTheCsvAndTheSummary) {
  REQUIRE_REAL_RECORDINGS();
  int too_wide = 0;
  for (const GyroRecording& r : real_fits()) {
    const FitReport report = fit_report(r, {});
    const std::vector<std::vector<std::string>> rows = cells(report.toss_csv);
    const std::size_t predicted = column(rows.at(0), "half_period_predicted");
    const std::size_t sigma = column(rows.at(0), "half_period_predicted_sigma");
    const std::size_t why = column(rows.at(0), "not_predicted");
    const std::size_t window = column(rows.at(0), "predicted_window");
    ASSERT_EQ(rows.size(), report.result.tosses.size() + 1);
    for (std::size_t k = 0; k < report.result.tosses.size(); ++k) {
      const TossFit& t = report.result.tosses[k];
      const std::vector<std::string>& row = rows[k + 1];
      SCOPED_TRACE(r.name + " toss " + std::to_string(k + 1));
      // The summary's line of this toss.
      std::string line;
      for (const std::string& l : report.summary)
        if (l.rfind("kept toss " + std::to_string(k + 1) + ":", 0) == 0) line = l;
      ASSERT_FALSE(line.empty());
      if (t.half_period_predicted) {
        EXPECT_TRUE(row[why].empty()) << row[why];
        EXPECT_FALSE(row[window].empty());
        EXPECT_NE(line.find("T/2 predicted"), std::string::npos) << line;
        continue;
      }
      // Withheld: empty cells (never NaN), and the reason in its column and its line.
      EXPECT_TRUE(row[predicted].empty()) << row[predicted];
      EXPECT_TRUE(row[sigma].empty()) << row[sigma];
      EXPECT_TRUE(row[window].empty()) << row[window];
      ASSERT_FALSE(row[why].empty());
      EXPECT_EQ(row[why], t.not_predicted);
      EXPECT_NE(line.find("not predicted: " + t.not_predicted), std::string::npos) << line;
      // Withheld for its width: the width it names is over 25 %.
      const std::size_t at = t.not_predicted.find("interval ±");
      if (at == std::string::npos) continue;
      ++too_wide;
      const double percent =
          std::atof(t.not_predicted.c_str() + at + std::string("interval ±").size());
      EXPECT_GT(percent, 25.0) << t.not_predicted;
    }
  }
  EXPECT_GE(too_wide, 1);  // the plate's tosses near the separatrix
}

TEST(PredictionIntervals, ARealRecordingShiftedInTimeGivesTheSamePredictions) {
  REQUIRE_REAL_RECORDINGS();
  int compared = 0;
  const std::vector<GyroRecording> now = real_fits(), later = real_fits(1000.0);
  for (std::size_t i = 0; i < now.size(); ++i) {
    const GyroRecording& r = now[i];
    const FitResult a = fit_report(r, {}).result, b = fit_report(later[i], {}).result;
    ASSERT_EQ(a.tosses.size(), b.tosses.size()) << r.name;
    for (std::size_t k = 0; k < a.tosses.size(); ++k) {
      const TossFit &x = a.tosses[k], &y = b.tosses[k];
      SCOPED_TRACE(r.name + " toss " + std::to_string(k + 1));
      ASSERT_EQ(x.half_period_predicted.has_value(), y.half_period_predicted.has_value());
      EXPECT_EQ(x.not_predicted, y.not_predicted);
      if (!x.half_period_predicted) continue;
      ++compared;
      EXPECT_NEAR(*y.half_period_predicted, *x.half_period_predicted, 1e-6);
      EXPECT_EQ(x.prediction_interval, y.prediction_interval);
      ASSERT_EQ(x.half_period_predicted_sigma.has_value(),
                y.half_period_predicted_sigma.has_value());
      if (!x.half_period_predicted_sigma) continue;
      EXPECT_NEAR(*y.half_period_predicted_sigma, *x.half_period_predicted_sigma, 1e-6);
      EXPECT_EQ(x.predicted_window, y.predicted_window);
    }
  }
  EXPECT_GE(compared, 4);
}

}  // namespace
}  // namespace bookspin::fit
