// The panel painter, which keeps the plots' frames between frames and draws again only the
// plot whose axis range changed, gives exactly draw_panel's pixels frame after frame.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "pipeline/panel.hpp"

namespace bookspin::pipeline {
namespace {

RgbaImage backdrop(int width, int height) {
  RgbaImage image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.row(y) + 4 * x;
      p[0] = static_cast<std::uint8_t>(x), p[1] = static_cast<std::uint8_t>(2 * y);
      p[2] = static_cast<std::uint8_t>(x + y), p[3] = 255;
    }
  }
  return image;
}

overlay::Series series(const std::vector<double>& t, double (*f)(double), double r) {
  overlay::Series s;
  s.label = "series";
  s.x = t;
  for (double v : t) s.y.push_back(f(v));
  s.r = r;
  return s;
}

/// Three stacked plots after `n` samples: a range that settles (the first), one that drifts
/// by round-off every frame (the second, as the energy drift does) and one that jumps when
/// the data do (the third).
std::vector<overlay::PlotSpec> plots_after(int n) {
  std::vector<double> t;
  for (int i = 0; i < n; ++i) t.push_back(0.1 * i);
  overlay::PlotSpec spec;
  spec.title = std::string("a plot");
  spec.x_label = std::string("t (time units)");
  spec.y_label = std::string("y (units)");
  std::vector<overlay::PlotSpec> plots(3, spec);
  for (auto& p : plots) {
    p.legend_placement = overlay::LegendPlacement::top;
    p.x_range = std::pair{0.0, 10.0};
    p.min_y_span = 1e-3;
    p.cursor_x = t.empty() ? 0.0 : t.back();
  }
  plots[0].series = {series(
      t, [](double v) { return std::sin(v); }, 0.8)};
  plots[1].series = {series(
      t, [](double v) { return 1e-9 * v * v; }, 0.5)};
  plots[2].series = {series(
      t, [](double v) { return v > 5 ? 3.0 : 0.1 * v; }, 0.2)};
  return plots;
}

TEST(PanelPainter, DrawsExactlyWhatDrawPanelDrawsFrameAfterFrame) {
  const int width = 800, height = 450;
  const PixelRect rect = panel_rect(width, height);
  PanelPainter painter;
  for (int n = 0; n < 100; n += 3) {
    const auto plots = plots_after(n);
    RgbaImage expected = backdrop(width, height), painted = backdrop(width, height);
    draw_panel(expected, rect, plots);
    painter.draw(painted, rect, plots);
    ASSERT_EQ(painted.pixels, expected.pixels) << "after " << n << " samples";
  }
}

TEST(PanelPainter, KeepsUpWithANewRectangleAndTooSmallAPanel) {
  PanelPainter painter;
  for (const PixelRect& rect :
       {panel_rect(800, 450), panel_rect(640, 360), PixelRect{10, 10, 90, 90}}) {
    const auto plots = plots_after(40);
    RgbaImage expected = backdrop(800, 450), painted = backdrop(800, 450);
    draw_panel(expected, rect, plots);
    painter.draw(painted, rect, plots);
    EXPECT_EQ(painted.pixels, expected.pixels);
  }
}

}  // namespace
}  // namespace bookspin::pipeline
