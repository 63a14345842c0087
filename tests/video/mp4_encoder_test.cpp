#include "video/mp4_encoder.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <iostream>
#include <thread>

#include "clip/bounded_queue.hpp"
#include "decoded_clip.hpp"
#include "mp4_probe.hpp"
#include "output/atomic_output.hpp"
#include "support/scratch.hpp"
#include "support/test_images.hpp"
#include "video/ffmpeg_info.hpp"

namespace bookspin::video {
namespace {
namespace fs = std::filesystem;
using bookspin::test::ScratchDir;
using test::moving_square_frame;
using test::noise_frame;

constexpr int kWidth = 128, kHeight = 96, kFps = 24, kFrames = 24;

EncoderSettings small_settings(const std::string& codec = "libx264") {
  EncoderSettings settings;
  settings.width = kWidth;
  settings.height = kHeight;
  settings.fps = kFps;
  settings.codec = codec;
  settings.preset = "ultrafast";
  return settings;
}

void encode_clip(Mp4Encoder& encoder, int frames) {
  for (int i = 0; i < frames; ++i) encoder.add_frame(moving_square_frame(kWidth, kHeight, i));
}

void expect_valid_clip(const fs::path& path, int frames) {
  const testing::Mp4Probe probe = testing::probe_mp4(path);
  EXPECT_EQ(probe.video_streams, 1);
  EXPECT_EQ(probe.codec, "h264");
  EXPECT_EQ(probe.pix_fmt, "yuv420p");
  EXPECT_EQ(probe.width, kWidth);
  EXPECT_EQ(probe.height, kHeight);
  EXPECT_EQ(probe.nb_frames, frames);
  EXPECT_EQ(static_cast<int>(probe.frames.size()), frames);
}

TEST(Mp4Encoder, RoundTripKeepsFormatRateFrameCountAndColours) {
  ScratchDir dir;
  EncoderSettings settings = small_settings();
  settings.preset = "faster";  // the default, as the app will use it
  {
    Mp4Encoder encoder(dir / "clip.mp4", settings);
    EXPECT_EQ(encoder.codec_name(), "libx264");
    EXPECT_EQ(encoder.fallback_message(), "");
    encode_clip(encoder, kFrames);
    EXPECT_EQ(encoder.frame_count(), kFrames);
    EXPECT_FALSE(fs::exists(dir / "clip.mp4"));  // only the temporary so far
    encoder.finish();
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"clip.mp4"});

  const testing::Mp4Probe probe = testing::probe_mp4(dir / "clip.mp4");
  testing::expect_video_stream(probe, "h264", kWidth, kHeight, kFps);
  EXPECT_EQ(probe.avg_frame_rate_num, kFps);
  EXPECT_EQ(probe.avg_frame_rate_den, 1);
  EXPECT_EQ(probe.nb_frames, kFrames);
  ASSERT_EQ(static_cast<int>(probe.frames.size()), kFrames);

  // Every frame in order: the square moves, so a swapped or dropped frame
  // would show up as a large error inside it. Measured error is ~1–2/255; a
  // BT.601/BT.709 tag mismatch alone gives ~13 on the red square.
  for (int i = 0; i < kFrames; ++i)
    testing::expect_moving_square(probe.frames[i], kWidth, kHeight, i, 1, 6.0, 6.0);
}

TEST(Mp4Encoder, MoovAtomPrecedesMediaData) {
  ScratchDir dir;
  Mp4Encoder encoder(dir / "clip.mp4", small_settings());
  encode_clip(encoder, 6);
  encoder.finish();
  const std::vector<std::string> boxes = testing::top_level_boxes(dir / "clip.mp4");
  const auto moov = std::find(boxes.begin(), boxes.end(), "moov");
  const auto mdat = std::find(boxes.begin(), boxes.end(), "mdat");
  ASSERT_NE(moov, boxes.end());
  ASSERT_NE(mdat, boxes.end());
  EXPECT_LT(moov - boxes.begin(), mdat - boxes.begin());
}

TEST(Mp4Encoder, OddSizesAreRejectedBeforeAnythingIsWritten) {
  ScratchDir dir;
  EncoderSettings settings = small_settings();
  settings.width = 129;
  try {
    Mp4Encoder encoder(dir / "odd.mp4", settings);
    FAIL() << "odd width accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("4:2:0 video needs even sizes"), std::string::npos)
        << e.what();
  }
  settings.width = kWidth;
  settings.height = 95;
  EXPECT_THROW(Mp4Encoder(dir / "odd.mp4", settings), std::invalid_argument);
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Mp4Encoder, RejectsOtherBadSettingsAndFrames) {
  ScratchDir dir;
  EncoderSettings settings = small_settings();
  settings.fps = 0;
  EXPECT_THROW(Mp4Encoder(dir / "a.mp4", settings), std::invalid_argument);
  settings = small_settings();
  settings.crf = 52;
  EXPECT_THROW(Mp4Encoder(dir / "a.mp4", settings), std::invalid_argument);
  // A codec or preset the scene names but the encoder cannot use is the user's input.
  EXPECT_THROW(Mp4Encoder(dir / "a.mp4", small_settings("mpeg4")), InputError);
  settings = small_settings();
  settings.preset = "medum";
  EXPECT_THROW(Mp4Encoder(dir / "a.mp4", settings), InputError);

  Mp4Encoder encoder(dir / "a.mp4", small_settings());
  EXPECT_THROW(encoder.add_frame(moving_square_frame(kWidth + 2, kHeight, 0)),
               std::invalid_argument);
  EXPECT_THROW(encoder.finish(), EncoderError);  // no frames
  EXPECT_THROW(encoder.add_frame(moving_square_frame(kWidth, kHeight, 0)), std::logic_error);
  EXPECT_THROW(encoder.finish(), std::logic_error);
}

TEST(Mp4Encoder, DestroyedWithoutFinishLeavesNoFileAndNoTemporary) {
  ScratchDir dir;
  try {
    Mp4Encoder encoder(dir / "clip.mp4", small_settings());
    encode_clip(encoder, 5);
    EXPECT_EQ(dir.entries().size(), 1u);  // the temporary
    throw std::runtime_error("interrupted");
  } catch (const std::runtime_error&) {
  }
  EXPECT_TRUE(dir.entries().empty());
}

TEST(Mp4Encoder, MissingCodecFallsBackToLibx264WithAMessage) {
  ScratchDir dir;
  Mp4Encoder encoder(dir / "clip.mp4", small_settings("no_such_codec"));
  EXPECT_EQ(encoder.codec_name(), "libx264");
  EXPECT_NE(encoder.fallback_message().find("no_such_codec"), std::string::npos)
      << encoder.fallback_message();
  encode_clip(encoder, 4);
  encoder.finish();
  expect_valid_clip(dir / "clip.mp4", 4);
}

// On a machine without an NVIDIA GPU h264_nvenc is compiled in but cannot
// open; with a GPU it may work. Either way the clip must be valid, and the
// message must say which happened.
TEST(Mp4Encoder, NvencEitherWorksOrFallsBackToLibx264) {
  const auto encoders = h264_encoders();
  if (std::find(encoders.begin(), encoders.end(), "h264_nvenc") == encoders.end()) {
    GTEST_SKIP() << "this FFmpeg has no h264_nvenc";
  }
  ScratchDir dir;
  EncoderSettings settings = small_settings("h264_nvenc");
  settings.preset = "p4";  // an NVENC preset, not an x264 one
  Mp4Encoder encoder(dir / "clip.mp4", settings);
  if (encoder.fallback_message().empty()) {
    EXPECT_EQ(encoder.codec_name(), "h264_nvenc");
  } else {
    EXPECT_EQ(encoder.codec_name(), "libx264");
    EXPECT_NE(encoder.fallback_message().find("h264_nvenc"), std::string::npos);
    EXPECT_NE(encoder.fallback_message().find("medium"), std::string::npos);
  }
  std::cout << "[ info     ] " << encoder.codec_name() << ": " << encoder.fallback_message()
            << "\n";
  encode_clip(encoder, 4);
  encoder.finish();
  expect_valid_clip(dir / "clip.mp4", 4);
}

TEST(Mp4Encoder, PathWithColonIsAFileNotAProtocol) {
  ScratchDir dir;
  Mp4Encoder encoder(dir / "take:2.mp4", small_settings());
  encode_clip(encoder, 2);
  encoder.finish();
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"take:2.mp4"});
}

TEST(Mp4Encoder, WriteErrorSurfacesAsOutputErrorAndLeavesNothing) {
  ScratchDir dir;
  EncoderSettings settings = small_settings();
  settings.crf = 0;  // lossless: noise stays big
  auto* const old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit old_limit{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  std::string message;
  {
    Mp4Encoder encoder(dir / "clip.mp4", settings);
    rlimit small = old_limit;
    small.rlim_cur = 64 * 1024;
    ::setrlimit(RLIMIT_FSIZE, &small);
    try {
      for (int i = 0; i < 12; ++i) encoder.add_frame(noise_frame(kWidth, kHeight, i));
      encoder.finish();
    } catch (const OutputError& e) {
      message = e.what();
    }
    ::setrlimit(RLIMIT_FSIZE, &old_limit);
  }
  std::signal(SIGXFSZ, old_handler);
  EXPECT_NE(message.find("File too large"), std::string::npos) << message;
  EXPECT_NE(message.find((dir / "clip.mp4").string()), std::string::npos) << message;
  EXPECT_TRUE(dir.entries().empty());
}

// The clip sinks' shape: frames handed over a bounded queue to an
// encoder running on its own thread.
TEST(Mp4Encoder, EncodesFromAQueueOnAnotherThread) {
  ScratchDir dir;
  clip::BoundedQueue<RgbaImage> queue(4);
  Mp4Encoder encoder(dir / "clip.mp4", small_settings());
  std::thread writer([&] {
    while (auto frame = queue.pop()) encoder.add_frame(*frame);
    encoder.finish();
  });
  for (int i = 0; i < 10; ++i) ASSERT_TRUE(queue.push(moving_square_frame(kWidth, kHeight, i)));
  queue.close();
  writer.join();
  expect_valid_clip(dir / "clip.mp4", 10);
}

TEST(FfmpegInfo, ReportsLibrariesAndAUsableLibx264) {
  const std::vector<std::string> lines = ffmpeg_info();
  ASSERT_GE(lines.size(), 5u);
  EXPECT_EQ(lines[0].rfind("libavcodec ", 0), 0u) << lines[0];
  EXPECT_NE(std::find(lines.begin(), lines.end(), "H.264 encoder libx264: usable"), lines.end());
  const auto encoders = h264_encoders();
  EXPECT_NE(std::find(encoders.begin(), encoders.end(), "libx264"), encoders.end());
  for (const auto& line : lines) std::cout << "[ info     ] " << line << "\n";
}

}  // namespace
}  // namespace bookspin::video
