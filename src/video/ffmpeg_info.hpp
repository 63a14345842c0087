#pragma once
// What FFmpeg the program runs with, for `bookspin info`.
#include <string>
#include <vector>

namespace bookspin::video {

/// Human-readable lines: one per library ("libavcodec 59.37.100 (built with
/// 59.37.100)"), then one per H.264 encoder with whether it opens here
/// ("H.264 encoder h264_nvenc: unusable (…)"). Probing opens each encoder
/// once at 256×256, so this takes a moment; never throws on a probe failure.
std::vector<std::string> ffmpeg_info();

/// Names of all H.264 video encoders compiled into the linked libavcodec, in
/// libavcodec's order (present, not necessarily usable: see ffmpeg_info()).
std::vector<std::string> h264_encoders();

}  // namespace bookspin::video
