#include "render/cairo_draw.hpp"

#include <algorithm>
#include <cstdint>

#include "common/argb32.hpp"
#include "render/render_error.hpp"
#include "typeface/text_layout.hpp"

namespace bookspin::render::draw {

namespace {

// A small integer hash: the same cloth grain on every run and machine.
std::uint32_t hash2(std::uint32_t x, std::uint32_t y) {
  std::uint32_t h = x * 374761393u + y * 668265263u;
  h = (h ^ (h >> 13)) * 1274126177u;
  return h ^ (h >> 16);
}

std::uint8_t channel(double value) {
  return static_cast<std::uint8_t>(std::clamp(value, 0.0, 1.0) * 255.0 + 0.5);
}

}  // namespace

SurfacePtr make_surface(int width, int height) {
  SurfacePtr surface(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height),
                     &cairo_surface_destroy);
  if (cairo_surface_status(surface.get()) != CAIRO_STATUS_SUCCESS)
    throw RenderError(std::string("cairo cannot create a texture surface: ") +
                      cairo_status_to_string(cairo_surface_status(surface.get())));
  return surface;
}

ContextPtr make_context(cairo_surface_t* surface) {
  ContextPtr cr(cairo_create(surface), &cairo_destroy);
  if (cairo_status(cr.get()) != CAIRO_STATUS_SUCCESS)
    throw RenderError(std::string("cairo cannot draw a texture: ") +
                      cairo_status_to_string(cairo_status(cr.get())));
  return cr;
}

RgbaImage to_rgba(cairo_surface_t* surface) {
  cairo_surface_flush(surface);
  const int width = cairo_image_surface_get_width(surface);
  const int height = cairo_image_surface_get_height(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  RgbaImage image(width, height);
  for (int y = 0; y < height; ++y) {
    const unsigned char* src = data + static_cast<std::size_t>(y) * stride;
    std::uint8_t* dst = image.row(y);
    for (int x = 0; x < width; ++x, dst += 4)
      argb32::to_straight_rgba(argb32::load(src + 4 * x), dst);
  }
  return image;
}

void set_color(cairo_t* cr, Rgb color, double alpha) {
  cairo_set_source_rgba(cr, color.r, color.g, color.b, alpha);
}

void fill_cloth(cairo_surface_t* surface, Rgb base) {
  cairo_surface_flush(surface);
  const int width = cairo_image_surface_get_width(surface);
  const int height = cairo_image_surface_get_height(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  unsigned char* data = cairo_image_surface_get_data(surface);
  for (int y = 0; y < height; ++y) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::size_t>(y) * stride);
    for (int x = 0; x < width; ++x) {
      // Weave: alternating threads in x and y, plus fine random fibre noise.
      const double weave = ((x / 2 + y / 2) % 2 == 0 ? 0.025 : -0.025);
      const double noise = (static_cast<double>(hash2(x, y) & 0xff) / 255.0 - 0.5) * 0.06;
      const double k = 1.0 + weave + noise;
      row[x] = 0xff000000u | (std::uint32_t{channel(base.r * k)} << 16) |
               (std::uint32_t{channel(base.g * k)} << 8) | channel(base.b * k);
    }
  }
  cairo_surface_mark_dirty(surface);
}

double text_width(cairo_t* cr, const std::string& text) {
  cairo_text_extents_t extents;
  typeface::text_extents(cr, text.c_str(), &extents);
  return extents.x_advance;
}

double centered_text(cairo_t* cr, const std::string& text, double centre_x, double baseline,
                     double max_width) {
  cairo_matrix_t matrix;
  cairo_get_font_matrix(cr, &matrix);
  double size = matrix.yy;
  const double width = text_width(cr, text);
  if (width > max_width) {
    size *= max_width / width;
    cairo_set_font_size(cr, size);
  }
  cairo_move_to(cr, centre_x - text_width(cr, text) / 2.0, baseline);
  typeface::show_text(cr, text.c_str());
  return size;
}

void inset_frame(cairo_t* cr, double width, double height, double inset, double line_width) {
  cairo_set_line_width(cr, line_width);
  cairo_rectangle(cr, inset, inset, width - 2 * inset, height - 2 * inset);
  cairo_stroke(cr);
}

void ornament_rule(cairo_t* cr, double centre_x, double y, double half_length) {
  const double d = 14.0;
  cairo_set_line_width(cr, 3.0);
  cairo_move_to(cr, centre_x - half_length, y);
  cairo_line_to(cr, centre_x - 2 * d, y);
  cairo_move_to(cr, centre_x + 2 * d, y);
  cairo_line_to(cr, centre_x + half_length, y);
  cairo_stroke(cr);
  diamond(cr, centre_x, y, d);
}

void diamond(cairo_t* cr, double x, double y, double d) {
  cairo_move_to(cr, x, y - d);
  cairo_line_to(cr, x + d, y);
  cairo_line_to(cr, x, y + d);
  cairo_line_to(cr, x - d, y);
  cairo_close_path(cr);
  cairo_fill(cr);
}

ClothCanvas cloth_canvas(int width, int height, Rgb base, Rgb ink) {
  SurfacePtr surface = make_surface(width, height);
  fill_cloth(surface.get(), base);
  ContextPtr context = make_context(surface.get());
  set_color(context.get(), ink);
  return {std::move(surface), std::move(context)};
}

}  // namespace bookspin::render::draw
