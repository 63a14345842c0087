// The plot sheet of `bookspin plot` (charts/plot_sheet.hpp): what it plots, checked against
// values the scene file states.
#include "charts/plot_sheet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "charts/panel.hpp"
#include "overlay/cairo_canvas.hpp"

namespace bookspin::charts {
namespace {

TEST(PlotSheet, TheTHandleComparisonPlotsOmegaAboutItsIntermediateAxisY) {
  // The T-handle's axes are sorted (x smallest, y intermediate: docs/physics.md §12) and the
  // scene spins it at spin_rate = 2 about the intermediate axis, so ω_y starts at 2 (plus the
  // jiggle's share) in every tile, and ω_x near 0. The heading names the axis that flips.
  const scene::Scene scene = scene::parse_scene(
      std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/compare-t-handle-models.toml", {"time.frames=6"});
  const PlotSheet sheet = plot_sheet_for(scene, analysis::run_frames(scene));
  ASSERT_FALSE(sheet.plots.empty());
  const overlay::PlotSpec& flips = sheet.plots.front();
  EXPECT_EQ(flips.title, "ω_y, body frame (the flips)");
  ASSERT_EQ(flips.series.size(), scene.compare.size());
  for (const overlay::Series& s : flips.series) {
    ASSERT_FALSE(s.y.empty()) << s.label;
    EXPECT_NEAR(s.y.front(), 2.0, 0.05) << s.label;
  }
}

TEST(PlotSheet, TheBookComparisonPlotsOmegaAboutItsIntermediateAxisX) {
  // The book's intermediate axis is x (docs/physics.md §12); compare-methods-x spins it about x.
  const scene::Scene scene = scene::parse_scene(
      std::string(BOOKSPIN_SOURCE_DIR) + "/scenes/compare-methods-x.toml", {"time.frames=3"});
  const PlotSheet sheet = plot_sheet_for(scene, analysis::run_frames(scene));
  ASSERT_FALSE(sheet.plots.empty());
  EXPECT_EQ(sheet.plots.front().title, "ω_x, body frame (the flips)");
  for (const overlay::Series& s : sheet.plots.front().series)
    EXPECT_NEAR(s.y.front(), scene.initial.omega0_body.x(), 0.05 * scene.initial.omega0_body.x());
}

// A comparison's line of tiles longer than the sheet (compare-engines' six methods ran past
// the right edge, "… ODE, dWorldS") is broken at spaces into lines that fit; the title stays.
TEST(PlotSheet, AHeaderLineLongerThanTheSheetIsBrokenIntoLinesThatFit) {
  const std::string tiles =
      "comparison: exact (Jacobi elliptic functions) \u00b7 MuJoCo, Euler (its default) \u00b7 "
      "MuJoCo, RK4 \u00b7 Bullet, implicit body (its default) \u00b7 Bullet, no gyroscopic term "
      "\u00b7 ODE, dWorldStep (its default)";
  const std::vector<std::string> header{"The engines side by side", tiles};
  const int width = 1600, height = 1000;
  const double font = 0.024 * height;
  overlay::CairoCanvas canvas(width, height);
  const auto lines = wrap_sheet_header(canvas.cr(), header, font, width);
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(lines[0], header[0]);
  std::string joined;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    cairo_text_extents_t e;
    cairo_text_extents(canvas.cr(), lines[i].c_str(), &e);
    EXPECT_LE(e.x_advance, width - 2 * font) << lines[i];
    joined += (i == 1 ? "" : " ") + lines[i];
  }
  EXPECT_EQ(joined, tiles);
  // Broken between two methods, never inside one's name.
  EXPECT_EQ(lines[1].substr(lines[1].size() - 2), "\u00b7");
  // Drawn: no ink in the sheet's right margin (half the font) over the header's rows.
  const RgbaImage image = plot_sheet(header, {}, width, height);
  for (int y = 0; y < static_cast<int>(6 * font); ++y)
    for (int x = width - static_cast<int>(0.5 * font); x < width; ++x)
      ASSERT_GT(image.row(y)[4 * x], 200) << "ink at (" << x << ", " << y << ")";
}

}  // namespace
}  // namespace bookspin::charts
