// The comparison itself, on small synthetic images.
#include "image_compare.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace bookspin::picture {
namespace {

RgbaImage flat(int width, int height, std::uint8_t grey) {
  RgbaImage image(width, height);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = i % 4 == 3 ? 255 : grey;
  return image;
}

TEST(ImageCompare, IdenticalImagesPassWithInfinitePsnr) {
  const Comparison c = compare_images(flat(10, 10, 100), flat(10, 10, 100));
  EXPECT_TRUE(c.passed);
  EXPECT_EQ(c.differing_pixels, 0);
  EXPECT_TRUE(std::isinf(c.psnr_db));
}

TEST(ImageCompare, DifferencesUpToTheThresholdAreNotCounted) {
  const Tolerance tolerance;
  const Comparison c =
      compare_images(flat(10, 10, 100 + tolerance.channel_threshold), flat(10, 10, 100));
  EXPECT_TRUE(c.passed);
  EXPECT_EQ(c.differing_pixels, 0);
  EXPECT_EQ(c.max_channel_difference, tolerance.channel_threshold);
  EXPECT_NEAR(c.psnr_db, 20 * std::log10(255.0 / tolerance.channel_threshold), 1e-9);
}

TEST(ImageCompare, FailsWhenMoreThanTheAllowedShareOfPixelsDiffers) {
  RgbaImage actual = flat(10, 10, 100);
  actual.pixels[0] = 200;  // 1 of 100 pixels: 1%
  EXPECT_TRUE(compare_images(actual, flat(10, 10, 100), {24, 0.01}).passed);
  actual.pixels[4] = 0;  // 2%
  const Comparison c = compare_images(actual, flat(10, 10, 100), {24, 0.01});
  EXPECT_FALSE(c.passed);
  EXPECT_EQ(c.differing_pixels, 2);
  EXPECT_DOUBLE_EQ(c.differing_fraction, 0.02);
  EXPECT_EQ(c.max_channel_difference, 100);
}

TEST(ImageCompare, DifferentSizesFail) {
  const Comparison c = compare_images(flat(10, 10, 0), flat(10, 12, 0));
  EXPECT_FALSE(c.passed);
  EXPECT_FALSE(c.same_size);
  EXPECT_THROW(diff_image(flat(10, 10, 0), flat(10, 12, 0)), std::invalid_argument);
}

TEST(ImageCompare, DiffMarksLargeDifferencesRedAndSmallOnesBlue) {
  RgbaImage actual = flat(3, 1, 100);
  actual.pixels[0] = 200;  // pixel 0: large
  actual.pixels[4] = 105;  // pixel 1: tolerated
  const RgbaImage diff = diff_image(actual, flat(3, 1, 100));
  EXPECT_GT(diff.pixels[0], 200);
  EXPECT_EQ(diff.pixels[1], 0);
  EXPECT_EQ(diff.pixels[6], 220);
  EXPECT_LT(diff.pixels[4], 100);
  EXPECT_EQ(diff.pixels[8], diff.pixels[10]);  // pixel 2: equal, grey
}

TEST(ImageCompare, MirroredSwapsColumns) {
  RgbaImage image = flat(2, 1, 0);
  image.pixels[0] = 7;
  EXPECT_EQ(mirrored(image).pixels[4], 7);
  EXPECT_EQ(mirrored(image).pixels[0], 0);
}

}  // namespace
}  // namespace bookspin::picture
