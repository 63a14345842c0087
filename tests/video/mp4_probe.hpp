#pragma once
// Independent read-back of an MP4 for the tests: demux and decode with
// libavformat/libavcodec directly, not through the code under test.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "common/rgba_image.hpp"

namespace bookspin::video::testing {

struct Mp4Probe {
  std::string format_name;  ///< demuxer, e.g. "mov,mp4,m4a,3gp,3g2,mj2"
  int video_streams = 0;
  std::string codec;        ///< e.g. "h264"
  std::string pix_fmt;      ///< e.g. "yuv420p"
  std::string color_space;  ///< e.g. "bt709"
  int width = 0, height = 0;
  int r_frame_rate_num = 0, r_frame_rate_den = 0;
  int avg_frame_rate_num = 0, avg_frame_rate_den = 0;
  std::int64_t nb_frames = 0;     ///< as stored in the container
  std::vector<RgbaImage> frames;  ///< every decoded frame, display order, as RGBA
};

/// Throws std::runtime_error if the file cannot be opened or decoded.
Mp4Probe probe_mp4(const std::filesystem::path& path);

/// The file's top-level box types in order, e.g. {"ftyp", "moov", "free", "mdat"}.
std::vector<std::string> top_level_boxes(const std::filesystem::path& path);

}  // namespace bookspin::video::testing
