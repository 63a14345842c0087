#include "overlay/caption.hpp"

#include <algorithm>

#include "overlay/cairo_canvas.hpp"

namespace bookspin::overlay {

namespace {

double font_size_for(const RgbaImage& image) { return std::max(10.0, 0.026 * image.height); }

void select_font(cairo_t* cr, bool bold, double size) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

double text_width(cairo_t* cr, const std::string& text) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  return extents.x_advance;
}

}  // namespace

void draw_caption(RgbaImage& image, const std::vector<CaptionLine>& lines) {
  if (lines.empty()) return;
  CairoCanvas canvas(image.width, image.height);
  cairo_t* cr = canvas.cr();
  const double size = font_size_for(image);
  const double pad = 0.6 * size, line_height = 1.35 * size;
  double width = 0.0;
  for (const auto& line : lines) {
    select_font(cr, line.bold, size);
    width = std::max(width, text_width(cr, line.text));
  }
  cairo_rectangle(cr, pad, pad, width + 2 * pad, lines.size() * line_height + pad);
  cairo_set_source_rgba(cr, 0.05, 0.06, 0.09, 0.62);
  cairo_fill(cr);
  double y = pad + pad / 2 + size;
  for (const auto& line : lines) {
    select_font(cr, line.bold, size);
    if (line.style == CaptionStyle::warning) {
      cairo_set_source_rgb(cr, 1.0, 0.45, 0.35);
    } else {
      cairo_set_source_rgb(cr, 0.95, 0.95, 0.92);
    }
    cairo_move_to(cr, 2 * pad, y);
    cairo_show_text(cr, line.text.c_str());
    y += line_height;
  }
  canvas.composite_onto(image);
}

void draw_banner(RgbaImage& image, const std::string& text) {
  CairoCanvas canvas(image.width, image.height);
  cairo_t* cr = canvas.cr();
  const double size = 1.8 * font_size_for(image);
  select_font(cr, true, size);
  const double width = text_width(cr, text), pad = 0.5 * size;
  const double x = 0.5 * (image.width - width), y = image.height - 2.2 * size;
  cairo_rectangle(cr, x - pad, y - size - pad / 2, width + 2 * pad, size + 1.5 * pad);
  cairo_set_source_rgba(cr, 0.75, 0.08, 0.06, 0.88);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
  canvas.composite_onto(image);
}

}  // namespace bookspin::overlay
