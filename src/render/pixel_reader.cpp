#include "render/pixel_reader.hpp"

#include <algorithm>
#include <cstring>

namespace bookspin::render {

namespace {

// GL's rows run bottom to top; RgbaImage's run top to bottom.
void flip_rows(RgbaImage& image, std::vector<std::uint8_t>& scratch) {
  const std::size_t stride = static_cast<std::size_t>(image.width) * 4;
  scratch.resize(stride);
  for (int top = 0, bottom = image.height - 1; top < bottom; ++top, --bottom) {
    std::memcpy(scratch.data(), image.row(top), stride);
    std::memcpy(image.row(top), image.row(bottom), stride);
    std::memcpy(image.row(bottom), scratch.data(), stride);
  }
}

}  // namespace

void PixelReader::read(const OffscreenTarget& target, RgbaImage& image) {
  if (image.width != target.width() || image.height != target.height())
    image = RgbaImage(target.width(), target.height());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, target.resolved_framebuffer());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
  check_gl("reading back the frame (glReadPixels)");
  flip_rows(image, row_buffer_);
}

}  // namespace bookspin::render
