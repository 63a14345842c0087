#include "decoded_clip.hpp"

#include <gtest/gtest.h>

#include <cstdlib>

#include "support/test_images.hpp"

namespace bookspin::video::testing {

double mean_rgb_error(const RgbaImage& decoded, const RgbaImage& expected, int scale, int x0,
                      int y0, int x1, int y1) {
  double sum = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      for (int c = 0; c < 3; ++c) {
        sum += std::abs(decoded.row(y)[4 * x + c] - expected.row(y * scale)[4 * x * scale + c]);
      }
    }
  }
  return sum / (3.0 * (x1 - x0) * (y1 - y0));
}

void expect_video_stream(const Mp4Probe& probe, const std::string& codec, int width, int height,
                         int fps) {
  EXPECT_EQ(probe.codec, codec);
  EXPECT_EQ(probe.pix_fmt, "yuv420p");
  EXPECT_EQ(probe.color_space, "bt709");
  EXPECT_EQ(probe.width, width);
  EXPECT_EQ(probe.height, height);
  EXPECT_EQ(probe.r_frame_rate_num, fps);
  EXPECT_EQ(probe.r_frame_rate_den, 1);
}

void expect_moving_square(const RgbaImage& decoded, int width, int height, int index, int scale,
                          double square_max, double frame_max) {
  const RgbaImage original = test::moving_square_frame(width, height, index);
  const test::Square sq = test::moving_square(index);
  const int inset = 2;
  EXPECT_LT(mean_rgb_error(decoded, original, scale, sq.x / scale + inset, sq.y / scale + inset,
                           (sq.x + sq.size) / scale - inset, (sq.y + sq.size) / scale - inset),
            square_max)
      << "square of source frame " << index;
  EXPECT_LT(mean_rgb_error(decoded, original, scale, 0, 0, width / scale, height / scale),
            frame_max)
      << "source frame " << index;
}

}  // namespace bookspin::video::testing
