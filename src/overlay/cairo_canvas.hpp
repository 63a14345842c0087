#pragma once
// A cairo ARGB32 surface the size of an RgbaImage, composited back over it with alpha.
#include <cairo.h>

#include "common/rgba_image.hpp"

namespace bookspin::overlay {

/// Draw on `cr()`, then `composite_onto(image)` blends what was drawn over the image
/// (source-over, cairo's premultiplied native-endian ARGB converted to RGBA bytes).
class CairoCanvas {
 public:
  CairoCanvas(int width, int height);
  ~CairoCanvas();
  CairoCanvas(const CairoCanvas&) = delete;
  CairoCanvas& operator=(const CairoCanvas&) = delete;

  cairo_t* cr() const { return cr_; }
  void composite_onto(RgbaImage& image);

 private:
  cairo_surface_t* surface_;
  cairo_t* cr_;
};

}  // namespace bookspin::overlay
