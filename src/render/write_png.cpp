#include <cairo.h>

#include <cstdint>

#include "render/renderer.hpp"

namespace bookspin::render {

void write_png(const RgbaImage& image, const std::string& path) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, image.width, image.height);
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(surface);
    throw RenderError("cannot write '" + path + "': cairo cannot allocate the image");
  }
  // cairo wants premultiplied ARGB in native-endian 32-bit words.
  unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  for (int y = 0; y < image.height; ++y) {
    auto* dst = reinterpret_cast<std::uint32_t*>(data + static_cast<std::size_t>(y) * stride);
    const std::uint8_t* src = image.row(y);
    for (int x = 0; x < image.width; ++x, src += 4) {
      const std::uint32_t a = src[3];
      const auto pre = [a](std::uint32_t c) { return (c * a + 127) / 255; };
      dst[x] = (a << 24) | (pre(src[0]) << 16) | (pre(src[1]) << 8) | pre(src[2]);
    }
  }
  cairo_surface_mark_dirty(surface);
  const cairo_status_t status = cairo_surface_write_to_png(surface, path.c_str());
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS)
    throw RenderError("cannot write '" + path + "': " + cairo_status_to_string(status));
}

}  // namespace bookspin::render
