#include "overlay/cairo_canvas.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include "common/argb32.hpp"
#include "overlay/caption.hpp"
#include "typeface/typeface.hpp"

namespace bookspin::overlay {

namespace {

PixelRegion clipped(PixelRegion r, int image_width, int image_height) {
  const int x0 = std::clamp(r.x, 0, image_width), y0 = std::clamp(r.y, 0, image_height);
  const int x1 = std::clamp(r.x + std::max(0, r.width), x0, image_width);
  const int y1 = std::clamp(r.y + std::max(0, r.height), y0, image_height);
  return {x0, y0, x1 - x0, y1 - y0};
}

}  // namespace

void select_overlay_font(cairo_t* cr, bool bold, double size) {
  typeface::select(cr, bold ? typeface::Face::sans_bold : typeface::Face::sans, size);
}

void draw_placed_text(cairo_t* cr, const typeface::PlacedText& placed) {
  const typeface::LaidOutText& text = *placed.text;
  cairo_save(cr);
  if (placed.angle != 0 || placed.x != 0 || placed.y != 0) {
    cairo_translate(cr, placed.x, placed.y);
    cairo_rotate(cr, placed.angle);
  }
  cairo_set_source_rgb(cr, placed.r, placed.g, placed.b);
  if (text.font_options) cairo_set_font_options(cr, text.font_options.get());
  cairo_set_font_matrix(cr, &text.font_matrix);
  std::vector<cairo_glyph_t> glyphs;
  for (const typeface::GlyphRun& run : text.runs) {
    glyphs.clear();
    for (const typeface::PlacedGlyph& g : run.glyphs)
      glyphs.push_back({g.index, placed.origin_x + g.x, placed.origin_y + g.y});
    cairo_set_font_face(cr, run.font_face.get());
    cairo_show_glyphs(cr, glyphs.data(), static_cast<int>(glyphs.size()));
  }
  cairo_move_to(cr, placed.origin_x + text.extents.x_advance, placed.origin_y);
  cairo_restore(cr);
}

double inset_font(const PixelRect& rect) {
  return std::max({9.0, 0.052 * rect.height, std::min(kMinFont / 0.85, rect.height / 17.0)});
}

double inset_title_height(const PixelRect& rect) {
  return std::max(0.1 * rect.height, 1.9 * inset_font(rect));
}

PixelRegion region_around(double x, double y, double width, double height, double margin,
                          int image_width, int image_height) {
  const double x0 = std::floor(x - margin), y0 = std::floor(y - margin);
  const double x1 = std::ceil(x + width + margin), y1 = std::ceil(y + height + margin);
  // Clamp in double first: a huge rectangle must not overflow int.
  const auto to_int = [](double v, int hi) {
    return static_cast<int>(std::clamp(v, 0.0, double(hi)));
  };
  const int ix0 = to_int(x0, image_width), iy0 = to_int(y0, image_height);
  return {ix0, iy0, to_int(x1, image_width) - ix0, to_int(y1, image_height) - iy0};
}

CairoCanvas::CairoCanvas(int width, int height)
    : CairoCanvas(width, height, {0, 0, width, height}) {}

CairoCanvas::CairoCanvas(int width, int height, PixelRegion region)
    : region_(clipped(region, width, height)),
      surface_(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, region_.width, region_.height)),
      cr_(nullptr) {
  // Callers draw in image coordinates; the device offset maps them onto the region.
  cairo_surface_set_device_offset(surface_, -region_.x, -region_.y);
  cr_ = cairo_create(surface_);
}

CairoCanvas::~CairoCanvas() {
  cairo_destroy(cr_);
  cairo_surface_destroy(surface_);
}

void CairoCanvas::composite_onto(RgbaImage& image) {
  cairo_surface_flush(surface_);
  const unsigned char* data = cairo_image_surface_get_data(surface_);
  if (data == nullptr) return;  // an empty region
  const int stride = cairo_image_surface_get_stride(surface_);
  const int rows = std::min(region_.height, image.height - region_.y);
  const int columns = std::min(region_.width, image.width - region_.x);
  for (int y = 0; y < rows; ++y) {
    const unsigned char* src_row = data + static_cast<std::ptrdiff_t>(y) * stride;
    std::uint8_t* dst = image.row(region_.y + y) + 4 * static_cast<std::ptrdiff_t>(region_.x);
    argb32::blend_row_over_opaque(src_row, dst, columns);
  }
}

std::vector<unsigned char> CairoCanvas::snapshot() {
  cairo_surface_flush(surface_);
  const unsigned char* data = cairo_image_surface_get_data(surface_);
  if (data == nullptr) return {};
  const std::size_t bytes =
      static_cast<std::size_t>(cairo_image_surface_get_stride(surface_)) * region_.height;
  return std::vector<unsigned char>(data, data + bytes);
}

void CairoCanvas::restore(const std::vector<unsigned char>& pixels) {
  cairo_surface_flush(surface_);
  unsigned char* data = cairo_image_surface_get_data(surface_);
  const std::size_t bytes =
      data == nullptr
          ? 0
          : static_cast<std::size_t>(cairo_image_surface_get_stride(surface_)) * region_.height;
  if (pixels.size() != bytes)
    throw std::invalid_argument("CairoCanvas::restore: a snapshot of another size");
  if (bytes > 0) std::memcpy(data, pixels.data(), bytes);
  cairo_surface_mark_dirty(surface_);
}

}  // namespace bookspin::overlay
