#pragma once
// Read-back of a finished frame into CPU memory.
//
// Today synchronous (glReadPixels straight into the image). The seam is deliberate: an
// asynchronous reader with a ring of 2+ pixel-buffer objects (issue 7) can replace this
// class with start(frame) / finish(frame − N) without touching the drawing code.
#include <cstdint>
#include <vector>

#include "common/rgba_image.hpp"
#include "render/offscreen_target.hpp"

namespace bookspin::render {

class PixelReader {
 public:
  /// Reads target's resolved framebuffer into `image` (resized to the target's size),
  /// flipping rows so the result is top row first. Throws RenderError on a GL error.
  void read(const OffscreenTarget& target, RgbaImage& image);

 private:
  std::vector<std::uint8_t> row_buffer_;  ///< scratch for the in-place row flip
};

}  // namespace bookspin::render
