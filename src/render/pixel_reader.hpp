#pragma once
// Read-back of a finished frame into CPU memory: synchronous, or asynchronous through a ring
// of pixel-buffer objects, so a frame's read-back overlaps the next frame's work.
#include <cstdint>
#include <vector>

#include "common/rgba_image.hpp"
#include "render/offscreen_target.hpp"

namespace bookspin::render {

class PixelReader {
 public:
  /// `ring_size` ≥ 2 pixel-buffer objects for start()/finish(); created on first use.
  explicit PixelReader(int ring_size = 2);

  /// Reads target's resolved framebuffer into `image` (resized to the target's size),
  /// flipping rows so the result is top row first. Throws RenderError on a GL error.
  void read(const OffscreenTarget& target, RgbaImage& image);

  /// Starts reading target's resolved framebuffer into the next pixel-buffer object of the
  /// ring (frame N into buffer N mod ring_size) and returns without waiting for it.
  /// Requires pending() < ring_size(). Throws RenderError on a GL error.
  void start(const OffscreenTarget& target);
  /// Waits for the oldest started read and returns its image, top row first, in `reuse`'s
  /// buffer when it has the right size (no allocation, no page faults). Requires
  /// pending() > 0. Throws RenderError on a GL error.
  RgbaImage finish(RgbaImage reuse = {});

  int pending() const { return pending_; }
  int ring_size() const { return ring_size_; }

 private:
  struct Slot {
    BufferHandle buffer;
    int width = 0, height = 0;
  };
  void prepare(Slot& slot, int width, int height);

  int ring_size_;
  std::vector<Slot> slots_;
  int next_ = 0;                       ///< slot the next start() uses
  int pending_ = 0;                    ///< reads started and not finished
  std::vector<std::uint8_t> gl_rows_;  ///< read()'s bottom-up copy before the flip
};

}  // namespace bookspin::render
