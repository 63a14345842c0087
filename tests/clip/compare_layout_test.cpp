// A comparison frame's layout: the title strip, the grid of tiles and the plot column, worked
// out by hand from the rule in compare_layout.hpp (header max(14, 5% of the height), gaps
// max(2, 0.4% of the height), even tile sizes, the grid with the largest smaller tile side);
// and blit's clipping.
#include "clip/compare_layout.hpp"

#include <gtest/gtest.h>

namespace bookspin::clip {
namespace {

void expect_rect(const PixelRect& r, double x, double y, double width, double height) {
  EXPECT_DOUBLE_EQ(r.x, x);
  EXPECT_DOUBLE_EQ(r.y, y);
  EXPECT_DOUBLE_EQ(r.width, width);
  EXPECT_DOUBLE_EQ(r.height, height);
}

// 1280×720: header 36, gap 2.88, grid 1280×684. Four tiles: 1×4 gives sides of 171, 2×2 of
// 342, 3×2 also 342 (a tie: 2×2 leaves no cell empty), 4×1 of 320.
TEST(CompareLayout, FourTilesInA720pFrameAreTwoByTwoUnderTheStrip) {
  const CompareLayout layout = compare_layout(4, 1280, 720, false);
  expect_rect(layout.header, 0, 0, 1280, 36);
  EXPECT_EQ(layout.columns, 2);
  EXPECT_EQ(layout.rows, 2);
  EXPECT_EQ(layout.tile_width, 638);   // (1280 − 2.88) / 2 = 638.56, even
  EXPECT_EQ(layout.tile_height, 340);  // (684 − 2.88) / 2 = 340.56, even
  ASSERT_EQ(layout.tiles.size(), 4u);
  expect_rect(layout.tiles[0], 0, 36, 638, 340);
  expect_rect(layout.tiles[1], 640.88, 36, 638, 340);
  expect_rect(layout.tiles[2], 0, 378.88, 638, 340);
  expect_rect(layout.tiles[3], 640.88, 378.88, 638, 340);
  EXPECT_FALSE(layout.plots.has_value());
}

// Three tiles: 1×3 gives 228, 2×2 gives 342, 3×1 gives 426.67: one row.
TEST(CompareLayout, ThreeTilesInA720pFrameAreOneRow) {
  const CompareLayout layout = compare_layout(3, 1280, 720, false);
  EXPECT_EQ(layout.columns, 3);
  EXPECT_EQ(layout.rows, 1);
  EXPECT_EQ(layout.tile_width, 424);  // (1280 − 2 · 2.88) / 3 = 424.75
  EXPECT_EQ(layout.tile_height, 684);
  ASSERT_EQ(layout.tiles.size(), 3u);
  expect_rect(layout.tiles[2], 2 * (424 + 2.88), 36, 424, 684);
}

// With the panel the grid has the left 60% (768 px); three tiles: 1×3 gives 228, 2×2 342,
// 3×1 256. The plots fill the rest, inset by 1.2% of 720 = 8.64.
TEST(CompareLayout, WithThePanelTheGridTakesTheLeftSixtyPercentAndThePlotsTheRest) {
  const CompareLayout layout = compare_layout(3, 1280, 720, true);
  EXPECT_EQ(layout.columns, 2);
  EXPECT_EQ(layout.rows, 2);
  EXPECT_EQ(layout.tile_width, 382);  // (768 − 2.88) / 2 = 382.56
  EXPECT_EQ(layout.tile_height, 340);
  ASSERT_EQ(layout.tiles.size(), 3u);
  expect_rect(layout.tiles[2], 0, 378.88, 382, 340);
  ASSERT_TRUE(layout.plots.has_value());
  expect_rect(*layout.plots, 776.64, 44.64, 494.72, 666.72);
}

// A small frame: the header's floor of 14 px, the gap's of 2 px and the tiles' of 16 px.
TEST(CompareLayout, ASmallFrameKeepsTheFloors) {
  const CompareLayout layout = compare_layout(2, 40, 100, false);
  expect_rect(layout.header, 0, 0, 40, 14);
  // 1×2: min(40, 43) = 40; 2×1: min(20, 86) = 20.
  EXPECT_EQ(layout.columns, 1);
  EXPECT_EQ(layout.rows, 2);
  EXPECT_EQ(layout.tile_width, 40);
  EXPECT_EQ(layout.tile_height, 42);  // (86 − 2) / 2
  expect_rect(layout.tiles[1], 0, 14 + 42 + 2, 40, 42);
  const CompareLayout tiny = compare_layout(9, 40, 40, false);
  EXPECT_EQ(tiny.tile_width, 16);
  EXPECT_EQ(tiny.tile_height, 16);
}

RgbaImage filled(int width, int height, std::uint8_t value) {
  RgbaImage image(width, height);
  std::fill(image.pixels.begin(), image.pixels.end(), value);
  return image;
}

TEST(CompareLayout, BlitCopiesATileAndClipsItAtTheFrameEdges) {
  RgbaImage frame = filled(6, 4, 0);
  blit(frame, filled(3, 3, 200), 4, 2);  // 2 columns and 2 rows fit
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 6; ++x) {
      const bool inside = x >= 4 && y >= 2;
      for (int c = 0; c < 4; ++c)
        EXPECT_EQ(frame.row(y)[4 * x + c], inside ? 200 : 0) << x << ',' << y << ',' << c;
    }
  }
  RgbaImage untouched = filled(6, 4, 0);
  blit(untouched, filled(3, 3, 200), 6, 0);   // right of the frame
  blit(untouched, filled(3, 3, 200), -1, 0);  // left of it
  EXPECT_EQ(untouched.pixels, filled(6, 4, 0).pixels);
}

TEST(CompareLayout, ABlankFrameIsOpaqueAndDark) {
  const RgbaImage frame = blank_frame(3, 2);
  ASSERT_EQ(frame.pixels.size(), 3u * 2 * 4);
  for (std::size_t i = 0; i < frame.pixels.size(); i += 4) {
    EXPECT_LT(frame.pixels[i] + frame.pixels[i + 1] + frame.pixels[i + 2], 3 * 32);
    EXPECT_EQ(frame.pixels[i + 3], 255);
  }
}

}  // namespace
}  // namespace bookspin::clip
