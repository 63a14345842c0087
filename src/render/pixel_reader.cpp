#include "render/pixel_reader.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "render/gl_util.hpp"
#include "render/render_error.hpp"

namespace bookspin::render {

namespace {

void bind_for_reading(const OffscreenTarget& target) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target.resolved_framebuffer());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
}

/// A bottom-up GL image (GL's rows run bottom to top) as an RgbaImage, flipped while copying: one
/// pass over the pixels, into `image`'s own buffer when it has the size already, else into a new
/// one without zero-filling it first.
void copy_flipped(const std::uint8_t* gl_rows, int width, int height, RgbaImage& image) {
  const std::size_t stride = static_cast<std::size_t>(width) * 4;
  if (image.width == width && image.height == height && image.pixels.size() == stride * height) {
    for (int y = 0; y < height; ++y)
      std::memcpy(image.row(y), gl_rows + stride * (height - 1 - y), stride);
    return;
  }
  image.width = width;
  image.height = height;
  image.pixels.clear();
  image.pixels.reserve(stride * height);
  for (int y = height - 1; y >= 0; --y) {
    const std::uint8_t* row = gl_rows + stride * y;
    image.pixels.insert(image.pixels.end(), row, row + stride);
  }
}

}  // namespace

PixelReader::PixelReader(int ring_size, bool read_directly)
    : ring_size_(std::max(2, ring_size)), read_directly_(read_directly) {}

bool PixelReader::read_directly_here(const std::string& gl_renderer) {
  return is_software_rasterizer(gl_renderer) && epoxy_has_gl_extension("GL_MESA_pack_invert");
}

// GL_PACK_INVERT_MESA makes glReadPixels write the last row first, i.e. top row first. The
// image's buffer is reused when it has the size already (no allocation, no page faults).
void PixelReader::read_inverted(const OffscreenTarget& target, RgbaImage& image) {
  const std::size_t bytes = static_cast<std::size_t>(target.width()) * target.height() * 4;
  image.width = target.width();
  image.height = target.height();
  image.pixels.resize(bytes);
  bind_for_reading(target);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_INVERT_MESA, GL_TRUE);
  glReadPixels(0, 0, target.width(), target.height(), GL_RGBA, GL_UNSIGNED_BYTE,
               image.pixels.data());
  glPixelStorei(GL_PACK_INVERT_MESA, GL_FALSE);
  check_gl("reading back the frame (glReadPixels, rows inverted)");
}

void PixelReader::read(const OffscreenTarget& target, RgbaImage& image) {
  if (read_directly_) {
    read_inverted(target, image);
    return;
  }
  bind_for_reading(target);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);  // into client memory, not a ring buffer
  gl_rows_.resize(static_cast<std::size_t>(target.width()) * target.height() * 4);
  glReadPixels(0, 0, target.width(), target.height(), GL_RGBA, GL_UNSIGNED_BYTE, gl_rows_.data());
  check_gl("reading back the frame (glReadPixels)");
  copy_flipped(gl_rows_.data(), target.width(), target.height(), image);
}

void PixelReader::prepare(Slot& slot, int width, int height) {
  if (!slot.buffer.get()) {
    GLuint name = 0;
    glGenBuffers(1, &name);
    slot.buffer = BufferHandle(name);
  }
  glBindBuffer(GL_PIXEL_PACK_BUFFER, slot.buffer.get());
  if (slot.width != width || slot.height != height) {
    const auto bytes = static_cast<GLsizeiptr>(width) * height * 4;
    glBufferData(GL_PIXEL_PACK_BUFFER, bytes, nullptr, GL_STREAM_READ);
    slot.width = width;
    slot.height = height;
  }
}

void PixelReader::start(const OffscreenTarget& target) {
  if (pending_ >= ring_size_) throw std::logic_error("PixelReader::start with the ring full");
  if (slots_.empty()) slots_.resize(static_cast<std::size_t>(ring_size_));
  Slot& slot = slots_[static_cast<std::size_t>(next_)];
  if (read_directly_) {
    slot.image = std::move(spare_);
    read_inverted(target, slot.image);
    next_ = (next_ + 1) % ring_size_;
    ++pending_;
    return;
  }
  bind_for_reading(target);
  prepare(slot, target.width(), target.height());
  // With a pack buffer bound the pointer is an offset into it: the call only queues the copy.
  glReadPixels(0, 0, slot.width, slot.height, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  check_gl("starting the read-back of a frame (glReadPixels into a pixel buffer)");
  next_ = (next_ + 1) % ring_size_;
  ++pending_;
}

RgbaImage PixelReader::finish(RgbaImage reuse) {
  if (pending_ == 0) throw std::logic_error("PixelReader::finish with no read pending");
  const int oldest = (next_ - pending_ + ring_size_) % ring_size_;
  Slot& slot = slots_[static_cast<std::size_t>(oldest)];
  --pending_;
  if (read_directly_) {
    spare_ = std::move(reuse);
    return std::move(slot.image);
  }
  glBindBuffer(GL_PIXEL_PACK_BUFFER, slot.buffer.get());
  const auto bytes = static_cast<GLsizeiptr>(slot.width) * slot.height * 4;
  const void* mapped = glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, bytes, GL_MAP_READ_BIT);
  if (mapped == nullptr) {
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    check_gl("mapping a read-back pixel buffer");
    throw RenderError("cannot map a read-back pixel buffer");
  }
  RgbaImage image = std::move(reuse);
  copy_flipped(static_cast<const std::uint8_t*>(mapped), slot.width, slot.height, image);
  glUnmapBuffer(GL_PIXEL_PACK_BUFFER);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  check_gl("reading a read-back pixel buffer");
  return image;
}

}  // namespace bookspin::render
