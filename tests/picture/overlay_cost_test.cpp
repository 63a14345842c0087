// The overlays' bounded-cost drawing: canvases over a region of the frame and plot lines
// thinned per pixel column must draw exactly what the whole-frame, point-by-point versions
// drew.
#include <gtest/gtest.h>

#include <cmath>

#include "image_compare.hpp"
#include "overlay/cairo_canvas.hpp"
#include "overlay/caption.hpp"
#include "overlay/plot.hpp"
#include "support/test_images.hpp"

namespace bookspin::picture {
namespace {

void draw_sample(cairo_t* cr) {
  cairo_rectangle(cr, 40.5, 30.25, 70, 35);
  cairo_set_source_rgba(cr, 0.9, 0.2, 0.1, 0.6);
  cairo_fill(cr);
  overlay::select_overlay_font(cr, true, 14);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_move_to(cr, 45, 55);
  cairo_show_text(cr, "t = 12.5");
}

TEST(PixelRegion, DrawsTheSamePixelsAsAWholeFrameCanvas) {
  RgbaImage whole = test::gradient_frame(200, 120), part = whole;
  overlay::CairoCanvas full(200, 120);
  draw_sample(full.cr());
  full.composite_onto(whole);
  overlay::CairoCanvas region(200, 120, overlay::region_around(40.5, 30.25, 70, 35, 2, 200, 120));
  draw_sample(region.cr());
  region.composite_onto(part);
  EXPECT_EQ(whole.pixels, part.pixels);
  EXPECT_NE(whole.pixels, test::gradient_frame(200, 120).pixels);  // something was drawn
}

TEST(PixelRegion, DrawingOutsideTheRegionIsClippedAway) {
  RgbaImage image = test::gradient_frame(200, 120);
  overlay::CairoCanvas canvas(200, 120, {150, 80, 20, 20});
  cairo_rectangle(canvas.cr(), 0, 0, 200, 120);
  cairo_set_source_rgb(canvas.cr(), 0, 0, 0);
  cairo_fill(canvas.cr());
  canvas.composite_onto(image);
  const RgbaImage before = test::gradient_frame(200, 120);
  for (int y = 0; y < 120; ++y) {
    for (int x = 0; x < 200; ++x) {
      const bool inside = x >= 150 && x < 170 && y >= 80 && y < 100;
      const bool black = image.row(y)[4 * x] == 0 && image.row(y)[4 * x + 1] == 0;
      ASSERT_EQ(inside ? !black : before.row(y)[4 * x] != image.row(y)[4 * x], false)
          << "pixel " << x << ", " << y;
    }
  }
}

TEST(PixelRegion, RegionAroundIsClippedToTheImage) {
  const auto r = overlay::region_around(-10.2, 5.5, 30, 10, 2, 100, 50);
  EXPECT_EQ(r.x, 0);
  EXPECT_EQ(r.y, 3);
  EXPECT_EQ(r.width, 22);  // up to ceil(-10.2 + 30 + 2) = 22, exclusive
  EXPECT_EQ(r.height, 15);
  const auto huge = overlay::region_around(-1e300, -1e300, 1e308, 1e308, 2, 100, 50);
  EXPECT_EQ(huge.x, 0);
  EXPECT_EQ(huge.width, 100);
  EXPECT_EQ(huge.height, 50);
  const auto outside = overlay::region_around(500, 500, 10, 10, 2, 100, 50);
  EXPECT_EQ(outside.width * outside.height, 0);
  RgbaImage image = test::gradient_frame(100, 50);
  overlay::CairoCanvas empty(100, 50, outside);  // an empty region draws nothing, safely
  draw_sample(empty.cr());
  empty.composite_onto(image);
  EXPECT_EQ(image.pixels, test::gradient_frame(100, 50).pixels);
}

TEST(PixelRegion, CaptionAndBannerStillDrawWhereTheyDid) {
  RgbaImage image = test::gradient_frame(256, 144);
  overlay::draw_caption(image, {{"Figure 5", overlay::CaptionStyle::normal, true}, {"t = 1.0"}});
  overlay::draw_banner(image, "diverged at t = 31.35");
  const RgbaImage before = test::gradient_frame(256, 144);
  const auto changed = [&](int x, int y) {
    return image.row(y)[4 * x + 2] != before.row(y)[4 * x + 2];
  };
  EXPECT_TRUE(changed(10, 10));    // the caption's box, top left
  EXPECT_TRUE(changed(128, 100));  // the banner, bottom centre
  EXPECT_FALSE(changed(250, 70));  // neither, right middle
}

// A time series far denser than the plot's pixel columns (a long clip's panel): ascending
// x is thinned per column, the same points in descending order are drawn one by one. Both
// trace the same geometric line, so the pictures must agree.
TEST(PlotThinning, DenseSeriesDrawsTheSameLineAsPointByPoint) {
  overlay::Series ascending;
  const int n = 60000;
  for (int i = 0; i < n; ++i) {
    const double t = 100.0 * i / (n - 1);
    ascending.x.push_back(t);
    ascending.y.push_back(std::sin(0.2 * t) + 0.3 * std::sin(7.3 * t) + (i == n / 2 ? 2.0 : 0.0));
  }
  ascending.r = 0.85, ascending.g = 0.15, ascending.b = 0.10;
  overlay::Series descending = ascending;
  std::reverse(descending.x.begin(), descending.x.end());
  std::reverse(descending.y.begin(), descending.y.end());
  overlay::PlotSpec spec;
  spec.title = "dense";
  spec.legend = false;
  spec.series = {ascending};
  const RgbaImage thinned = overlay::plot_image(spec, 480, 240);
  spec.series = {descending};
  const RgbaImage exact = overlay::plot_image(spec, 480, 240);
  const Comparison c = compare_images(thinned, exact, {8, 0.002});
  EXPECT_TRUE(c.passed) << c.summary({8, 0.002});
  EXPECT_GT(c.psnr_db, 45.0);
  spec.series.clear();
  const RgbaImage blank = overlay::plot_image(spec, 480, 240);
  EXPECT_GT(compare_images(thinned, blank).differing_fraction, 0.05);  // the line is there
}

}  // namespace
}  // namespace bookspin::picture
