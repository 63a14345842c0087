// The plot sheet of `bookspin plot` (charts/plot_sheet.hpp): what it plots, checked against
// values the scene file states.
#include "charts/plot_sheet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

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

}  // namespace
}  // namespace bookspin::charts
