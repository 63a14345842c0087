// WebM (VP9) and GIF (palettegen/paletteuse) clips, decoded back independently with
// libavformat/libavcodec (mp4_probe.cpp demuxes any container FFmpeg reads).
#include "output/web_encoders.hpp"

#include <gtest/gtest.h>

extern "C" {
#include <libavformat/avformat.h>
}
#include <unistd.h>

#include <cmath>
#include <fstream>

#include "decoded_clip.hpp"
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

/// Each video packet's duration in seconds as the container stores it (a GIF: each frame's
/// delay), read with libavformat directly.
std::vector<double> packet_durations(const fs::path& path) {
  AVFormatContext* format = nullptr;
  std::vector<double> durations;
  if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) return durations;
  AVPacket* packet = av_packet_alloc();
  while (av_read_frame(format, packet) >= 0) {
    durations.push_back(static_cast<double>(packet->duration) *
                        av_q2d(format->streams[packet->stream_index]->time_base));
    av_packet_unref(packet);
  }
  av_packet_free(&packet);
  avformat_close_input(&format);
  return durations;
}

// 61 frames at 30 frames/s as a 10 frames/s GIF: every 3rd frame (21 of them), each shown
// 3/30 s, so the GIF lasts 2.1 s, the clip's 61/30 s rounded up to whole GIF frames; frame j
// is source frame 3j (the palette pass reads the stored frames back in order).
TEST(GifEncoder, DecodedGifHasTheClipsFrameCountAndDuration) {
  ScratchDir dir;
  constexpr int kSourceFrames = 61, kSourceFps = 30;
  const GifSettings settings{kWidth, kHeight, kSourceFps, 64, 10};
  {
    GifEncoder encoder(dir / "clip.gif", settings);
    for (int i = 0; i < kSourceFrames; ++i)
      encoder.add_frame(moving_square_frame(kWidth, kHeight, i));
    encoder.finish();
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"clip.gif"});  // the frame store is gone
  const testing::Mp4Probe probe = testing::probe_mp4(dir / "clip.gif");
  ASSERT_EQ(static_cast<int>(probe.frames.size()), 21);
  for (int j = 0; j < 21; ++j) {
    const testing::Square sq = testing::moving_square(3 * j);
    EXPECT_LT(testing::mean_rgb_error(probe.frames[j], moving_square_frame(kWidth, kHeight, 3 * j),
                                      2, sq.x / 2 + 2, sq.y / 2 + 2, (sq.x + sq.size) / 2 - 2,
                                      (sq.y + sq.size) / 2 - 2),
              10.0)
        << "GIF frame " << j;
  }
  const std::vector<double> durations = packet_durations(dir / "clip.gif");
  ASSERT_EQ(durations.size(), 21u);
  double total = 0;
  for (double d : durations) {
    EXPECT_NEAR(d, 0.1, 1e-9);
    total += d;
  }
  EXPECT_NEAR(total, 2.1, 1e-9);
  EXPECT_LT(total - static_cast<double>(kSourceFrames) / kSourceFps, 3.0 / kSourceFps);
}

/// This process's resident memory in bytes (/proc/self/statm).
double resident_bytes() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE));
}

// Holding every kept frame until the end would grow by 300 × 320×240×4 bytes (92 MB) here;
// the encoder keeps them on disk, so what it holds does not grow with the clip. The frames
// repeat every 20, so the palette's colour counts are complete before the measurement.
TEST(GifEncoder, MemoryDoesNotGrowWithTheNumberOfFrames) {
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer keeps freed blocks in its quarantine (256 MB by default), so resident
  // memory grows with every freed frame; the Release pass of the suite measures this.
  GTEST_SKIP() << "resident memory is not the encoder's under AddressSanitizer";
#endif
  ScratchDir dir;
  constexpr int kW = 320, kH = 240, kMany = 320;
  const double frame_bytes = 4.0 * kW * kH;
  GifEncoder encoder(dir / "long.gif", GifSettings{kW, kH, 30, kW, 30});
  for (int i = 0; i < 20; ++i) encoder.add_frame(moving_square_frame(kW, kH, i % 20));
  const double before = resident_bytes();
  for (int i = 20; i < kMany; ++i) encoder.add_frame(moving_square_frame(kW, kH, i % 20));
  const double grown = resident_bytes() - before;
  EXPECT_LT(grown, 10 * frame_bytes) << "grew by " << grown / frame_bytes << " frames' worth";
  // The palette pass adds a fixed amount (paletteuse's colour cache, about 6 MB here), not one
  // that grows with the frames.
  encoder.finish();
  EXPECT_EQ(encoder.frame_count(), kMany);
  EXPECT_LT(resident_bytes() - before, 40 * frame_bytes);
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
