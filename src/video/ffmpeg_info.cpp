#include "video/ffmpeg_info.hpp"

#include "video/codec_selection.hpp"
#include "video/libav_support.hpp"

namespace bookspin::video {
namespace {

std::string version_text(unsigned version) {
  return std::to_string(AV_VERSION_MAJOR(version)) + "." +
         std::to_string(AV_VERSION_MINOR(version)) + "." +
         std::to_string(AV_VERSION_MICRO(version));
}

// Run-time and build-time versions differ when the shared libraries were
// upgraded under the binary; worth seeing when an encoder misbehaves.
std::string library_line(const char* name, unsigned runtime, unsigned built) {
  return std::string(name) + " " + version_text(runtime) + " (built with " + version_text(built) +
         ")";
}

}  // namespace

std::vector<std::string> h264_encoders() {
  std::vector<std::string> names;
  void* cursor = nullptr;
  while (const AVCodec* codec = av_codec_iterate(&cursor)) {
    if (av_codec_is_encoder(codec) && codec->type == AVMEDIA_TYPE_VIDEO &&
        codec->id == AV_CODEC_ID_H264) {
      names.emplace_back(codec->name);
    }
  }
  return names;
}

std::vector<std::string> ffmpeg_info() {
  std::vector<std::string> lines = {
      library_line("libavcodec", avcodec_version(), LIBAVCODEC_VERSION_INT),
      library_line("libavformat", avformat_version(), LIBAVFORMAT_VERSION_INT),
      library_line("libavutil", avutil_version(), LIBAVUTIL_VERSION_INT),
      library_line("libswscale", swscale_version(), LIBSWSCALE_VERSION_INT),
  };
  for (const std::string& name : h264_encoders()) {
    const std::string why = probe_encoder(name);
    lines.push_back("H.264 encoder " + name + ": " +
                    (why.empty() ? "usable" : "unusable (" + why + ")"));
  }
  return lines;
}

}  // namespace bookspin::video
