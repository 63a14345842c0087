// The title strip (a comparison's header): the title at the strip's left, "t = …" at its
// right, both inside the strip, the time to one decimal.
#include "overlay/caption.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>

namespace bookspin::overlay {
namespace {

/// An opaque dark grey image (the comparison's gap colour does not matter here).
RgbaImage dark(int width, int height) {
  RgbaImage image(width, height);
  for (std::size_t i = 0; i < image.pixels.size(); i += 4)
    image.pixels[i] = image.pixels[i + 1] = image.pixels[i + 2] = 20, image.pixels[i + 3] = 255;
  return image;
}

/// The columns and rows holding every pixel that differs between `a` and `b` (empty: none).
struct Ink {
  int left = -1, right = -1, top = -1, bottom = -1;  ///< inclusive
  bool empty() const { return left < 0; }
};

Ink ink_between(const RgbaImage& a, const RgbaImage& b) {
  Ink ink;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      if (!std::equal(a.row(y) + 4 * x, a.row(y) + 4 * x + 4, b.row(y) + 4 * x)) {
        ink.left = ink.empty() ? x : std::min(ink.left, x);
        ink.right = std::max(ink.right, x);
        ink.top = ink.top < 0 ? y : ink.top;
        ink.bottom = y;
      }
    }
  }
  return ink;
}

/// The ink of the strip's drawing in the columns [from, to) only.
Ink ink_in_columns(const RgbaImage& drawn, int from, int to) {
  RgbaImage part = dark(drawn.width, drawn.height), blank = part;
  for (int y = 0; y < drawn.height; ++y)
    std::copy(drawn.row(y) + 4 * from, drawn.row(y) + 4 * to, part.row(y) + 4 * from);
  return ink_between(part, blank);
}

TEST(TitleStrip, DrawsTheTitleAtTheLeftAndTheTimeAtTheRightInsideTheStrip) {
  // A 300×40 strip at (100, 50): the font is half its height (20 px), the margins 0.6 of the
  // font (12 px), the baseline 0.36 font below the middle (70 + 7.2).
  const RgbaImage blank = dark(480, 160);
  RgbaImage image = blank;
  draw_title_strip(image, PixelRect{100, 50, 300, 40}, "Wx", 12.34);
  const Ink all = ink_between(image, blank);
  ASSERT_FALSE(all.empty());
  EXPECT_GE(all.left, 100 + 12 - 2);  // the title's first glyph, at the left margin
  EXPECT_LE(all.left, 100 + 12 + 3);
  EXPECT_LE(all.right, 400 - 12);  // the time's last glyph, at the right margin
  EXPECT_GE(all.right, 400 - 12 - 4);
  EXPECT_GE(all.top, 50);     // inside the strip: capitals 0.73 font high above the
  EXPECT_LE(all.bottom, 89);  // baseline at 77.2
  EXPECT_NEAR(all.top, 77.2 - 0.73 * 20, 2.0);
  // Both texts are there: ink at the left (the title) and at the right (the time), none in
  // the gap between them ("Wx" and "t = 12.3" are about 35 and 90 px wide).
  EXPECT_FALSE(ink_in_columns(image, 100, 160).empty());
  EXPECT_TRUE(ink_in_columns(image, 160, 280).empty());
  EXPECT_FALSE(ink_in_columns(image, 340, 400).empty());
}

TEST(TitleStrip, ShowsTheTimeToOneDecimal) {
  const PixelRect strip{0, 0, 240, 30};
  RgbaImage a = dark(240, 30), b = a, c = a;
  draw_title_strip(a, strip, "title", 12.34);  // t = 12.3
  draw_title_strip(b, strip, "title", 12.26);  // t = 12.3
  draw_title_strip(c, strip, "title", 12.36);  // t = 12.4
  EXPECT_EQ(a.pixels, b.pixels);
  const Ink changed = ink_between(a, c);
  ASSERT_FALSE(changed.empty());
  EXPECT_GT(changed.left, 240 / 2);  // only the last digit, at the right end, changes
}

}  // namespace
}  // namespace bookspin::overlay
