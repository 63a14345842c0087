// SSIM and PSNR against closed forms worked by hand, and a clip decoded back to RGB against
// its frames and against the tests' own decoder (mp4_probe.cpp).
#include "video/video_quality.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "mp4_probe.hpp"
#include "support/scratch.hpp"
#include "support/test_images.hpp"
#include "video/mp4_encoder.hpp"

namespace bookspin::video {
namespace {

constexpr double kC1 = 6.5025, kC2 = 58.5225;  // (0.01·255)², (0.03·255)²

/// A grey image: value `a` where (x/2 + y/2) is even, `b` elsewhere (2×2 tiles).
RgbaImage grey_checker(int width, int height, int a, int b) {
  RgbaImage image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const auto v = static_cast<std::uint8_t>((x / 2 + y / 2) % 2 == 0 ? a : b);
      std::uint8_t* p = image.row(y) + 4 * x;
      p[0] = p[1] = p[2] = v;
      p[3] = 255;
    }
  }
  return image;
}

TEST(VideoQuality, IdenticalFramesHaveSsimOneAndTheCappedPsnr) {
  const RgbaImage frame = test::moving_square_frame(64, 48, 3);
  const FrameQuality q = frame_quality(frame, frame);
  EXPECT_NEAR(q.ssim, 1.0, 1e-12);
  EXPECT_EQ(q.squared_error, 0.0);
  EXPECT_EQ(q.samples, 64 * 48 * 3);
  EXPECT_EQ(psnr_db(q.squared_error, q.samples), kPsnrIdentical);
}

// Flat grey 100 against flat grey 110: no variance, so SSIM is its luminance term alone,
// (2·100·110 + C1) / (100² + 110² + C1); every sample is 10 levels off: PSNR 20 log10(25.5).
TEST(VideoQuality, AFlatOffsetGivesTheLuminanceTermAndItsPsnr) {
  const FrameQuality q =
      frame_quality(grey_checker(40, 32, 100, 100), grey_checker(40, 32, 110, 110));
  EXPECT_NEAR(q.ssim, (22000 + kC1) / (10000 + 12100 + kC1), 1e-9);
  EXPECT_NEAR(psnr_db(q.squared_error, q.samples), 28.1308036, 1e-6);
}

// Checker 80/160 against checker 100/140: every 8×8 window has the mean 120 in both, σx = 40,
// σy = 20, σxy = 800, so SSIM = (2·800 + C2) / (40² + 20² + C2); every sample is 20 levels off.
TEST(VideoQuality, ALowerContrastGivesTheContrastStructureTerm) {
  const FrameQuality q =
      frame_quality(grey_checker(40, 32, 80, 160), grey_checker(40, 32, 100, 140));
  EXPECT_NEAR(q.ssim, (1600 + kC2) / (2000 + kC2), 1e-9);
  EXPECT_NEAR(psnr_db(q.squared_error, q.samples), 20 * std::log10(255.0 / 20.0), 1e-9);
}

TEST(VideoQuality, MismatchedOrTinyFramesAreRejected) {
  EXPECT_THROW(frame_quality(RgbaImage(16, 16), RgbaImage(16, 18)), std::invalid_argument);
  EXPECT_THROW(frame_quality(RgbaImage(6, 16), RgbaImage(6, 16)), std::invalid_argument);
  EXPECT_THROW(psnr_db(0, 0), std::invalid_argument);
}

// An H.264 clip decoded back: every frame, in order, close to what was encoded and to what
// the tests' own decoder makes of it.
TEST(VideoQuality, DecodeVideoGivesEveryFrameOfAClipInOrder) {
  test::ScratchDir dir;
  constexpr int kWidth = 128, kHeight = 96, kFrames = 20;
  {
    EncoderSettings settings;
    settings.width = kWidth;
    settings.height = kHeight;
    settings.fps = 24;
    settings.crf = 12;
    settings.preset = "ultrafast";
    settings.threads = 1;
    Mp4Encoder encoder(dir / "clip.mp4", settings);
    for (int i = 0; i < kFrames; ++i)
      encoder.add_frame(test::moving_square_frame(kWidth, kHeight, i));
    encoder.finish();
  }
  const testing::Mp4Probe probe = testing::probe_mp4(dir / "clip.mp4");
  ASSERT_EQ(static_cast<int>(probe.frames.size()), kFrames);
  int index = 0;
  const std::int64_t decoded = decode_video(dir / "clip.mp4", [&](const RgbaImage& frame) {
    ASSERT_LT(index, kFrames);
    const FrameQuality original =
        frame_quality(test::moving_square_frame(kWidth, kHeight, index), frame);
    // 4:2:0 chroma blurs the red square's edges: about 35 dB at CRF 12.
    EXPECT_GT(psnr_db(original.squared_error, original.samples), 33.0) << "frame " << index;
    EXPECT_GT(original.ssim, 0.97) << "frame " << index;
    // A frame taken for another (order lost) would put the square 3 px away.
    const FrameQuality neighbour =
        frame_quality(test::moving_square_frame(kWidth, kHeight, (index + 1) % kFrames), frame);
    EXPECT_LT(psnr_db(neighbour.squared_error, neighbour.samples),
              psnr_db(original.squared_error, original.samples) - 6.0);
    const FrameQuality probed = frame_quality(probe.frames[index], frame);
    EXPECT_GT(psnr_db(probed.squared_error, probed.samples), 40.0) << "frame " << index;
    ++index;
  });
  EXPECT_EQ(decoded, kFrames);
  EXPECT_EQ(index, kFrames);
  EXPECT_THROW(decode_video(dir / "missing.mp4", [](const RgbaImage&) {}), EncoderError);
}

}  // namespace
}  // namespace bookspin::video
