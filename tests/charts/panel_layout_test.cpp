// The panel's plots as laid out and drawn in a clip's frame: text of at least 12 px in every
// clip from 960 × 540 up (the gallery's 1280 × 720, the notebook's 960 × 540), at least 9 px in
// smaller ones; one time axis; plots that fit or are left out from the last.
// The text's height is measured in the drawn pixels too (the x tick digits' ink), against
// DejaVu Sans' digit height, 0.73 em (its fonts' metrics), not against the layout's numbers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "charts/panel.hpp"
#include "charts/sphere_view.hpp"
#include "overlay/cairo_canvas.hpp"

namespace bookspin::charts {
namespace {

/// A run of `frames` samples over 600 time units: ω turning over once, an energy drift and a
/// strain of `size` (small: ticks like -0.0001 widen the plots' left margin; large: 0.2 leaves
/// it to the y labels).
DiagnosticsHistory history_of(int frames, double phase, double size = 1e-4) {
  DiagnosticsHistory h;
  for (int i = 0; i < frames; ++i) {
    const double t = 600.0 * i / (frames - 1);
    h.t.push_back(t);
    h.omega_x.push_back(0.12 * std::tanh((300.0 - t) / 30.0 + phase));
    h.omega_y.push_back(0.1 / std::cosh((300.0 - t) / 30.0));
    h.omega_z.push_back(0.08 / std::cosh((300.0 - t) / 30.0 + phase));
    h.energy_drift.push_back(size * std::sin(t / 50.0 + phase));
    h.strain_max.push_back(5 * size);
    h.quaternion_deviation.push_back(0);
    h.orthogonality_error.push_back(0);
  }
  return h;
}

scene::Scene book_scene() {
  return scene::parse_scene(std::string(BOOKSPIN_SOURCE_DIR) +
                            "/scenes/fig05-particle-unstable-x.toml");
}

/// The panel's rectangles in a width×height frame: the whole column (a single scene's), and
/// the part of it below the sphere (a comparison's, or below Poinsot's construction).
std::vector<PixelRect> panel_rects(int width, int height) {
  const PixelRect column = panel_rect(width, height);
  return {column, split_for_sphere(column).second};
}

const std::pair<int, int> kFrameSizes[] = {
    {1280, 720}, {1920, 1080}, {960, 540}, {640, 360}, {480, 270}};

TEST(PanelLayout, TextIsAtLeast12PxFrom960x540UpAndEveryPlotAreaThreeLinesHigh) {
  const scene::Scene scene = book_scene();
  std::vector<DiagnosticsHistory> histories;
  for (int i = 0; i < 6; ++i) histories.push_back(history_of(600, 0.1 * i));
  std::vector<PanelRun> six;
  for (int i = 0; i < 6; ++i)
    six.emplace_back(scene, histories[i], "a run labelled at some length " + std::to_string(i));
  const auto single = panel_plots({PanelRun(scene, histories[0])}, 600, 300.0);
  const DiagnosticsHistory coarse_history = history_of(600, 0, 0.05);
  const auto coarse = panel_plots({PanelRun(scene, coarse_history)}, 600, 300.0);
  auto comparison = panel_plots(six, 600, 300.0);
  for (auto& p : comparison) p.legend = false;  // as a comparison's clip draws them

  overlay::CairoCanvas measure(1, 1);
  for (const auto& [width, height] : kFrameSizes) {
    for (const PixelRect& rect : panel_rects(width, height)) {
      for (const auto* plots :
           std::vector<const std::vector<overlay::PlotSpec>*>{&single, &coarse, &comparison}) {
        const std::string where = std::to_string(width) + "x" + std::to_string(height) +
                                  " rect y " + std::to_string(rect.y);
        const PanelLayout layout = panel_layout(rect, *plots);
        ASSERT_FALSE(layout.plots.empty()) << where;
        ASSERT_EQ(layout.rects.size(), layout.plots.size());
        EXPECT_GE(layout.font, height >= 540 ? 12.0 : 9.0) << where;
        double y = rect.y;
        for (std::size_t i = 0; i < layout.plots.size(); ++i) {
          const PixelRect& r = layout.rects[i];
          EXPECT_EQ(layout.plots[i].font, layout.font);
          // One time axis: its ticks and label under the lowest plot only.
          EXPECT_EQ(layout.plots[i].x_axis_text, i + 1 == layout.plots.size()) << where;
          // Stacked inside the panel, in order, without overlapping.
          EXPECT_GE(r.y, y - 1e-9) << where;
          EXPECT_LE(r.bottom(), rect.bottom() + 1e-9) << where;
          EXPECT_GE(r.x, rect.x);
          EXPECT_LE(r.right(), rect.right() + 1e-9);
          y = r.bottom();
          const double area = r.height - overlay::plot_frame_height(measure.cr(), r.width,
                                                                    layout.plots[i], layout.font);
          EXPECT_GE(area, kPanelMinPlotFonts * layout.font - 1e-9) << where << " plot " << i;
          // The left margin holds the y label as this plot's height draws it (on two lines
          // where one is longer than the plot), whatever the other plots need.
          overlay::PlotSpec alone = layout.plots[i];
          alone.left_margin = 0;
          EXPECT_GE(layout.plots[i].left_margin,
                    overlay::plot_left_margin(measure.cr(), r.height, alone) - 1e-9)
              << where << " plot " << i;
        }
        // At the gallery's sizes every plot is kept; smaller frames keep ω first.
        if (height >= 720) {
          EXPECT_EQ(layout.plots.size(), plots->size()) << where;
        }
        EXPECT_EQ(layout.plots.front().title, plots->front().title) << where;
      }
    }
  }
}

TEST(PanelLayout, NoPanelWhereNotEvenOnePlotFits) {
  const scene::Scene scene = book_scene();
  const DiagnosticsHistory h = history_of(50, 0);
  const auto plots = panel_plots({PanelRun(scene, h)}, 600, 100.0);
  EXPECT_TRUE(panel_layout({0, 0, 300, 60}, plots).plots.empty());    // too short
  EXPECT_TRUE(panel_layout({0, 0, 80, 400}, plots).plots.empty());    // too narrow
  EXPECT_EQ(panel_layout({0, 0, 300, 140}, plots).plots.size(), 1u);  // ω alone
}

/// Rows of `image` within columns [x0, x1) that hold dark ink (the tick labels' grey, 0.2).
std::vector<int> dark_rows(const RgbaImage& image, int x0, int x1, int y0, int y1) {
  std::vector<int> rows;
  for (int y = std::max(0, y0); y < std::min(image.height, y1); ++y) {
    for (int x = std::max(0, x0); x < std::min(image.width, x1); ++x) {
      const unsigned char* p = &image.pixels[4 * (static_cast<std::size_t>(y) * image.width + x)];
      if (p[0] < 110 && p[1] < 110 && p[2] < 110) {
        rows.push_back(y);
        break;
      }
    }
  }
  return rows;
}

TEST(PanelLayout, DrawnTickDigitsAreAt12PxFrom960x540Up) {
  const scene::Scene scene = book_scene();
  const DiagnosticsHistory h = history_of(600, 0);
  const auto plots = panel_plots({PanelRun(scene, h)}, 600, 300.0);
  for (const auto& [width, height] : kFrameSizes) {
    for (const PixelRect& rect : panel_rects(width, height)) {
      RgbaImage image(width, height);
      std::fill(image.pixels.begin(), image.pixels.end(), 255);
      draw_panel(image, rect, plots);
      // The lowest plot's x tick digits ("0 100 200 …") lie in the band under its area's
      // bottom edge, from that edge to 1.7 text sizes below it (the x label starts lower); one line
      // of them.
      const PanelLayout layout = panel_layout(rect, plots);
      ASSERT_FALSE(layout.plots.empty());
      const PixelRect& last = layout.rects.back();
      const double area_bottom = last.bottom() - 3.2 * layout.font;  // overlay/plot.cpp's layout
      const std::vector<int> rows = dark_rows(
          image, static_cast<int>(rect.x + 0.4 * rect.width), static_cast<int>(rect.right()),
          static_cast<int>(area_bottom) + 3, static_cast<int>(area_bottom + 1.7 * layout.font));
      ASSERT_FALSE(rows.empty()) << width << "x" << height;
      const int digit_height = rows.back() - rows.front() + 1;
      // DejaVu Sans' digits are 0.73 em high: 8.8 px at 12 px (8 with hinting, at least), 6.6
      // at 9 px.
      EXPECT_GE(digit_height, height >= 540 ? 8 : 6) << width << "x" << height;
      EXPECT_EQ(static_cast<int>(rows.size()), digit_height) << "one line of digits";
    }
  }
}

}  // namespace
}  // namespace bookspin::charts
