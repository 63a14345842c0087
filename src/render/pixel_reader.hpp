#pragma once
// Read-back of a finished frame into CPU memory: synchronous, or asynchronous through a ring
// of pixel-buffer objects, so a frame's read-back overlaps the next frame's work. On a
// software rasterizer with GL_MESA_pack_invert the GL writes the rows top first straight into
// the image: the driver's one copy instead of a copy into the buffer and a flipped copy out.
#include <cstdint>
#include <string>
#include <vector>

#include "common/rgba_image.hpp"
#include "render/offscreen_target.hpp"

namespace bookspin::render {

class PixelReader {
 public:
  /// `ring_size` ≥ 2 pixel-buffer objects for start()/finish(); created on first use.
  /// `read_directly`: start() reads synchronously into a CPU image with GL_PACK_INVERT_MESA
  /// instead (only where reads cost no waiting, i.e. a software rasterizer, and only with
  /// GL_MESA_pack_invert; see read_directly_here()). Same images either way.
  explicit PixelReader(int ring_size = 2, bool read_directly = false);

  /// Whether direct reads pay on the current context: a software rasterizer (its GL_RENDERER
  /// string `gl_renderer`, see is_software_rasterizer()) with GL_MESA_pack_invert.
  static bool read_directly_here(const std::string& gl_renderer);

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
    RgbaImage image;  ///< direct reads: the frame read by start(), top row first
  };
  void prepare(Slot& slot, int width, int height);
  void read_inverted(const OffscreenTarget& target, RgbaImage& image);

  int ring_size_;
  bool read_directly_;
  RgbaImage spare_;  ///< direct reads: finish()'s `reuse`, the next start()'s buffer
  std::vector<Slot> slots_;
  int next_ = 0;                       ///< slot the next start() uses
  int pending_ = 0;                    ///< reads started and not finished
  std::vector<std::uint8_t> gl_rows_;  ///< read()'s bottom-up copy before the flip
};

}  // namespace bookspin::render
