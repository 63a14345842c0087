// A two-key sweep's heat maps (charts/heat_map.hpp): every cell is drawn where its CSV row's
// two key values say, in the colour of its value, and diverged cells are marked.
#include "charts/heat_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "overlay/cairo_canvas.hpp"
#include "overlay/sheet_header.hpp"

namespace bookspin::charts {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

std::string number(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", v);
  return text;
}

// A 4 × 3 grid as `bookspin sweep` writes it (first key slowest): time.dt on a log range,
// normalize_every on a linear one. orientation_error = 10^(i + 4j) ranks every cell apart on
// its log colour scale; the run at (dt[3], every[0]) diverged (diverged_at set, no error).
TEST(HeatMap, EveryCellIsWhereItsRowSaysInItsValuesColour) {
  const std::vector<double> dt{1.0 / 480, 1.0 / 120, 1.0 / 30, 1.0 / 8};  // log spaced, ×4
  const std::vector<double> every{1, 11, 21};
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 0; i < dt.size(); ++i) {
    for (std::size_t j = 0; j < every.size(); ++j) {
      const bool diverged = i == 3 && j == 0;
      const std::string line = number(dt[i]) + "," + number(every[j]) + "," +
                               (diverged ? "" : number(std::pow(10.0, i + 4.0 * j))) + "," +
                               (diverged ? "1234.5" : "");
      rows.push_back(split(line));
    }
  }
  const std::vector<std::string> header{"time.dt", "model.normalize_every", "orientation_error",
                                        "diverged_at"};
  const std::vector<const analysis::Measure*> measures{analysis::find_measure("orientation_error"),
                                                       analysis::find_measure("diverged_at")};
  const auto maps = sweep_heat_maps(header, rows, dt, true, every, false, measures);
  ASSERT_EQ(maps.size(), 2u);
  // The keys in words first, as in the CSV second (scene/key_label.hpp).
  EXPECT_EQ(maps[0].x_label, "time step dt (time units) \u00b7 time.dt");
  EXPECT_EQ(maps[0].y_label, "steps between normalizations \u00b7 model.normalize_every");
  EXPECT_NE(maps[0].value_label.find("(rad)"), std::string::npos);  // the unit on the bar

  const int width = 1400, height = 680;
  const std::vector<std::string> lines{"Sweep", "varied: time.dt", "varied: normalize_every"};
  const RgbaImage image = heat_map_sheet(lines, maps, width, height);
  const MapRect cells = heat_map_cells(width, height, lines.size(), maps.size(), 0);
  for (std::size_t i = 0; i < dt.size(); ++i) {
    for (std::size_t j = 0; j < every.size(); ++j) {
      SCOPED_TRACE("cell dt[" + std::to_string(i) + "], every[" + std::to_string(j) + "]");
      // y grows upwards: row j from the bottom.
      const int px = static_cast<int>((cells.left + (i + 0.5) * cells.width / dt.size()));
      const int py =
          static_cast<int>(cells.top + cells.height - (j + 0.5) * cells.height / every.size());
      const std::uint8_t* p = image.row(py) + 4 * px;
      if (i == 3 && j == 0) {  // the diverged run: the × crosses the cell's centre
        EXPECT_LT(p[0] + p[1] + p[2], 60);
        continue;
      }
      // log10 of the values spans 0 (dt[0], every[0]) … 11 (dt[3], every[2]).
      const auto rgb = heat_colour((i + 4.0 * j) / 11.0);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], rgb[c], 2) << "channel " << c;
    }
  }
}

// A header line longer than the sheet is wrapped (overlay/sheet_header.hpp), and the maps are
// laid out under the lines drawn, not under the lines given: the sheet of a header that wraps is
// the sheet of its wrapped lines given already wrapped, pixel for pixel, and the first map's
// cells are where heat_map_cells() puts them under that many lines. Laid out under the lines
// given, the wrapped title was drawn over the first row of maps.
TEST(HeatMap, TheMapsAreLaidOutUnderTheWrappedHeader) {
  const std::vector<double> x{1, 2, 3}, y{1, 2};
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = 0; j < y.size(); ++j)
      rows.push_back({number(x[i]), number(y[j]), number(std::pow(10.0, i + 3.0 * j))});
  const auto maps =
      sweep_heat_maps({"time.dt", "model.normalize_every", "orientation_error"}, rows, x, false, y,
                      false, {analysis::find_measure("orientation_error")});
  const int width = 900, height = 700;
  std::string varied = "varied:";
  for (int k = 0; k < 12; ++k) varied += " body.moment_" + std::to_string(k) + " \u00b7";
  varied += " the last";
  const std::vector<std::string> header{
      "A sweep whose title runs on well past the width of its sheet, so that it wraps onto a "
      "second line and a third",
      varied};
  overlay::CairoCanvas canvas(width, height);
  const double font = 0.024 * height;  // the sheets' header font (as plot_sheet_test.cpp)
  const std::vector<std::string> lines =
      overlay::wrap_sheet_header(canvas.cr(), header, font, width);
  ASSERT_GE(lines.size(), header.size() + 2) << "the header must wrap";
  ASSERT_EQ(overlay::wrap_sheet_header(canvas.cr(), lines, font, width), lines);
  const RgbaImage image = heat_map_sheet(header, maps, width, height);
  EXPECT_TRUE(image.pixels == heat_map_sheet(lines, maps, width, height).pixels)
      << "the sheet of a header that wraps is not the sheet of its wrapped lines";
  const MapRect cells = heat_map_cells(width, height, lines.size(), maps.size(), 0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    for (std::size_t j = 0; j < y.size(); ++j) {
      SCOPED_TRACE("cell x[" + std::to_string(i) + "], y[" + std::to_string(j) + "]");
      const int px = static_cast<int>(cells.left + (i + 0.5) * cells.width / x.size());
      const int py =
          static_cast<int>(cells.top + cells.height - (j + 0.5) * cells.height / y.size());
      const std::uint8_t* p = image.row(py) + 4 * px;
      const auto rgb = heat_colour((i + 3.0 * j) / 5.0);  // log10 spans 0 … 5
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(p[c], rgb[c], 2) << "channel " << c;
    }
  }
}

TEST(HeatMap, DivergedAtMapsTheTimeAndCountsTheRunsThatFinished) {
  const std::vector<double> x{1, 2}, y{1, 2};
  const std::vector<std::vector<std::string>> rows{
      {"1", "1", ""}, {"1", "2", "5"}, {"2", "1", ""}, {"2", "2", "7"}};
  const auto maps = sweep_heat_maps({"time.dt", "initial.jiggle", "diverged_at"}, rows, x, false, y,
                                    false, {analysis::find_measure("diverged_at")});
  ASSERT_EQ(maps.size(), 1u);
  EXPECT_EQ(maps[0].empty_meaning, "ran to the end");
  EXPECT_EQ(maps[0].diverged, (std::vector<char>{0, 0, 1, 1}));  // j·nx + i
  EXPECT_EQ(maps[0].value[2], 5.0);                              // (x = 1, y = 2)
  EXPECT_EQ(maps[0].value[3], 7.0);
}

// The colour bar of a measure that barely varies (diverged_at from 813.94 to 814.08 read
// "814", "814", "814") says three different numbers; one value alone is one tick.
TEST(HeatMap, ColourBarTicksTellTheirValuesApart) {
  using Ticks = std::vector<std::pair<double, std::string>>;
  EXPECT_EQ(colour_bar_ticks(813.94, 814.08, false),
            (Ticks{{0.0, "813.94"}, {0.5, "814.01"}, {1.0, "814.08"}}));
  EXPECT_EQ(colour_bar_ticks(0.284, 3.08, true),
            (Ticks{{0.0, "0.284"}, {0.5, "0.935"}, {1.0, "3.08"}}));
  EXPECT_EQ(colour_bar_ticks(0.284, 3.08, false),
            (Ticks{{0.0, "0.28"}, {0.5, "1.68"}, {1.0, "3.08"}}));
  EXPECT_EQ(colour_bar_ticks(100.0, 500.0, false),
            (Ticks{{0.0, "100"}, {0.5, "300"}, {1.0, "500"}}));
  EXPECT_EQ(colour_bar_ticks(1e-9, 3e-9, false),
            (Ticks{{0.0, "1e-09"}, {0.5, "2e-09"}, {1.0, "3e-09"}}));
  EXPECT_EQ(colour_bar_ticks(814.0, 814.0, false), (Ticks{{0.5, "814"}}));
}

// The maps' titles read the measure in words first, its CSV column second.
TEST(HeatMap, TitlesReadTheMeasureInWordsThenItsColumn) {
  const auto maps = sweep_heat_maps({"time.dt", "initial.jiggle", "first_flip"}, {{"1", "1", "2"}},
                                    {1}, false, {1}, false, {analysis::find_measure("first_flip")});
  ASSERT_EQ(maps.size(), 1u);
  const std::string words(analysis::find_measure("first_flip")->axis_label);
  EXPECT_EQ(maps[0].title.rfind(words, 0), 0u) << maps[0].title;
  EXPECT_NE(maps[0].title.find("first_flip"), std::string::npos) << maps[0].title;
}

TEST(HeatMap, ARowOffTheGridIsAnError) {
  EXPECT_THROW(sweep_heat_maps({"time.dt", "initial.jiggle", "twist"}, {{"1", "3", "0.5"}}, {1, 2},
                               false, {1, 2}, false, {analysis::find_measure("twist")}),
               std::invalid_argument);
}

}  // namespace
}  // namespace bookspin::charts
