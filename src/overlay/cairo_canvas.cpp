#include "overlay/cairo_canvas.hpp"

#include <cstdint>
#include <cstring>

namespace bookspin::overlay {

CairoCanvas::CairoCanvas(int width, int height)
    : surface_(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height)),
      cr_(cairo_create(surface_)) {}

CairoCanvas::~CairoCanvas() {
  cairo_destroy(cr_);
  cairo_surface_destroy(surface_);
}

void CairoCanvas::composite_onto(RgbaImage& image) {
  cairo_surface_flush(surface_);
  const unsigned char* data = cairo_image_surface_get_data(surface_);
  const int stride = cairo_image_surface_get_stride(surface_);
  for (int y = 0; y < image.height; ++y) {
    const unsigned char* src_row = data + static_cast<std::ptrdiff_t>(y) * stride;
    std::uint8_t* dst = image.row(y);
    for (int x = 0; x < image.width; ++x, dst += 4) {
      std::uint32_t argb;
      std::memcpy(&argb, src_row + 4 * x, 4);
      const std::uint32_t a = argb >> 24;
      if (a == 0) continue;
      // Premultiplied source over opaque destination: out = src + dst·(1 − a).
      const std::uint32_t keep = 255 - a;
      const std::uint32_t rgb[3] = {(argb >> 16) & 255u, (argb >> 8) & 255u, argb & 255u};
      for (int c = 0; c < 3; ++c) dst[c] = static_cast<std::uint8_t>(rgb[c] + (dst[c] * keep + 127) / 255);
    }
  }
}

}  // namespace bookspin::overlay
