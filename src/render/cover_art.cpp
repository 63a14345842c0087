#include "render/cover_art.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>

#include "render/cairo_draw.hpp"
#include "typeface/text_layout.hpp"
#include "typeface/typeface.hpp"

namespace bookspin::render::art {

namespace {

using draw::Rgb;

constexpr Rgb navy{0.105, 0.165, 0.310};
constexpr Rgb burgundy{0.370, 0.105, 0.135};
constexpr Rgb gold{0.870, 0.700, 0.360};
constexpr Rgb cream{0.940, 0.905, 0.800};
using typeface::Face;

// The emblem: a small book tilted in a circular arrow, the subject of the volume.
void spinning_book_emblem(cairo_t* cr, double cx, double cy, double radius) {
  cairo_save(cr);
  cairo_translate(cr, cx, cy);
  cairo_set_line_width(cr, 5.0);
  cairo_arc(cr, 0, 0, radius, -0.35 * std::numbers::pi, 1.35 * std::numbers::pi);
  cairo_stroke(cr);
  // Arrow head at the arc's end, pointing along the direction of rotation.
  const double end = 1.35 * std::numbers::pi;
  cairo_save(cr);
  cairo_translate(cr, radius * std::cos(end), radius * std::sin(end));
  cairo_rotate(cr, end + std::numbers::pi / 2);
  cairo_move_to(cr, 16, 0);
  cairo_line_to(cr, -10, -14);
  cairo_line_to(cr, -10, 14);
  cairo_close_path(cr);
  cairo_fill(cr);
  cairo_restore(cr);
  cairo_rotate(cr, -0.35);
  cairo_rectangle(cr, -0.32 * radius, -0.5 * radius, 0.64 * radius, radius);
  cairo_set_line_width(cr, 4.0);
  cairo_stroke(cr);
  cairo_move_to(cr, 0.22 * radius, -0.5 * radius);  // the spine line
  cairo_line_to(cr, 0.22 * radius, 0.5 * radius);
  cairo_stroke(cr);
  cairo_restore(cr);
}

void corner_diamonds(cairo_t* cr, double width, double height, double inset) {
  const double d = 12.0;
  for (double x : {inset, width - inset}) {
    for (double y : {inset, height - inset}) {
      draw::diamond(cr, x, y, d);
    }
  }
}

void left_text(cairo_t* cr, const char* text, double x, double baseline) {
  cairo_move_to(cr, x, baseline);
  typeface::show_text(cr, text);
}

void barcode(cairo_t* cr, double x, double y, double w, double h) {
  cairo_set_source_rgb(cr, 0.97, 0.97, 0.95);
  cairo_rectangle(cr, x, y, w, h);
  cairo_fill(cr);
  cairo_set_source_rgb(cr, 0.05, 0.05, 0.05);
  std::uint32_t state = 12345u;  // fixed seed: the same "code" every time
  double bx = x + 20;
  while (bx < x + w - 24) {
    state = state * 1664525u + 1013904223u;
    const double bar = 2.0 + static_cast<double>((state >> 24) % 4) * 2.0;
    cairo_rectangle(cr, bx, y + 16, bar, h - 62);
    cairo_fill(cr);
    bx += bar + 2.0 + static_cast<double>((state >> 16) % 3) * 2.0;
  }
  typeface::select(cr, Face::sans_mono, 24);
  draw::centered_text(cr, "978-3-16-148410-0", x + w / 2, y + h - 16, w - 30);
}

const char* const blurb[] = {
    "Toss a book into the air spinning about",
    "its longest or its shortest axis, and it",
    "turns calmly. Spin it about the middle",
    "axis, and it flips over, again and again.",
    "",
    "This volume follows Euler's equations from",
    "a cloud of particles on springs to rotation",
    "matrices and quaternions, and shows what",
    "happens when a numerical integrator",
    "forgets to normalize.",
};

}  // namespace

RgbaImage front_cover() {
  const double w = cover_width, h = cover_height;
  const draw::ClothCanvas canvas = draw::cloth_canvas(cover_width, cover_height, navy, gold);
  cairo_t* cr = canvas.cr();
  draw::inset_frame(cr, w, h, 46, 7);
  draw::inset_frame(cr, w, h, 66, 2.5);
  corner_diamonds(cr, w, h, 66);
  typeface::select(cr, Face::serif_bold, 150);
  draw::centered_text(cr, "Classical", w / 2, 430, w - 220);
  typeface::select(cr, Face::serif_bold, 150);
  draw::centered_text(cr, "Mechanics", w / 2, 600, w - 220);
  draw::ornament_rule(cr, w / 2, 690, 260);
  spinning_book_emblem(cr, w / 2, 960, 150);
  typeface::select(cr, Face::serif_italic, 54);
  draw::centered_text(cr, "Rigid Bodies and Their Rotations", w / 2, 1240, w - 220);
  draw::ornament_rule(cr, w / 2, 1320, 120);
  typeface::select(cr, Face::sans, 44);
  draw::centered_text(cr, "L. EULER  \xc2\xb7  L. POINSOT", w / 2, 1430, w - 220);
  return draw::to_rgba(canvas.surface.get());
}

RgbaImage back_cover() {
  const double w = cover_width, h = cover_height;
  const draw::ClothCanvas canvas = draw::cloth_canvas(cover_width, cover_height, burgundy, gold);
  cairo_t* cr = canvas.cr();
  draw::inset_frame(cr, w, h, 46, 4);
  typeface::select(cr, Face::serif_bold, 64);
  draw::centered_text(cr, "The Unstable Rotation", w / 2, 250, w - 200);
  draw::centered_text(cr, "of a Book", w / 2, 335, w - 200);
  draw::ornament_rule(cr, w / 2, 400, 200);
  draw::set_color(cr, cream);
  typeface::select(cr, Face::serif, 38);
  double baseline = 520;
  for (const char* line : blurb) {
    left_text(cr, line, 110, baseline);
    baseline += 58;
  }
  barcode(cr, w - 110 - 330, h - 110 - 200, 330, 200);
  draw::set_color(cr, gold);
  typeface::select(cr, Face::sans_bold, 34);
  left_text(cr, "bookspin press", 110, h - 130);
  return draw::to_rgba(canvas.surface.get());
}

RgbaImage spine() {
  const double w = spine_width, h = spine_height;
  const draw::ClothCanvas canvas = draw::cloth_canvas(spine_width, spine_height, navy, gold);
  cairo_t* cr = canvas.cr();
  // Gilt bands near both ends of the spine (the book's bottom at u = 0, top at u = 1).
  for (double x : {70.0, 90.0, w - 90.0, w - 70.0}) {
    cairo_rectangle(cr, x - 3, 16, 6, h - 32);
    cairo_fill(cr);
  }
  // Reading from u = 0: publisher at the book's bottom, title, authors near the top.
  typeface::select(cr, Face::serif_bold, 96);
  draw::centered_text(cr, "CLASSICAL MECHANICS", w * 0.48, h / 2 + 34, w * 0.50);
  typeface::select(cr, Face::sans, 40);
  draw::centered_text(cr, "EULER \xc2\xb7 POINSOT", w - 280, h / 2 + 15, 240);
  typeface::select(cr, Face::sans_bold, 30);
  draw::centered_text(cr, "bookspin", 230, h / 2 + 11, 180);
  return draw::to_rgba(canvas.surface.get());
}

RgbaImage pages() {
  const double w = pages_width, h = pages_height;
  auto surface = draw::make_surface(pages_width, pages_height);
  auto ctx = draw::make_context(surface.get());
  cairo_t* cr = ctx.get();
  draw::set_color(cr, cream);
  cairo_paint(cr);
  // Page lines: one darker hairline every few rows, with a little irregularity.
  std::uint32_t state = 777u;
  for (double y = 14; y < h - 14; y += 3.0) {
    state = state * 1664525u + 1013904223u;
    const double shade = 0.14 + 0.18 * static_cast<double>((state >> 24) & 0xff) / 255.0;
    cairo_set_source_rgba(cr, 0.35, 0.30, 0.22, shade);
    cairo_rectangle(cr, 0, y, w, 1.0);
    cairo_fill(cr);
  }
  // A little shadow where the pages meet the boards.
  for (const auto& [y0, y1] : {std::pair{12.0, 40.0}, std::pair{h - 12.0, h - 40.0}}) {
    cairo_pattern_t* shadow = cairo_pattern_create_linear(0, y0, 0, y1);
    cairo_pattern_add_color_stop_rgba(shadow, 0, 0.25, 0.2, 0.12, 0.35);
    cairo_pattern_add_color_stop_rgba(shadow, 1, 0.25, 0.2, 0.12, 0.0);
    cairo_set_source(cr, shadow);
    cairo_rectangle(cr, 0, std::min(y0, y1), w, std::abs(y1 - y0));
    cairo_fill(cr);
    cairo_pattern_destroy(shadow);
  }
  // Cover boards: back cover (−z) at the top edge, front cover (+z) at the bottom edge.
  draw::set_color(cr, burgundy);
  cairo_rectangle(cr, 0, 0, w, 12);
  cairo_fill(cr);
  draw::set_color(cr, navy);
  cairo_rectangle(cr, 0, h - 12, w, 12);
  cairo_fill(cr);
  return draw::to_rgba(surface.get());
}

}  // namespace bookspin::render::art
