#pragma once
// Internal to the video stage: choose and open an H.264 encoder, falling back
// to libx264 when the requested one is missing or refuses to open.
#include <string>

#include "video/libav_support.hpp"
#include "video/mp4_encoder.hpp"

namespace bookspin::video {

struct OpenedEncoder {
  libav::CodecContextPtr context;
  std::string name;              ///< encoder in use
  std::string fallback_message;  ///< empty unless we fell back to libx264
};

/// Opens an encoder for `settings` (already validated). `global_header` asks
/// for out-of-band SPS/PPS, as MP4 needs. Throws InputError if
/// settings.codec names a non-H.264 encoder or a bad x264 preset, EncoderError
/// if libx264 is missing or cannot open.
OpenedEncoder open_h264_encoder(const EncoderSettings& settings, bool global_header);

/// Empty if encoder `name` opens for a small yuv420p test stream, otherwise the
/// reason it does not (for `bookspin info`).
std::string probe_encoder(const std::string& name);

/// True for x264's preset names, "ultrafast" … "placebo".
bool is_x264_preset(const std::string& preset);

}  // namespace bookspin::video
