#include "overlay/caption.hpp"

#include <algorithm>
#include <cstdio>
#include <memory>

#include "overlay/cairo_canvas.hpp"
#include "typeface/text_layout.hpp"

namespace bookspin::overlay {

namespace {

double font_size_for(const RgbaImage& image) { return default_caption_font(image.height); }

double text_width(cairo_t* cr, const std::string& text) {
  cairo_text_extents_t extents;
  typeface::text_extents(cr, text.c_str(), &extents);
  return extents.x_advance;
}

double widest_line(cairo_t* cr, const std::vector<CaptionLine>& lines, double size) {
  double width = 0.0;
  for (const auto& line : lines) {
    select_overlay_font(cr, line.bold, size);
    width = std::max(width, text_width(cr, line.text));
  }
  return width;
}

/// A context for measuring text only (no pixels).
struct Measure {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1);
  cairo_t* cr = cairo_create(surface);
  ~Measure() {
    cairo_destroy(cr);
    cairo_surface_destroy(surface);
  }
};

double font_size_within(cairo_t* cr, const std::vector<CaptionLine>& lines, double font_size,
                        double max_width) {
  const double width = widest_line(cr, lines, font_size);
  if (max_width <= 0 || width + 1.2 * font_size <= max_width) return font_size;
  // The box is (text width + 1.2 font sizes) wide, both proportional to the font size, so
  // one rescale fits (2% spare for hinting; never below 7 px).
  return std::max(7.0, 0.98 * font_size * max_width / (width + 1.2 * font_size));
}

/// Where a caption's box goes and how large its text is (pixels).
struct CaptionBox {
  double size = 0, pad = 0, line_height = 0, x = 0, y = 0, width = 0, height = 0;
  double key_gap = 0;  ///< room under the first line for a key (CaptionLayout::key)
};

/// The room a key takes under a caption's first line, in font sizes.
constexpr double kKeyGap = 0.5;

CaptionBox caption_box(cairo_t* cr, int image_height, const std::vector<CaptionLine>& lines,
                       const CaptionLayout& layout) {
  CaptionBox box;
  box.size = layout.font_size > 0 ? layout.font_size : default_caption_font(image_height);
  box.size = font_size_within(cr, lines, box.size, layout.max_width);
  box.pad = 0.6 * box.size, box.line_height = 1.35 * box.size;
  box.x = layout.x > 0 ? layout.x : box.pad, box.y = layout.y > 0 ? layout.y : box.pad;
  box.width = widest_line(cr, lines, box.size) + 2 * box.pad;
  box.height = caption_height(lines.size(), box.size, layout.key.has_value());
  box.key_gap = layout.key ? kKeyGap * box.size : 0.0;
  return box;
}

void fill_caption_box(cairo_t* cr, const CaptionBox& box) {
  cairo_rectangle(cr, box.x, box.y, box.width, box.height);
  cairo_set_source_rgba(cr, 0.05, 0.06, 0.09, 0.62);
  cairo_fill(cr);
}

/// Lines [first, last) of the caption in `box`.
void draw_caption_lines(cairo_t* cr, const std::vector<CaptionLine>& lines, std::size_t first,
                        std::size_t last, const CaptionBox& box) {
  double baseline = box.y + box.pad / 2 + box.size;
  for (std::size_t i = 0; i < last; ++i, baseline += box.line_height) {
    if (i == 1) baseline += box.key_gap;
    if (i < first) continue;
    const CaptionLine& line = lines[i];
    select_overlay_font(cr, line.bold, box.size);
    if (line.style == CaptionStyle::warning) {
      cairo_set_source_rgb(cr, 1.0, 0.45, 0.35);
    } else {
      cairo_set_source_rgb(cr, 0.95, 0.95, 0.92);
    }
    cairo_move_to(cr, box.x + box.pad, baseline);
    typeface::show_text(cr, line.text.c_str());
  }
}

void draw_caption_box(cairo_t* cr, const std::vector<CaptionLine>& lines, const CaptionBox& box) {
  fill_caption_box(cr, box);
  draw_caption_lines(cr, lines, 0, lines.size(), box);
}

/// The key's line under the first line's baseline, across the box's text width, in the
/// line width and dash pattern of a plot's curves at this size (overlay/plot.cpp), on a strip
/// of the panel's paper (charts/panel.cpp), so that dark colours show as in the plots.
void draw_key(cairo_t* cr, const CaptionKey& key, const CaptionBox& box) {
  // Midway between the first line's descenders (0.24 font sizes under its baseline) and the
  // second line's capitals.
  const double y = box.y + box.pad / 2 + box.size + 0.66 * box.size;
  const double width = std::max(1.5, 0.15 * box.size);
  const double left = box.x + box.pad, right = box.x + box.width - box.pad;
  cairo_rectangle(cr, left - 2 * width, y - 1.5 * width, right - left + 4 * width, 3 * width);
  cairo_set_source_rgba(cr, 0.98, 0.98, 0.97, 0.9);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, key.colour.r, key.colour.g, key.colour.b);
  cairo_set_line_width(cr, width);
  const double dash[] = {4 * width, 2.5 * width};
  cairo_set_dash(cr, dash, key.dashed ? 2 : 0, 0);
  cairo_move_to(cr, left, y);
  cairo_line_to(cr, right, y);
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
}

bool operator==(const CaptionLine& a, const CaptionLine& b) {
  return a.text == b.text && a.style == b.style && a.bold == b.bold;
}

bool operator==(const CaptionBox& a, const CaptionBox& b) {
  return a.size == b.size && a.pad == b.pad && a.line_height == b.line_height && a.x == b.x &&
         a.y == b.y && a.width == b.width && a.height == b.height && a.key_gap == b.key_gap;
}

/// How many leading lines `a` and `b` share.
std::size_t common_lines(const std::vector<CaptionLine>& a, const std::vector<CaptionLine>& b) {
  std::size_t n = 0;
  while (n < a.size() && n < b.size() && a[n] == b[n]) ++n;
  return n;
}

}  // namespace

double caption_height(std::size_t lines, double font_size, bool keyed) {
  return static_cast<double>(lines) * 1.35 * font_size + 0.6 * font_size +
         (keyed ? kKeyGap * font_size : 0.0);
}

double default_caption_font(int image_height) { return std::max(10.0, 0.026 * image_height); }

double caption_font_size(const std::vector<CaptionLine>& lines, double font_size,
                         double max_width) {
  return font_size_within(Measure().cr, lines, font_size, max_width);
}

std::vector<CaptionLine> wrap_at_commas(const CaptionLine& line, double font_size, double max_width,
                                        std::size_t max_lines) {
  Measure measure;
  select_overlay_font(measure.cr, line.bold, font_size);
  const double room = max_width - 1.2 * font_size;  // the box's two paddings
  std::vector<CaptionLine> out;
  std::string rest = line.text;
  while (out.size() + 1 < max_lines && text_width(measure.cr, rest) > room) {
    // The longest head of `rest` that ends at a comma and fits; none fits: the first.
    std::size_t cut = std::string::npos;
    for (std::size_t at = rest.find(", "); at != std::string::npos; at = rest.find(", ", at + 1)) {
      if (cut != std::string::npos && text_width(measure.cr, rest.substr(0, at + 1)) > room) break;
      cut = at;
    }
    if (cut == std::string::npos) break;  // no comma: one line, shrunk
    out.push_back({rest.substr(0, cut + 1), line.style, line.bold});
    rest = rest.substr(cut + 2);
  }
  out.push_back({rest, line.style, line.bold});
  return out;
}

void draw_caption(RgbaImage& image, const std::vector<CaptionLine>& lines,
                  const CaptionLayout& layout) {
  if (lines.empty()) return;
  const CaptionBox box = caption_box(Measure().cr, image.height, lines, layout);
  // Only the box's pixels: a frame's caption then costs its own area, not the frame's.
  CairoCanvas canvas(
      image.width, image.height,
      region_around(box.x, box.y, box.width, box.height, 2.0, image.width, image.height));
  draw_caption_box(canvas.cr(), lines, box);
  if (layout.key) draw_key(canvas.cr(), *layout.key, box);
  canvas.composite_onto(image);
}

struct CaptionPainter::State {
  Measure measure;
  int width = 0, height = 0;
  CaptionBox box;
  std::unique_ptr<CairoCanvas> canvas;
  std::vector<CaptionLine> kept;      ///< the lines drawn in `drawn`
  std::vector<unsigned char> drawn;   ///< the canvas with the box and `kept` drawn
  std::vector<CaptionLine> previous;  ///< the last frame's lines
};

CaptionPainter::CaptionPainter() : state_(std::make_unique<State>()) {}
CaptionPainter::~CaptionPainter() = default;

// draw_caption's calls, with the box and the lines the frames share drawn once.
void CaptionPainter::draw(RgbaImage& image, const std::vector<CaptionLine>& lines,
                          const CaptionLayout& layout) {
  if (lines.empty()) return;
  State& s = *state_;
  const CaptionBox box = caption_box(s.measure.cr, image.height, lines, layout);
  const std::size_t stable = common_lines(lines, s.previous);
  s.previous = lines;
  const bool holds = s.canvas && image.width == s.width && image.height == s.height &&
                     box == s.box && common_lines(lines, s.kept) == s.kept.size() &&
                     s.kept.size() >= stable;
  if (holds) {
    s.canvas->restore(s.drawn);
  } else {
    s.width = image.width, s.height = image.height, s.box = box;
    s.canvas = std::make_unique<CairoCanvas>(
        image.width, image.height,
        region_around(box.x, box.y, box.width, box.height, 2.0, image.width, image.height));
    fill_caption_box(s.canvas->cr(), box);
    draw_caption_lines(s.canvas->cr(), lines, 0, stable, box);
    s.kept.assign(lines.begin(), lines.begin() + static_cast<std::ptrdiff_t>(stable));
    s.drawn = s.canvas->snapshot();
  }
  draw_caption_lines(s.canvas->cr(), lines, s.kept.size(), lines.size(), box);
  s.canvas->composite_onto(image);
}

void draw_caption(RgbaImage& image, const std::vector<CaptionLine>& lines) {
  draw_caption(image, lines, CaptionLayout{});
}

void draw_banner(RgbaImage& image, const std::string& text, double centre_x) {
  Measure measure;
  cairo_t* m = measure.cr;
  if (centre_x < 0) centre_x = 0.5 * image.width;
  double size = 1.8 * font_size_for(image);
  select_overlay_font(m, true, size);
  // Shrink to fit small frames: the banner, centred on centre_x, must stay in the frame.
  const double room = 2.0 * std::min(centre_x, image.width - centre_x);
  const double fit = 0.9 * room / std::max(1.0, text_width(m, text) + size);
  if (fit < 1.0) {
    size *= fit;
    select_overlay_font(m, true, size);
  }
  const double width = text_width(m, text), pad = 0.5 * size;
  const double x = centre_x - 0.5 * width, y = image.height - 2.2 * size;
  const double box_x = x - pad, box_y = y - size - pad / 2, box_w = width + 2 * pad,
               box_h = size + 1.5 * pad;
  CairoCanvas canvas(image.width, image.height,
                     region_around(box_x, box_y, box_w, box_h, 2.0, image.width, image.height));
  cairo_t* cr = canvas.cr();
  cairo_rectangle(cr, box_x, box_y, box_w, box_h);
  cairo_set_source_rgba(cr, 0.75, 0.08, 0.06, 0.88);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  select_overlay_font(cr, true, size);
  cairo_move_to(cr, x, y);
  typeface::show_text(cr, text.c_str());
  canvas.composite_onto(image);
}

void draw_title_strip(RgbaImage& image, const PixelRect& strip, const std::string& title,
                      double t) {
  CairoCanvas canvas(
      image.width, image.height,
      region_around(strip.x, strip.y, strip.width, strip.height, 0.0, image.width, image.height));
  cairo_t* cr = canvas.cr();
  const double font = 0.5 * strip.height, margin = 0.6 * font;
  select_overlay_font(cr, true, font);
  cairo_set_source_rgb(cr, 0.95, 0.95, 0.92);
  const double baseline = strip.y + 0.5 * strip.height + 0.36 * font;
  cairo_move_to(cr, strip.x + margin, baseline);
  typeface::show_text(cr, title.c_str());
  char time[32];
  std::snprintf(time, sizeof time, "t = %.1f", t);
  cairo_move_to(cr, strip.x + strip.width - text_width(cr, time) - margin, baseline);
  typeface::show_text(cr, time);
  canvas.composite_onto(image);
}

}  // namespace bookspin::overlay
