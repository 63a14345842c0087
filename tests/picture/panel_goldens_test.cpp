// The plot panel and the comparison layout are part of the picture too: one
// figure frame with its panel and one comparison frame are pinned. 512×288 is the smallest
// 16:9 size at which the panel column is wide enough to be drawn.
#include <gtest/gtest.h>

#include <cstdlib>

#include "clip/frame.hpp"
#include "golden_store.hpp"
#include "output/png_writer.hpp"
#include "picture_scenes.hpp"

namespace bookspin::picture {
namespace {

const std::vector<std::string> kPanelSize{"render.width=512", "render.height=288"};

TEST(PanelGoldens, FigureFrameCarriesThePlotPanel) {
  const scene::Scene scene = figure_scene("fig09-matrix-unstable-x", kPanelSize);
  ASSERT_TRUE(scene.render.panel);
  const int index = 250;  // mid-flip: all three ω curves are moving
  EXPECT_TRUE(matches_golden("panel-fig09-matrix-unstable-x-f0250",
                             clip::render_still(scene, renderer_for(scene), index)));
}

// Comparison scenes render through `bookspin render` (several simulators, one tile each).
TEST(PanelGoldens, ComparisonFrameShowsAllPanelsInLockstep) {
  // Frame 105: the exact, matrix and quaternion books are mid-flip at the same angle.
  const RgbaImage frame =
      rendered_frame("compare-methods-x", 105, 512, 288, {"render.sphere=false"}, "panel-compare");
  EXPECT_TRUE(matches_golden("compare-methods-x-f0105", frame));
}

}  // namespace
}  // namespace bookspin::picture
