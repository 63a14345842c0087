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

double widest_line(cairo_t* cr, const std::vector<CaptionLine>& lines, double size) {
  double width = 0.0;
  for (const auto& line : lines) {
    select_font(cr, line.bold, size);
    width = std::max(width, text_width(cr, line.text));
  }
  return width;
}

}  // namespace

double caption_font_size(cairo_t* cr, const std::vector<CaptionLine>& lines, double font_size,
                         double max_width) {
  const double width = widest_line(cr, lines, font_size);
  if (max_width <= 0 || width + 1.2 * font_size <= max_width) return font_size;
  // The box is (text width + 1.2 font sizes) wide, both proportional to the font size, so
  // one rescale fits (2% spare for hinting; never below 7 px).
  return std::max(7.0, 0.98 * font_size * max_width / (width + 1.2 * font_size));
}

void draw_caption(cairo_t* cr, int image_height, const std::vector<CaptionLine>& lines,
                  const CaptionLayout& layout) {
  if (lines.empty()) return;
  double size = layout.font_size > 0 ? layout.font_size : std::max(10.0, 0.026 * image_height);
  size = caption_font_size(cr, lines, size, layout.max_width);
  const double width = widest_line(cr, lines, size);
  const double pad = 0.6 * size, line_height = 1.35 * size;
  const double x = layout.x > 0 ? layout.x : pad, y = layout.y > 0 ? layout.y : pad;
  cairo_rectangle(cr, x, y, width + 2 * pad, lines.size() * line_height + pad);
  cairo_set_source_rgba(cr, 0.05, 0.06, 0.09, 0.62);
  cairo_fill(cr);
  double baseline = y + pad / 2 + size;
  for (const auto& line : lines) {
    select_font(cr, line.bold, size);
    if (line.style == CaptionStyle::warning) {
      cairo_set_source_rgb(cr, 1.0, 0.45, 0.35);
    } else {
      cairo_set_source_rgb(cr, 0.95, 0.95, 0.92);
    }
    cairo_move_to(cr, x + pad, baseline);
    cairo_show_text(cr, line.text.c_str());
    baseline += line_height;
  }
}

void draw_caption(RgbaImage& image, const std::vector<CaptionLine>& lines, const CaptionLayout& layout) {
  if (lines.empty()) return;
  CairoCanvas canvas(image.width, image.height);
  draw_caption(canvas.cr(), image.height, lines, layout);
  canvas.composite_onto(image);
}

void draw_caption(RgbaImage& image, const std::vector<CaptionLine>& lines) {
  draw_caption(image, lines, CaptionLayout{});
}

void draw_banner(RgbaImage& image, const std::string& text, double centre_x) {
  CairoCanvas canvas(image.width, image.height);
  cairo_t* cr = canvas.cr();
  if (centre_x < 0) centre_x = 0.5 * image.width;
  double size = 1.8 * font_size_for(image);
  select_font(cr, true, size);
  // Shrink to fit small frames: the banner, centred on centre_x, must stay in the frame.
  const double room = 2.0 * std::min(centre_x, image.width - centre_x);
  const double fit = 0.9 * room / std::max(1.0, text_width(cr, text) + size);
  if (fit < 1.0) {
    size *= fit;
    select_font(cr, true, size);
  }
  const double width = text_width(cr, text), pad = 0.5 * size;
  const double x = centre_x - 0.5 * width, y = image.height - 2.2 * size;
  cairo_rectangle(cr, x - pad, y - size - pad / 2, width + 2 * pad, size + 1.5 * pad);
  cairo_set_source_rgba(cr, 0.75, 0.08, 0.06, 0.88);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, text.c_str());
  canvas.composite_onto(image);
}

}  // namespace bookspin::overlay
