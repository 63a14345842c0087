// The H.264 encoder's choice (src/video/codec_selection.*): the scene's preset, one of x264's,
// reaches NVENC as NVENC's preset of the same intent (the table of docs/outputs.md, "The H.264
// encoder"), and an encoder that cannot open falls back to libx264 saying the real reason. No
// GPU needed: FFmpeg's h264_nvenc takes its options without one and only fails to open.
#include "video/codec_selection.hpp"

#include <gtest/gtest.h>

#include "video/libav_support.hpp"

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavutil/opt.h>
}

#include <map>
#include <string>

namespace bookspin::video {
namespace {

// The table as docs/outputs.md states it, each x264 name to the p of its own name in FFmpeg
// 5.1's `ffmpeg -h encoder=h264_nvenc` (p2 "faster", p3 "fast", p4 "medium (default)", p5
// "slow", p6 "slower"), the ends taking the rest.
const std::map<std::string, std::string> kDocumented = {
    {"ultrafast", "p1"}, {"superfast", "p1"}, {"veryfast", "p1"}, {"faster", "p2"},
    {"fast", "p3"},      {"medium", "p4"},    {"slow", "p5"},     {"slower", "p6"},
    {"veryslow", "p7"},  {"placebo", "p7"},
};

TEST(NvencPresets, EveryX264PresetMapsAsDocumented) {
  EXPECT_EQ(kNvencPresets.size(), kDocumented.size());
  for (const NvencPreset& p : kNvencPresets) {
    const std::string x264(p.x264);
    ASSERT_TRUE(kDocumented.contains(x264)) << x264;
    EXPECT_EQ(p.nvenc, kDocumented.at(x264)) << x264;
    EXPECT_TRUE(is_x264_preset(x264)) << x264;
    EXPECT_EQ(encoder_preset("h264_nvenc", x264), kDocumented.at(x264)) << x264;
  }
  EXPECT_EQ(encoder_preset("h264_nvenc", "faster"), "p2");  // the scene's default
  EXPECT_EQ(encoder_preset("hevc_nvenc", "slower"), "p6");
}

TEST(NvencPresets, TheTableRunsFromFastestToSlowest) {
  std::string previous = "p1";
  for (const NvencPreset& p : kNvencPresets) {
    EXPECT_GE(std::string(p.nvenc), previous) << p.x264;
    previous = std::string(p.nvenc);
  }
  EXPECT_EQ(kNvencPresets.front().x264, "ultrafast");
  EXPECT_EQ(kNvencPresets.back().x264, "placebo");
  EXPECT_EQ(kNvencPresets.back().nvenc, "p7");
}

TEST(NvencPresets, OtherPresetsAndOtherEncodersGetThePresetAsItIs) {
  EXPECT_EQ(encoder_preset("libx264", "faster"), "faster");
  EXPECT_EQ(encoder_preset("libx264", "placebo"), "placebo");
  EXPECT_EQ(encoder_preset("h264_nvenc", "p4"), "p4");  // NVENC's own name
  EXPECT_EQ(encoder_preset("h264_nvenc", "llhq"), "llhq");
  EXPECT_EQ(encoder_preset("h264_nvenc", ""), "");
  EXPECT_EQ(encoder_preset("h264_qsv", "faster"), "faster");
  EXPECT_FALSE(is_x264_preset("p4"));
  EXPECT_FALSE(is_x264_preset("Medium"));
}

/// av_opt_set's answer when `encoder`'s own "preset" option is set to `preset` (an encoder
/// context is allocated, never opened: no GPU needed).
int set_preset(const AVCodec* encoder, const std::string& preset) {
  AVCodecContext* context = avcodec_alloc_context3(encoder);
  if (context == nullptr) return AVERROR(ENOMEM);
  const int rc = av_opt_set(context->priv_data, "preset", preset.c_str(), 0);
  avcodec_free_context(&context);
  return rc;
}

// What the table is for: this FFmpeg's h264_nvenc refuses x264's default preset by name, and
// takes every preset the table hands it.
TEST(NvencPresets, ThisFfmpegsNvencTakesEveryMappedPresetAndRefusesX264sDefault) {
  libav::configure_logging();  // FFmpeg's complaint about "faster" stays off the terminal
  const AVCodec* nvenc = avcodec_find_encoder_by_name("h264_nvenc");
  if (nvenc == nullptr) GTEST_SKIP() << "this FFmpeg has no h264_nvenc";
  EXPECT_LT(set_preset(nvenc, "faster"), 0) << "h264_nvenc now knows x264's \"faster\"";
  for (const NvencPreset& p : kNvencPresets)
    EXPECT_GE(set_preset(nvenc, encoder_preset(nvenc->name, std::string(p.x264))), 0) << p.x264;
}

// Without an NVIDIA GPU (CI), h264_nvenc is in Debian's FFmpeg but cannot open: the fallback's
// message is the driver's reason, never a preset the encoder refused, for every scene preset.
TEST(H264Encoder, NvencWithAnyScenePresetOpensOrFallsBackForTheRealReason) {
  if (avcodec_find_encoder_by_name("h264_nvenc") == nullptr)
    GTEST_SKIP() << "this FFmpeg has no h264_nvenc";
  for (const NvencPreset& p : kNvencPresets) {
    EncoderSettings settings;
    settings.width = 256;
    settings.height = 256;
    settings.codec = "h264_nvenc";
    settings.preset = std::string(p.x264);
    const OpenedEncoder opened = open_h264_encoder(settings, true);
    ASSERT_TRUE(opened.context) << p.x264;
    if (opened.fallback_message.empty()) {
      EXPECT_EQ(opened.name, "h264_nvenc");  // a GPU with NVENC
      continue;
    }
    EXPECT_EQ(opened.name, "libx264") << p.x264;
    EXPECT_EQ(opened.fallback_message.find("rejects preset"), std::string::npos)
        << p.x264 << ": " << opened.fallback_message;
    EXPECT_EQ(opened.fallback_message.rfind("encoder \"h264_nvenc\" failed to open: ", 0), 0u)
        << opened.fallback_message;
    EXPECT_TRUE(opened.fallback_message.ends_with("; using libx264")) << opened.fallback_message;
  }
}

}  // namespace
}  // namespace bookspin::video
