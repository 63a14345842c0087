#pragma once
// Checks of a decoded clip (read back by mp4_probe) against the frames it was made from, for
// the MP4, WebM and GIF encoder tests.
#include <string>

#include "common/rgba_image.hpp"
#include "mp4_probe.hpp"

namespace bookspin::video::testing {

/// Mean absolute difference per channel (R, G, B), 0…255, of `decoded` against `expected`
/// over the rectangle [x0, x1) × [y0, y1) of `decoded`; `scale` maps decoded pixels to
/// expected ones (1: same size, 2: decoded at half size).
double mean_rgb_error(const RgbaImage& decoded, const RgbaImage& expected, int scale, int x0,
                      int y0, int x1, int y1);

/// Expects the stream's codec, 4:2:0 pixels tagged BT.709, its size and a frame rate of
/// `fps`/1.
void expect_video_stream(const Mp4Probe& probe, const std::string& codec, int width, int height,
                         int fps);

/// Expects `decoded` to be moving_square_frame(width, height, index) decoded at 1/`scale` of
/// its size: mean error below `square_max` inside the square (2 decoded pixels in from its
/// border, which 4:2:0 chroma and scaling blur) and below `frame_max` over the whole frame.
/// A swapped or dropped frame moves the square and fails the first.
void expect_moving_square(const RgbaImage& decoded, int width, int height, int index, int scale,
                          double square_max, double frame_max);

}  // namespace bookspin::video::testing
