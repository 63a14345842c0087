// Each toss's chart of a pooled fit on its own recording's clock (docs/phone-lab.md, "A class's
// recordings" and "Reading the result"), held against the recording's own file read alone: for
// every toss of a pooled real set, its chart's times are samples of its own recording within its
// own flight as the toss table states it, its measured ω those samples less one constant bias,
// and its fitted lines, flips and fitted ω on that same clock.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "fit/fit_tables.hpp"
#include "fit/pool.hpp"
#include "fit/recording.hpp"
#include "fit/report.hpp"
#include "real_recordings.hpp"

namespace bookspin::fit {
namespace {

/// The fitted line at `t` by linear interpolation of the chart's curve (1 ms apart; past its last
/// point, under 1 ms before the flight's last sample, by the line through its last two).
Eigen::Vector3d curve_at(const TossChart& chart, double t) {
  const auto hi = std::lower_bound(chart.curve_t.begin(), chart.curve_t.end(), t);
  const std::size_t j = std::clamp<std::size_t>(
      static_cast<std::size_t>(hi - chart.curve_t.begin()), 1, chart.curve_t.size() - 1);
  const double f = (t - chart.curve_t[j - 1]) / (chart.curve_t[j] - chart.curve_t[j - 1]);
  return (1.0 - f) * chart.curve[j - 1] + f * chart.curve[j];
}

void expect_charts_on_their_own_clocks(const std::vector<std::string>& names) {
  std::vector<GyroRecording> own;
  for (const std::string& name : names) own.push_back(read_recording(real_dir() / name));
  const FitReport report = fit_report(pool_recordings(own), {});
  const CsvTable table = fit_toss_csv(report.result);
  ASSERT_EQ(table.columns.at(1), "recording");
  ASSERT_EQ(table.columns.at(2), "t_start");
  ASSERT_EQ(table.columns.at(3), "t_end");
  ASSERT_EQ(report.tosses.size(), table.rows.size());
  ASSERT_GE(report.tosses.size(), names.size());
  std::vector<int> per_recording(names.size(), 0);
  std::vector<Eigen::Vector3d> recording_bias(names.size());
  for (std::size_t k = 0; k < report.tosses.size(); ++k) {
    const TossChart& chart = report.tosses[k].chart;
    SCOPED_TRACE("toss " + std::to_string(k + 1) + " of " + names.front() + " pooled");
    const std::vector<CsvCell>& row = table.rows[k];
    // Its recording, as the table names it, read alone: its own file's clock.
    const std::string name = std::get<std::string>(row.at(1));
    EXPECT_EQ(chart.recording, name);
    const auto found = std::find(names.begin(), names.end(), name);
    ASSERT_NE(found, names.end()) << name;
    const GyroRecording& alone = own[static_cast<std::size_t>(found - names.begin())];
    ++per_recording[static_cast<std::size_t>(found - names.begin())];
    const double start = std::get<CsvNumber>(row.at(2)).value.value();
    const double end = std::get<CsvNumber>(row.at(3)).value.value();
    ASSERT_LT(start, end);
    ASSERT_GE(chart.t.size(), 10u);
    EXPECT_NEAR(chart.t.front(), start, 1e-9);
    EXPECT_NEAR(chart.t.back(), end, 1e-9);
    // Its times: consecutive samples of its own recording, within its flight.
    const auto first = std::lower_bound(alone.t.begin(), alone.t.end(), chart.t.front() - 1e-9);
    ASSERT_NE(first, alone.t.end());
    const std::size_t j0 = static_cast<std::size_t>(first - alone.t.begin());
    ASSERT_LE(j0 + chart.t.size(), alone.t.size());
    Eigen::Vector3d bias = Eigen::Vector3d::Zero();
    double misfit2 = 0.0;
    for (std::size_t i = 0; i < chart.t.size(); ++i) {
      ASSERT_NEAR(chart.t[i], alone.t[j0 + i], 1e-9) << "sample " << i;
      EXPECT_GE(chart.t[i], start - 1e-9);
      EXPECT_LE(chart.t[i], end + 1e-9);
      // Its measured ω: those samples less one bias, the same for every sample of the toss.
      const Eigen::Vector3d removed = alone.omega[j0 + i] - chart.measured[i];
      if (i == 0) bias = removed;
      EXPECT_LT((removed - bias).norm(), 1e-9) << "sample " << i;
      // Its fitted ω on the same clock as its lines.
      EXPECT_LT((chart.fitted[i] - curve_at(chart, chart.t[i])).norm(),
                0.01 + 1e-3 * chart.fitted[i].norm())
          << "sample " << i;
      misfit2 += (chart.fitted[i] - chart.measured[i]).squaredNorm();
    }
    EXPECT_LT(bias.norm(), 0.1) << "rad/s removed as the gyroscope's bias";
    // One bias a recording: every toss of it less the same.
    const std::size_t r = static_cast<std::size_t>(found - names.begin());
    if (per_recording[r] == 1) recording_bias[r] = bias;
    EXPECT_LT((bias - recording_bias[r]).norm(), 1e-9) << "another bias than " << name << "'s";
    // The fitted motion follows the measured one (its RMS residual well under |ω|).
    double peak = 0.0;
    for (const Eigen::Vector3d& w : chart.measured) peak = std::max(peak, w.norm());
    EXPECT_LT(std::sqrt(misfit2 / static_cast<double>(chart.t.size())), 0.2 * peak);
    // Its lines and flips span its own flight.
    ASSERT_FALSE(chart.curve_t.empty());
    EXPECT_NEAR(chart.curve_t.front(), start, 1e-9);
    EXPECT_LE(chart.curve_t.back(), end + 1e-9);
    EXPECT_GT(chart.curve_t.back(), end - 0.002);
    for (const double flip : chart.flips) {
      EXPECT_GE(flip, start);
      EXPECT_LE(flip, end);
    }
  }
  for (std::size_t r = 0; r < names.size(); ++r)
    EXPECT_GE(per_recording[r], 1) << names[r] << " has no toss in the pool";
}

TEST(PooledCharts, EveryTossIsChartedOnItsOwnRecordingsClock) {
  REQUIRE_REAL_RECORDINGS();
  expect_charts_on_their_own_clocks({"12-10-56", "12-13-01", "12-13-51"});  // the bare phone
  expect_charts_on_their_own_clocks({"12-22-44", "12-38-00"});              // the plate
}

}  // namespace
}  // namespace bookspin::fit
