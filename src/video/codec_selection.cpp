#include "video/codec_selection.hpp"

extern "C" {
#include <libavutil/opt.h>
}

#include <algorithm>
#include <array>
#include <stdexcept>

#include "common/errors.hpp"

namespace bookspin::video {
namespace {

constexpr const char* kFallbackEncoder = "libx264";

// Encoder-specific knobs live in priv_data. x264 calls constant quality
// "crf"; NVENC's nearest equivalent is "cq" on the same 0…51 scale.
// Returns an empty string on success, else why the encoder refused.
std::string set_private_options(AVCodecContext* context, int quality, const std::string& preset) {
  void* priv = context->priv_data;
  if (priv == nullptr) return {};
  const std::string quality_text = std::to_string(quality);
  for (const char* name : {"crf", "cq"}) {
    if (av_opt_find(priv, name, nullptr, 0, 0) == nullptr) continue;
    const int rc = av_opt_set(priv, name, quality_text.c_str(), 0);
    if (rc < 0) return std::string("rejects ") + name + " " + quality_text;
    break;
  }
  if (!preset.empty() && av_opt_find(priv, "preset", nullptr, 0, 0) != nullptr &&
      av_opt_set(priv, "preset", preset.c_str(), 0) < 0) {
    return "rejects preset \"" + preset + "\"";
  }
  return {};
}

void set_stream_properties(AVCodecContext* context, const EncoderSettings& settings,
                           bool global_header) {
  context->width = settings.width;
  context->height = settings.height;
  context->pix_fmt = AV_PIX_FMT_YUV420P;
  context->time_base = AVRational{1, settings.fps};
  context->framerate = AVRational{settings.fps, 1};
  // libavcodec's default is 1; 0 lets x264 use every core. A cap (render --jobs) keeps
  // parallel renders from each starting a thread pool sized for the whole machine.
  context->thread_count = std::max(0, settings.threads);
  // Tag what Mp4Encoder's swscale conversion produces (BT.709, limited range),
  // so players do not guess BT.601 for small frames and shift the colours.
  context->colorspace = AVCOL_SPC_BT709;
  context->color_primaries = AVCOL_PRI_BT709;
  context->color_trc = AVCOL_TRC_BT709;
  context->color_range = AVCOL_RANGE_MPEG;
  if (global_header) context->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
}

// Returns an open context, or null with `why` set (libav's own log lines
// included, since av_strerror alone says little, e.g. for a missing libcuda).
libav::CodecContextPtr try_open(const AVCodec* codec, const EncoderSettings& settings,
                                const std::string& preset, bool global_header, std::string* why) {
  libav::CodecContextPtr context(avcodec_alloc_context3(codec));
  if (!context) {
    *why = "out of memory";
    return nullptr;
  }
  set_stream_properties(context.get(), settings, global_header);
  *why = set_private_options(context.get(), settings.crf, preset);
  if (!why->empty()) return nullptr;
  libav::LogCapture capture;
  const int rc = avcodec_open2(context.get(), codec, nullptr);
  if (rc >= 0) return context;
  *why = libav::error_text(rc);
  if (!capture.text().empty()) *why = capture.text() + " (" + *why + ")";
  return nullptr;
}

bool is_h264_video_encoder(const AVCodec* codec) {
  return codec->type == AVMEDIA_TYPE_VIDEO && codec->id == AV_CODEC_ID_H264 &&
         av_codec_is_encoder(codec);
}

OpenedEncoder open_fallback(const EncoderSettings& settings, bool global_header,
                            std::string reason) {
  const AVCodec* x264 = avcodec_find_encoder_by_name(kFallbackEncoder);
  if (x264 == nullptr) {
    throw EncoderError(reason +
                       "; libx264 is not in this FFmpeg build either, so no H.264 "
                       "encoder is available (install FFmpeg's libavcodec with libx264)");
  }
  std::string preset = settings.preset;
  if (!is_x264_preset(preset)) {
    reason += "; preset \"" + preset + "\" is not an x264 preset, using \"medium\"";
    preset = "medium";
  }
  std::string why;
  auto context = try_open(x264, settings, preset, global_header, &why);
  if (!context) throw EncoderError(reason + "; libx264 failed to open too: " + why);
  return {std::move(context), kFallbackEncoder, reason + "; using libx264"};
}

}  // namespace

bool is_x264_preset(const std::string& preset) {
  return std::any_of(kNvencPresets.begin(), kNvencPresets.end(),
                     [&preset](const NvencPreset& p) { return p.x264 == preset; });
}

std::string encoder_preset(std::string_view encoder, const std::string& preset) {
  constexpr std::string_view kNvenc = "_nvenc";
  if (!encoder.ends_with(kNvenc)) return preset;
  for (const NvencPreset& p : kNvencPresets)
    if (p.x264 == preset) return std::string(p.nvenc);
  return preset;
}

OpenedEncoder open_h264_encoder(const EncoderSettings& settings, bool global_header) {
  libav::configure_logging();
  const bool wants_x264 = settings.codec == kFallbackEncoder;
  if (wants_x264 && !is_x264_preset(settings.preset)) {
    throw InputError("preset \"" + settings.preset +
                     "\" is not an x264 preset (ultrafast … placebo)");
  }
  const AVCodec* codec = avcodec_find_encoder_by_name(settings.codec.c_str());
  if (codec == nullptr) {
    if (wants_x264) {
      throw EncoderError(
          "libx264 is not in this FFmpeg build (install FFmpeg's libavcodec "
          "with libx264)");
    }
    return open_fallback(settings, global_header,
                         "encoder \"" + settings.codec + "\" is not in this FFmpeg build");
  }
  if (!is_h264_video_encoder(codec)) {
    throw InputError("codec \"" + settings.codec + "\" is not an H.264 encoder");
  }
  std::string why;
  // The scene's preset is x264's; an NVENC encoder gets its own of the same intent, so that
  // it is not refused for a name it does not know.
  auto context =
      try_open(codec, settings, encoder_preset(codec->name, settings.preset), global_header, &why);
  if (context) return {std::move(context), codec->name, ""};
  if (wants_x264) throw EncoderError("libx264 failed to open: " + why);
  return open_fallback(settings, global_header,
                       "encoder \"" + settings.codec + "\" failed to open: " + why);
}

std::string probe_encoder(const std::string& name) {
  libav::configure_logging();
  const AVCodec* codec = avcodec_find_encoder_by_name(name.c_str());
  if (codec == nullptr) return "not in this FFmpeg build";
  EncoderSettings settings;
  settings.width = 256;  // above every hardware encoder's minimum size
  settings.height = 256;
  std::string why;
  auto context = try_open(codec, settings, "", true, &why);
  return context ? std::string() : why;
}

}  // namespace bookspin::video
