// WebM (VP9) and GIF (palettegen/paletteuse) clips, decoded back independently with
// libavformat/libavcodec (mp4_probe.cpp demuxes any container FFmpeg reads).
#include "output/web_encoders.hpp"

#include <gtest/gtest.h>

#include "decoded_clip.hpp"
#include "mp4_probe.hpp"
#include "output/atomic_output.hpp"
#include "scratch_dir.hpp"
#include "test_images.hpp"

namespace bookspin::output {
namespace {
namespace fs = std::filesystem;
using testing::moving_square_frame;
using testing::ScratchDir;

constexpr int kWidth = 128, kHeight = 96, kFps = 24, kFrames = 24;

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
  testing::expect_video_stream(probe, "vp9", kWidth, kHeight, kFps);
  ASSERT_EQ(static_cast<int>(probe.frames.size()), kFrames);
  for (int i = 0; i < kFrames; ++i)
    testing::expect_moving_square(probe.frames[i], kWidth, kHeight, i, 1, 8.0, 6.0);
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
  for (int j = 0; j < 12; ++j)
    testing::expect_moving_square(probe.frames[j], kWidth, kHeight, 2 * j, 2, 10.0, 10.0);
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
