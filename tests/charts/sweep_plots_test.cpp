// A sweep's line plots (charts/sweep_plots.hpp): one plot per measure against the first key,
// one line per value of the other keys, the exact curve dashed beside the measured one; the
// series checked against the table's cells placed by hand.
#include "charts/sweep_plots.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "scene/key_label.hpp"

namespace bookspin::charts {
namespace {

/// A varied key as jobs::sweep_chart makes it: its range and values, its words and caption.
SweepAxis axis(const std::string& key, double start, double stop, bool log,
               std::vector<double> values) {
  return {key,
          start,
          stop,
          log,
          std::move(values),
          scene::key_caption(key),
          scene::key_words(key).words};
}

TEST(SweepPlots, OneLinePerValueOfTheSecondKeyAndTheExactOneDashed) {
  SweepChart chart;
  chart.scene_name = "s";
  chart.axes = {axis("time.dt", 0.01, 0.02, true, {0.01, 0.02}),
                axis("model.normalize_every", 1, 2, false, {1, 2})};
  chart.measures = {analysis::find_measure("first_flip"), analysis::find_measure("energy_drift")};
  chart.header = {"time.dt", "model.normalize_every", "first_flip", "energy_drift",
                  "first_flip_exact"};
  // Grid order: the first key slowest; one run did not flip (empty cell: NaN, a break).
  chart.rows = {{"0.01", "1", "10", "0.5", "11"},
                {"0.01", "2", "20", "0.25", "21"},
                {"0.02", "1", "", "0.125", "12"},
                {"0.02", "2", "40", "1", "41"}};
  const std::vector<overlay::PlotSpec> plots = sweep_plots(chart);
  ASSERT_EQ(plots.size(), 2u);
  const overlay::PlotSpec& flips = plots[0];
  // The words lead, the keys (as in the CSV and on the command line) follow.
  EXPECT_EQ(flips.title,
            std::string(analysis::find_measure("first_flip")->axis_label) + " \u00b7 first_flip");
  EXPECT_EQ(flips.x_label, "time step dt (time units) \u00b7 time.dt (log scale)");
  EXPECT_TRUE(flips.log_x);
  ASSERT_EQ(flips.series.size(), 4u);  // 1 and 2 steps, each measured then exact
  EXPECT_EQ(flips.series[0].label, "steps between normalizations = 1");
  EXPECT_EQ(flips.series[0].x, (std::vector<double>{0.01, 0.02}));
  EXPECT_EQ(flips.series[0].y[0], 10.0);
  EXPECT_TRUE(std::isnan(flips.series[0].y[1]));
  EXPECT_FALSE(flips.series[0].dashed);
  EXPECT_EQ(flips.series[1].label, "exact, steps between normalizations = 1");
  EXPECT_EQ(flips.series[1].y, (std::vector<double>{11, 12}));
  EXPECT_TRUE(flips.series[1].dashed);
  EXPECT_EQ(flips.series[2].label, "steps between normalizations = 2");
  EXPECT_EQ(flips.series[2].y, (std::vector<double>{20, 40}));
  EXPECT_EQ(flips.series[3].y, (std::vector<double>{21, 41}));
  // energy_drift has no exact column: measured lines only.
  const overlay::PlotSpec& drift = plots[1];
  EXPECT_EQ(drift.title, std::string(analysis::find_measure("energy_drift")->axis_label) +
                             " \u00b7 energy_drift");
  ASSERT_EQ(drift.series.size(), 2u);
  EXPECT_EQ(drift.series[0].y, (std::vector<double>{0.5, 0.125}));
  EXPECT_EQ(drift.series[1].y, (std::vector<double>{0.25, 1}));
}

TEST(SweepPlots, TheSheetIsAsWideAndTallAsItsParts) {
  // One key, two measures: 120 pixels of header and one row of two plots, 300 tall, 1280 wide.
  SweepChart chart;
  chart.scene_name = "s";
  chart.axes = {axis("time.dt", 0.01, 0.02, false, {0.01, 0.02})};
  chart.measures = {analysis::find_measure("first_flip"), analysis::find_measure("energy_drift")};
  chart.header = {"time.dt", "first_flip", "energy_drift", "first_flip_exact"};
  chart.rows = {{"0.01", "10", "0.5", "11"}, {"0.02", "20", "0.25", "21"}};
  const RgbaImage sheet = sweep_sheet(chart);
  EXPECT_EQ(sheet.width, 1280);
  EXPECT_EQ(sheet.height, 120 + 300);
}

// A sweep's picture holds its header within the sheet: the title of every sweep of sweeps/
// (a sweep's title with "(sweep of …)" after it, 36 px bold, ran past the right edge: "…axis
// (s"), and a title longer than the sheet, leave no ink in the sheet's right margin over the
// header's rows.
TEST(SweepPlots, NoTitleIsCutAtThePicturesRightEdge) {
  std::vector<std::string> titles;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(BOOKSPIN_SOURCE_DIR) + "/sweeps")) {
    std::ifstream file(entry.path());
    for (std::string line; std::getline(file, line);)
      if (line.rfind("title = \"", 0) == 0) titles.push_back(line.substr(9, line.rfind('"') - 9));
  }
  ASSERT_GE(titles.size(), 5u);
  titles.push_back(
      "A title far longer than any sheet is wide, which must be broken between its words so that "
      "every one of them is seen");
  for (const std::string& title : titles) {
    SweepChart chart;
    chart.scene_name = "flip-time-vs-perturbation";
    chart.scene_title = title;
    chart.axes = {axis("initial.angular_velocity[1]", 1e-6, 1e-2, true, {1e-6, 1e-2})};
    chart.measures = {analysis::find_measure("first_flip"), analysis::find_measure("flip_period"),
                      analysis::find_measure("energy_drift"),
                      analysis::find_measure("orientation_error")};
    chart.header = {"initial.angular_velocity[1]", "first_flip", "flip_period", "energy_drift",
                    "orientation_error"};
    chart.rows = {{"1e-6", "190", "380", "1e-13", "1e-9"}, {"0.01", "55", "110", "1e-13", "1e-11"}};
    const RgbaImage sheet = sweep_sheet(chart);
    const double font = std::max(15.0, 0.024 * sheet.height);
    int ink = 0, first_y = -1;
    for (int y = 0; y < static_cast<int>(4 * font); ++y)
      for (int x = sheet.width - static_cast<int>(0.5 * font); x < sheet.width; ++x)
        if (sheet.row(y)[4 * x] < 200 && ink++ == 0) first_y = y;
    EXPECT_EQ(ink, 0) << title << ": ink in the right margin from row " << first_y;
  }
}

/// A sweep of `keys` varied keys (two values each) measuring the first `count` measures, every
/// cell filled.
SweepChart chart_of(std::size_t keys, std::size_t count) {
  SweepChart chart;
  chart.scene_name = "flip-time-vs-perturbation";
  chart.scene_title = "Flip time against the perturbation from the intermediate axis";
  const std::vector<std::string> names{"initial.angular_velocity[1]", "time.dt",
                                       "model.normalize_every"};
  for (std::size_t k = 0; k < keys; ++k) {
    chart.axes.push_back(axis(names[k], 1, 2, false, {1, 2}));
    chart.header.push_back(names[k]);
  }
  const auto& all = analysis::measure_table();
  for (std::size_t m = 0; m < count && m < all.size(); ++m) {
    chart.measures.push_back(&all[m]);
    chart.header.emplace_back(all[m].name);
  }
  // Every combination of the keys' two values, the first key slowest.
  for (std::size_t r = 0; r < (std::size_t{1} << keys); ++r) {
    std::vector<std::string> row;
    for (std::size_t k = 0; k < keys; ++k) row.push_back((r >> (keys - 1 - k)) & 1 ? "2" : "1");
    for (std::size_t m = 0; m < chart.measures.size(); ++m) row.push_back(std::to_string(m + 1));
    chart.rows.push_back(row);
  }
  return chart;
}

// Each sweep's picture is seen whole on a 1366×768 screen (docs/outputs.md, "Pictures"): at
// most 1280 wide (the gallery shows it at its own size) and 640 tall (768 less about 120 for a
// browser's bars and a taskbar), for one, two (heat maps) and three keys and any number of measures
// (four plots stacked 330 pixels each would be 1440 tall).
TEST(SweepPlots, EverySheetFitsA1366By768Screen) {
  for (std::size_t keys = 1; keys <= 3; ++keys) {
    for (std::size_t count = 1; count <= analysis::measure_table().size(); ++count) {
      const RgbaImage sheet = sweep_sheet(chart_of(keys, count));
      EXPECT_LE(sheet.width, 1280) << keys << " keys, " << count << " measures";
      EXPECT_LE(sheet.height, 640) << keys << " keys, " << count << " measures";
      EXPECT_GE(sheet.height, 400) << keys << " keys, " << count << " measures";
    }
  }
}

// Plots two a row keep their text within the sheet: an x label wider than its plot area (the
// perturbation's words and key, "(log scale)") is centred under its plot's half, not under the
// plot area, where the left plot's ran past the sheet's left edge. The sheet's outer columns
// hold no ink, for every number of measures.
TEST(SweepPlots, NoTextRunsPastTheSheetsSides) {
  for (std::size_t count = 1; count <= analysis::measure_table().size(); ++count) {
    SweepChart chart = chart_of(1, count);
    chart.axes[0] = axis("initial.angular_velocity[1]", 1e-6, 1e-2, true, {1e-6, 1e-2});
    chart.header[0] = chart.axes[0].key;
    chart.rows[0][0] = "1e-6", chart.rows[1][0] = "0.01";
    const RgbaImage sheet = sweep_sheet(chart);
    int ink = 0;
    for (int y = 0; y < sheet.height; ++y)
      for (int x : {0, 1, 2, 3, sheet.width - 4, sheet.width - 3, sheet.width - 2, sheet.width - 1})
        ink += sheet.row(y)[4 * x] < 200 ? 1 : 0;
    EXPECT_EQ(ink, 0) << count << " measures: ink at the sheet's sides";
  }
}

}  // namespace
}  // namespace bookspin::charts
