// WebM (VP9) and GIF (palettegen/paletteuse) clips, decoded back independently with
// libavformat/libavcodec (mp4_probe.cpp demuxes any container FFmpeg reads).
#include "video/web_encoders.hpp"

#include <gtest/gtest.h>

extern "C" {
#include <libavformat/avformat.h>
}
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <tuple>
#include <utility>

#include "decoded_clip.hpp"
#include "mp4_probe.hpp"
#include "output/atomic_output.hpp"
#include "support/scratch.hpp"
#include "support/test_images.hpp"

namespace bookspin::video {
namespace {
namespace fs = std::filesystem;
using bookspin::test::ScratchDir;
using test::moving_square_frame;

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

/// Each video packet's start and duration in seconds as the container stores them (a GIF:
/// each frame's delay), in the order stored, read with libavformat directly.
struct PacketTimes {
  std::vector<double> starts, durations;
};

PacketTimes packet_times(const fs::path& path) {
  AVFormatContext* format = nullptr;
  PacketTimes times;
  if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0) return times;
  AVPacket* packet = av_packet_alloc();
  while (av_read_frame(format, packet) >= 0) {
    const double unit = av_q2d(format->streams[packet->stream_index]->time_base);
    times.starts.push_back(static_cast<double>(packet->pts) * unit);
    times.durations.push_back(static_cast<double>(packet->duration) * unit);
    av_packet_unref(packet);
  }
  av_packet_free(&packet);
  avformat_close_input(&format);
  return times;
}

std::vector<double> packet_durations(const fs::path& path) { return packet_times(path).durations; }

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
    const test::Square sq = test::moving_square(3 * j);
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

// A GIF's delays are whole centiseconds and browsers show delays under 2 cs as 10 cs, so a
// GIF plays at most 50 frames/s: the rate fps / round(fps / gif_fps) beyond it is refused
// (before the muxer could see two frames in one centisecond).
TEST(GifEncoder, RefusesARateFasterThanFiftyFramesPerSecond) {
  ScratchDir dir;
  // {fps, gif_fps}: the played rates by hand are 240, 120, 60 (round(2.4) = 2) and 55.
  for (const auto& [fps, gif_fps] : {std::pair{240, 240}, {120, 120}, {120, 50}, {55, 50}}) {
    EXPECT_THROW(GifEncoder(dir / "a.gif", GifSettings{kWidth, kHeight, fps, 64, gif_fps}),
                 std::invalid_argument)
        << fps << " " << gif_fps;
  }
  // 50 (every frame), 40 (round(2.5) = 3), 48 (round(4.8) = 5), 50 (every 2nd of 100).
  for (const auto& [fps, gif_fps] : {std::pair{50, 50}, {120, 48}, {240, 50}, {100, 50}})
    EXPECT_NO_THROW(GifEncoder(dir / "b.gif", GifSettings{kWidth, kHeight, fps, 64, gif_fps}));
  EXPECT_TRUE(dir.entries().empty());
}

// 48 frames at the highest rates of the limits table, the GIF at the fastest it may play: the
// muxers take every frame (no "non monotonically increasing" refusal), store strictly
// increasing times, and each file lasts what the clip does.
TEST(WebEncoders, HighFrameRatesGiveIncreasingTimesInEveryFormat) {
  ScratchDir dir;
  constexpr int kFrames48 = 48;
  // {fps, gif_fps, step by hand}: 120 / 48 → every 3rd frame (40 frames/s); 240 / 50 → every
  // 5th (48 frames/s).
  for (const auto& [fps, gif_fps, step] : {std::tuple{120, 48, 3}, {240, 50, 5}}) {
    const std::string tag = std::to_string(fps);
    {
      EncoderSettings mp4_settings{kWidth, kHeight, fps};
      mp4_settings.preset = "ultrafast";
      Mp4Encoder mp4(dir / (tag + ".mp4"), mp4_settings);
      WebmEncoder webm(dir / (tag + ".webm"), WebmSettings{kWidth, kHeight, fps, 40, 1});
      GifEncoder gif(dir / (tag + ".gif"), GifSettings{kWidth, kHeight, fps, 64, gif_fps});
      for (int i = 0; i < kFrames48; ++i) {
        const RgbaImage frame = moving_square_frame(kWidth, kHeight, i);
        mp4.add_frame(frame);
        webm.add_frame(frame);
        gif.add_frame(frame);
      }
      mp4.finish();
      webm.finish();
      gif.finish();
    }
    const int gif_frames = (kFrames48 + step - 1) / step;
    for (const auto& [ext, count, frame_s] :
         {std::tuple{".mp4", kFrames48, 1.0 / fps},
          {".webm", kFrames48, 1.0 / fps},
          {".gif", gif_frames, static_cast<double>(step) / fps}}) {
      const fs::path file = dir / (tag + ext);
      std::vector<double> starts = packet_times(file).starts;
      std::sort(starts.begin(), starts.end());  // H.264 stores B-frames out of order
      ASSERT_EQ(static_cast<int>(starts.size()), count) << file;
      for (std::size_t k = 1; k < starts.size(); ++k) EXPECT_GT(starts[k], starts[k - 1]) << file;
      // Frame k starts at k × frame_s: to the millisecond (WebM) or centisecond (GIF).
      for (int k = 0; k < count; ++k)
        EXPECT_NEAR(starts[k] - starts[0], k * frame_s, 0.0051) << file << " frame " << k;
    }
    for (double delay : packet_durations(dir / (tag + ".gif"))) EXPECT_GE(delay, 0.02 - 1e-9);
  }
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
}  // namespace bookspin::video
