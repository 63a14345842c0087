#pragma once
// Internal cairo helpers for drawing the default face images.
#include <cairo.h>

#include <memory>
#include <string>

#include "common/colour.hpp"
#include "common/rgba_image.hpp"

namespace bookspin::render::draw {

using bookspin::Rgb;

using SurfacePtr = std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)>;
using ContextPtr = std::unique_ptr<cairo_t, decltype(&cairo_destroy)>;

/// A new opaque-black ARGB32 surface; throws RenderError if cairo cannot make it.
SurfacePtr make_surface(int width, int height);
ContextPtr make_context(cairo_surface_t* surface);

/// Converts a cairo ARGB32 surface (premultiplied, native-endian) to straight RGBA.
RgbaImage to_rgba(cairo_surface_t* surface);

void set_color(cairo_t* cr, Rgb color, double alpha = 1.0);

/// Fills the whole surface with `base` plus a faint woven-cloth grain (deterministic).
void fill_cloth(cairo_surface_t* surface, Rgb base);

/// Draws `text` centred on x = centre_x with its baseline at `baseline`, first shrinking
/// the font size so the text fits in max_width. Returns the size used.
double centered_text(cairo_t* cr, const std::string& text, double centre_x, double baseline,
                     double max_width);

/// Width of `text` at the current font.
double text_width(cairo_t* cr, const std::string& text);

/// A rectangle outline inset from the surface edges by `inset`.
void inset_frame(cairo_t* cr, double width, double height, double inset, double line_width);

/// A filled diamond (a square on its corner) centred on (x, y), `d` from centre to tip.
void diamond(cairo_t* cr, double x, double y, double d);

/// A surface filled with cloth of colour `base` and a context drawing on it in `ink`.
struct ClothCanvas {
  SurfacePtr surface;
  ContextPtr context;
  cairo_t* cr() const { return context.get(); }
};
ClothCanvas cloth_canvas(int width, int height, Rgb base, Rgb ink);

/// A horizontal rule with a small diamond at its middle.
void ornament_rule(cairo_t* cr, double centre_x, double y, double half_length);

}  // namespace bookspin::render::draw
