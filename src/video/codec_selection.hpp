#pragma once
// Internal to the video stage: choose and open an H.264 encoder, falling back
// to libx264 when the requested one is missing or refuses to open.
#include <array>
#include <string>
#include <string_view>

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

/// An x264 preset and the NVENC preset of the same speed/quality intent.
struct NvencPreset {
  std::string_view x264;   ///< x264's name, "ultrafast" … "placebo"
  std::string_view nvenc;  ///< NVENC's, "p1" (fastest) … "p7" (slowest)
};

/// x264's presets in x264's order, fastest first, each with NVENC's preset of the same intent:
/// the one table of both (docs/outputs.md, "The H.264 encoder"). FFmpeg 5.1's h264_nvenc knows
/// none of x264's names but "fast", "medium" and "slow", which it takes as its deprecated
/// aliases (p1, p4 and two-pass p7); its help text describes p1 … p7 as "fastest", "faster",
/// "fast", "medium (default)", "slow", "slower", "slowest", so each x264 name goes to the p
/// of its own name and the two ends take the rest.
inline constexpr std::array<NvencPreset, 10> kNvencPresets = {{
    {"ultrafast", "p1"},
    {"superfast", "p1"},
    {"veryfast", "p1"},
    {"faster", "p2"},
    {"fast", "p3"},
    {"medium", "p4"},
    {"slow", "p5"},
    {"slower", "p6"},
    {"veryslow", "p7"},
    {"placebo", "p7"},
}};

/// True for x264's preset names, "ultrafast" … "placebo" (kNvencPresets' x264 column).
bool is_x264_preset(const std::string& preset);

/// The preset to hand `encoder` for the scene's `preset`: to an NVENC encoder (a name ending in
/// "_nvenc"), an x264 name becomes NVENC's of the same intent (kNvencPresets); any other
/// preset, or any other encoder, gets `preset` as it is.
std::string encoder_preset(std::string_view encoder, const std::string& preset);

}  // namespace bookspin::video
