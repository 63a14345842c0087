// Line plots (src/overlay/plot.cpp): a fixed y range cuts curves at the plot's edge and marks
// where they leave it.
#include "overlay/plot.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace bookspin::overlay {
namespace {

/// A red curve from 0 up to 0.5 and out to 50 and back, on a bare plot (no title, labels
/// or legend, so the topmost dark pixel of a column right of the spike is the plot area's
/// frame).
PlotSpec spike(std::optional<std::pair<double, double>> y_range) {
  PlotSpec spec;
  spec.legend = false;
  spec.y_range = y_range;
  Series s;
  s.r = 1.0;
  for (int i = 0; i <= 100; ++i) {
    s.x.push_back(i);
    s.y.push_back(i >= 40 && i <= 60 ? 50.0 : 0.005 * i);
  }
  spec.series = {s};
  return spec;
}

bool red(const RgbaImage& image, int x, int y) {
  const std::uint8_t* p = image.row(y) + 4 * x;
  return p[0] > 200 && p[1] < 80 && p[2] < 80;
}

/// Rows from the top: the plot area's top edge (the frame's first dark pixel at 4/5 of the
/// width) and the first row holding a red pixel.
std::pair<int, int> frame_top_and_first_red(const RgbaImage& image) {
  int frame = -1, first_red = -1;
  for (int y = 0; y < image.height; ++y) {
    const std::uint8_t* p = image.row(y) + 4 * (image.width * 4 / 5);
    // The frame is dark grey, 1 px wide and spread over two rows by antialiasing; the grid
    // is light grey (0.88).
    if (frame < 0 && p[0] < 200 && p[0] == p[1] && p[1] == p[2]) frame = y;
    for (int x = 0; x < image.width && first_red < 0; ++x)
      if (red(image, x, y)) first_red = y;
  }
  return {frame, first_red};
}

/// `fitted` (no fixed range) keeps the red curve inside its frame; `clipped` (a fixed range
/// the spike leaves) cuts it at the edge, with a red triangle standing on the frame's top edge,
/// outside it, and only where the curve leaves the range (x = 40 of 0 … 100): no red above the
/// frame at the left or right quarter.
void expect_cut_and_marked(const RgbaImage& fitted, const RgbaImage& clipped) {
  const auto [fitted_frame, fitted_red] = frame_top_and_first_red(fitted);
  const auto [frame, first_red] = frame_top_and_first_red(clipped);
  ASSERT_GT(fitted_frame, 0);
  ASSERT_GT(frame, 0);
  EXPECT_GE(fitted_red, fitted_frame);
  EXPECT_LT(first_red, frame);
  EXPECT_GE(first_red, frame - 12);  // a small marker, not the curve running off the image
  for (int y = 0; y < frame; ++y) {
    for (int x = 0; x < clipped.width / 4; ++x) EXPECT_FALSE(red(clipped, x, y)) << x << ',' << y;
    for (int x = 3 * clipped.width / 4; x < clipped.width; ++x)
      EXPECT_FALSE(red(clipped, x, y)) << x << ',' << y;
  }
}

TEST(Plot, FixedYRangeCutsTheCurveAndMarksWhereItLeaves) {
  expect_cut_and_marked(plot_image(spike(std::nullopt), 400, 300),
                        plot_image(spike(std::pair{-0.1, 0.6}), 400, 300));
}

// The same on a log axis: the spike (50) above a fixed range 1e-3 … 1 is cut at the top edge
// and marked there; a range with a non-positive end is ignored on a log axis (fitted instead).
TEST(Plot, FixedLogYRangeCutsTheCurveAndMarksWhereItLeaves) {
  const auto log_spike = [](std::optional<std::pair<double, double>> y_range) {
    PlotSpec spec = spike(y_range);
    spec.log_y = true;
    for (double& y : spec.series[0].y) y = std::max(y, 1e-3);
    return spec;
  };
  expect_cut_and_marked(plot_image(log_spike(std::pair{0.0, 1.0}), 400, 300),
                        plot_image(log_spike(std::pair{1e-3, 1.0}), 400, 300));
}

/// Huge values that are constant, or differ by less than their rounding: the axis widens
/// around them and the ticks are counted, so the plot is drawn (it used to loop on a step lost
/// in rounding until memory ran out, as ω ≈ 10³⁰ of the smallest book does in a comparison).
TEST(Plot, HugeNearlyConstantValuesAreDrawn) {
  for (const double base : {1e30, -1e30, 1e300, 1e16}) {
    SCOPED_TRACE(base);
    PlotSpec spec;
    Series s;
    s.r = 1.0;
    for (int i = 0; i <= 10; ++i) {
      s.x.push_back(i);
      s.y.push_back(i % 2 == 0 ? base : std::nextafter(base, 0.0));
    }
    spec.series = {s};
    const RgbaImage image = plot_image(spec, 400, 300);
    ASSERT_EQ(image.width, 400);
    bool any_red = false;
    for (int y = 0; y < image.height && !any_red; ++y)
      for (int x = 0; x < image.width && !any_red; ++x) any_red = red(image, x, y);
    EXPECT_TRUE(any_red);
  }
}

/// Red pixels of a bare plot holding one point drawn with `marker` (one point: no line).
int red_pixels_of_one_point(Marker marker) {
  PlotSpec spec;
  spec.legend = false;
  Series s;
  s.r = 1.0;
  s.marker = marker;
  s.x = {1.0};
  s.y = {1.0};
  spec.series = {s};
  const RgbaImage image = plot_image(spec, 400, 300);
  int count = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) count += red(image, x, y) ? 1 : 0;
  return count;
}

// The marks' areas in units of r² (plot.cpp's draw_marker): circle π, square 2.3² = 5.29,
// triangle 2.7 × 2.4 / 2 = 3.24, diamond 2.6 × 3.2 / 2 = 4.16; r is a few pixels, so the
// counts follow the areas to within the antialiased rim.
TEST(Plot, EachMarkerDrawsItsOwnShape) {
  const double circle = red_pixels_of_one_point(Marker::circle);
  ASSERT_GT(circle, 4);
  EXPECT_NEAR(red_pixels_of_one_point(Marker::square) / circle, 5.29 / M_PI, 0.45);
  EXPECT_NEAR(red_pixels_of_one_point(Marker::diamond) / circle, 4.16 / M_PI, 0.45);
  EXPECT_GT(red_pixels_of_one_point(Marker::triangle), 0.6 * circle);
}

}  // namespace
}  // namespace bookspin::overlay

namespace bookspin::overlay {
namespace {

/// The runs of `colour` pixels along the row of the right half that holds most of them.
int legend_runs(const RgbaImage& image, bool (*colour)(const std::uint8_t*)) {
  int best_row = -1, best_count = 0;
  for (int y = 0; y < image.height; ++y) {
    int count = 0;
    for (int x = image.width / 2; x < image.width; ++x) count += colour(image.row(y) + 4 * x);
    if (count > best_count) best_count = count, best_row = y;
  }
  if (best_row < 0) return 0;
  int runs = 0;
  bool inside = false;
  for (int x = image.width / 2; x < image.width; ++x) {
    const bool here = colour(image.row(best_row) + 4 * x);
    runs += here && !inside;
    inside = here;
  }
  return runs;
}

// The legend shows a series as it is drawn: a measured series of dots (Series::dots) as three
// dots, a line as one stroke. The dots are drawn in the left tenth of the plot, so every red
// pixel of the right half is the legend's (a white series stretches the x axis to 10).
TEST(PlotLegend, ADotsSeriesShowsDotsALineSeriesALine) {
  PlotSpec spec;
  Series dots, line, white;
  white.label = "axis";
  white.r = white.g = white.b = 1.0;
  white.x = {0.0, 10.0};
  white.y = {0.0, 1.0};
  dots.label = "measured";
  dots.r = 1.0;
  dots.dots = true;
  line.label = "fitted";
  line.b = 1.0;
  for (int i = 0; i <= 10; ++i) {
    dots.x.push_back(0.1 * i), dots.y.push_back(0.1 * i);
    line.x.push_back(0.1 * i), line.y.push_back(0.1 * i);
  }
  spec.series = {dots, line, white};
  const RgbaImage image = plot_image(spec, 900, 300);
  const auto is_red = [](const std::uint8_t* p) { return p[0] > 200 && p[1] < 80 && p[2] < 80; };
  const auto is_blue = [](const std::uint8_t* p) { return p[2] > 200 && p[0] < 80 && p[1] < 80; };
  EXPECT_EQ(legend_runs(image, is_red), 3);
  EXPECT_EQ(legend_runs(image, is_blue), 1);
}

/// The heights of the runs of rows of `image` that hold dark ink (all channels under 110: the
/// text and the frame, not a coloured curve or the light grid) within columns [x0, x1), from
/// the bottom up.
std::vector<int> dark_bands_from_bottom(const RgbaImage& image, int x0, int x1) {
  std::vector<int> bands;
  int run = 0;
  for (int y = image.height - 1; y >= -1; --y) {
    bool dark = false;
    for (int x = x0; y >= 0 && x < x1 && !dark; ++x) {
      const std::uint8_t* p = image.row(y) + 4 * x;
      dark = p[0] < 110 && p[1] < 110 && p[2] < 110;
    }
    if (dark) {
      ++run;
    } else if (run > 0) {
      bands.push_back(run);
      run = 0;
    }
  }
  return bands;
}

// A chart drawn short (a plot 150 px tall, whose text its height alone would make 7 px) still
// writes its text at 12 px: measured in the pixels, the x tick digits (the lowest band of ink
// right of the x label, which is centred under the plot) are at least DejaVu Sans' digit
// height at 12 px (0.73 em, 8 px hinted).
TEST(PlotImage, AShortChartsTextIsDrawnAt12Px) {
  PlotSpec spec;
  spec.legend = false;
  spec.x_label = "t (time units)";
  spec.y_label = "sin(t)";
  Series s;
  s.r = 1.0;  // red: not dark ink
  for (int i = 0; i <= 100; ++i) s.x.push_back(i), s.y.push_back(std::sin(0.1 * i));
  spec.series = {s};
  for (const int height : {150, 300}) {
    const RgbaImage image = plot_image(spec, 1280, height);
    // Right of the x label: the ticks 60 … 100, then the plot area's frame above them.
    const auto bands = dark_bands_from_bottom(image, 760, 1200);
    ASSERT_GE(bands.size(), 2u) << height;
    EXPECT_GE(bands[0], 8) << "the x tick digits, " << height << " px tall";
    EXPECT_LE(bands[0], 14) << "one line of digits, " << height << " px tall";
  }
}

// The title, axis labels and legend are drawn in any alphabet (the typeface stage's text
// layout): 太郎 and 花子 draw differently in each. In DejaVu alone each is two identical
// missing-glyph boxes, and the two plots are the same bytes.
TEST(Plot, TitleLabelsAndLegendDrawCjk) {
  const auto plot = [](const std::string& name, int where) {
    PlotSpec spec = spike(std::nullopt);
    spec.legend = true;
    spec.series[0].label = where == 3 ? name : "ω_x";
    spec.title = where == 0 ? name : "toss 1";
    spec.x_label = where == 1 ? "time (s, " + name + "'s clock)" : "time (s)";
    spec.y_label = where == 2 ? name : "ω (rad/s)";
    return plot_image(spec, 640, 400).pixels;
  };
  for (int where = 0; where < 4; ++where)
    EXPECT_NE(plot("太郎", where), plot("花子", where)) << "text " << where;
}

// A plot lays its labels out once, before its area is known; the y ticks it draws follow the
// area's height (2 … 5 intervals, more where that gives fewer than two ticks), so every label
// those can have is laid out with the rest: at any height, for ranges of any size, each tick
// drawn has its label (else an internal error) and the plot is drawn.
TEST(Plot, EveryYTickDrawnAtAnyHeightWasLaidOut) {
  for (const double scale : {1e-7, 0.013, 1.0, 2.4, 37.0, 3e5}) {
    for (const double offset : {0.0, -0.7}) {
      PlotSpec spec;
      spec.title = "toss 1";
      spec.x_label = "time (s)";
      spec.y_label = "ω (rad/s)";
      Series s;
      s.label = "ω_x";
      for (int i = 0; i <= 50; ++i) {
        s.x.push_back(i);
        s.y.push_back(scale * (offset + std::sin(0.2 * i)));
      }
      spec.series = {s};
      for (int height = 60; height <= 900; height += 13) {
        RgbaImage image(1, 1);
        ASSERT_NO_THROW(image = plot_image(spec, 420, height)) << scale << " " << height;
        EXPECT_TRUE(std::any_of(image.pixels.begin(), image.pixels.end(),
                                [](std::uint8_t v) { return v < 100; }))
            << scale << " " << height;
      }
    }
  }
}

}  // namespace
}  // namespace bookspin::overlay
