// WebM (VP9) and GIF (palettegen/paletteuse) clips, decoded back independently with
// libavformat/libavcodec (mp4_probe.cpp demuxes any container FFmpeg reads).
#include "output/web_encoders.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "mp4_probe.hpp"
#include "output/atomic_output.hpp"
#include "support/scratch.hpp"
#include "test_images.hpp"

namespace bookspin::output {
namespace {
namespace fs = std::filesystem;
using bookspin::test::ScratchDir;
using testing::moving_square_frame;

constexpr int kWidth = 128, kHeight = 96, kFps = 24, kFrames = 24;

// Mean absolute difference per channel (R, G, B) of `decoded` against `expected` over a
// rectangle of `decoded`; `scale` maps decoded pixels to expected ones (2: half size).
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

TEST(WebmEncoder, RoundTripIsVp9AtSizeRateAndFrameCountWithTheColours) {
  ScratchDir dir;
  {
    WebmEncoder encoder(dir / "clip.webm", WebmSettings{kWidth, kHeight, kFps, 20, 1});
    for (int i = 0; i < kFrames; ++i) encoder.add_frame(moving_square_frame(kWidth, kHeight, i));
    EXPECT_EQ(encoder.frame_count(), kFrames);
    EXPECT_FALSE(fs::exists(dir / "clip.webm"));  // the temporary only
    encoder.finish();
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"clip.webm"});
  const testing::Mp4Probe probe = testing::probe_mp4(dir / "clip.webm");
  EXPECT_EQ(probe.format_name, "matroska,webm");
  EXPECT_EQ(probe.video_streams, 1);
  EXPECT_EQ(probe.codec, "vp9");
  EXPECT_EQ(probe.pix_fmt, "yuv420p");
  EXPECT_EQ(probe.color_space, "bt709");
  EXPECT_EQ(probe.width, kWidth);
  EXPECT_EQ(probe.height, kHeight);
  EXPECT_EQ(probe.r_frame_rate_num, kFps);
  EXPECT_EQ(probe.r_frame_rate_den, 1);
  ASSERT_EQ(static_cast<int>(probe.frames.size()), kFrames);
  for (int i = 0; i < kFrames; ++i) {
    const RgbaImage original = moving_square_frame(kWidth, kHeight, i);
    const testing::Square sq = testing::moving_square(i);
    EXPECT_LT(mean_rgb_error(probe.frames[i], original, 1, sq.x + 2, sq.y + 2, sq.x + sq.size - 2,
                             sq.y + sq.size - 2),
              8.0)
        << "square of frame " << i;
    EXPECT_LT(mean_rgb_error(probe.frames[i], original, 1, 0, 0, kWidth, kHeight), 6.0)
        << "frame " << i;
  }
}

TEST(GifEncoder, KeepsEveryStepthFrameScaledWithOnePaletteAndTheColours) {
  ScratchDir dir;
  const GifSettings settings{kWidth, kHeight, kFps, 64, 12};
  EXPECT_EQ(gif_step(settings), 2);
  EXPECT_EQ(gif_height(settings), 48);
  EXPECT_EQ(gif_frame_count(settings, kFrames - 1), 12);  // ceil(23 / 2)
  {
    GifEncoder encoder(dir / "clip.gif", settings);
    for (int i = 0; i < kFrames - 1; ++i)
      encoder.add_frame(moving_square_frame(kWidth, kHeight, i));
    encoder.finish();
    EXPECT_EQ(encoder.frame_count(), 12);
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"clip.gif"});
  const testing::Mp4Probe probe = testing::probe_mp4(dir / "clip.gif");
  EXPECT_EQ(probe.format_name, "gif");
  EXPECT_EQ(probe.codec, "gif");
  EXPECT_EQ(probe.width, 64);
  EXPECT_EQ(probe.height, 48);
  ASSERT_EQ(static_cast<int>(probe.frames.size()), 12);
  // GIF frame j is source frame 2j at half size: the square is where that frame had it, in
  // its red (palette and dither keep it within a few levels), and the gradient follows.
  for (int j = 0; j < 12; ++j) {
    const RgbaImage original = moving_square_frame(kWidth, kHeight, 2 * j);
    const testing::Square sq = testing::moving_square(2 * j);
    EXPECT_LT(mean_rgb_error(probe.frames[j], original, 2, sq.x / 2 + 2, sq.y / 2 + 2,
                             (sq.x + sq.size) / 2 - 2, (sq.y + sq.size) / 2 - 2),
              10.0)
        << "square of GIF frame " << j;
    EXPECT_LT(mean_rgb_error(probe.frames[j], original, 2, 0, 0, 64, 48), 10.0)
        << "GIF frame " << j;
  }
}

TEST(WebEncoders, BadSettingsThrowBeforeAnythingIsWrittenAndUnfinishedClipsLeaveNothing) {
  ScratchDir dir;
  EXPECT_THROW(WebmEncoder(dir / "a.webm", WebmSettings{129, 96, 24, 32, 1}),
               std::invalid_argument);
  EXPECT_THROW(WebmEncoder(dir / "a.webm", WebmSettings{128, 96, 24, 64, 1}),
               std::invalid_argument);
  EXPECT_THROW(GifEncoder(dir / "a.gif", GifSettings{128, 96, 24, 256, 12}), std::invalid_argument);
  EXPECT_THROW(GifEncoder(dir / "a.gif", GifSettings{128, 96, 24, 64, 25}), std::invalid_argument);
  {
    WebmEncoder webm(dir / "b.webm", WebmSettings{kWidth, kHeight, kFps, 32, 1});
    GifEncoder gif(dir / "b.gif", GifSettings{kWidth, kHeight, kFps, 64, 12});
    EXPECT_THROW(webm.add_frame(moving_square_frame(kWidth + 2, kHeight, 0)),
                 std::invalid_argument);
    EXPECT_THROW(gif.add_frame(moving_square_frame(kWidth + 2, kHeight, 0)), std::invalid_argument);
    webm.add_frame(moving_square_frame(kWidth, kHeight, 0));
    gif.add_frame(moving_square_frame(kWidth, kHeight, 0));
  }  // destroyed unfinished
  EXPECT_TRUE(dir.entries().empty());
  GifEncoder empty(dir / "c.gif", GifSettings{kWidth, kHeight, kFps, 64, 12});
  EXPECT_THROW(empty.finish(), EncoderError);
}

}  // namespace
}  // namespace bookspin::output
