#pragma once
// A cairo ARGB32 surface over an RgbaImage (or a rectangle of it), composited back over it
// with alpha.
#include <cairo.h>

#include <vector>

#include "common/pixel_rect.hpp"
#include "common/rgba_image.hpp"
#include "typeface/laid_out_text.hpp"

namespace bookspin::overlay {

using bookspin::PixelRegion;

/// The title's text size (pixels) of an inset `rect` (the momentum sphere, Poinsot's
/// construction): 0.052 of its height; its labels, at 0.85 of it, at least kMinFont
/// (caption.hpp) in an inset 240 px high or higher (a 960 × 540 frame's), scaled down with a
/// smaller one's height to 9 px.
double inset_font(const PixelRect& rect);

/// The rows an inset's title takes at its top (pixels): 0.1 of its height, at least 1.9 of
/// its title's text size.
double inset_title_height(const PixelRect& rect);

/// The smallest whole-pixel region holding the rectangle (x, y, width, height) (pixels,
/// fractional) and `margin` pixels around it, clipped to a width×height image.
PixelRegion region_around(double x, double y, double width, double height, double margin,
                          int image_width, int image_height);

/// Selects the one typeface of every overlay, DejaVu Sans built into the program, bold or
/// regular, `size` pixels high, with the typeface stage's fixed options (typeface.hpp): the
/// machine's fontconfig set-up never reaches an overlay.
void select_overlay_font(cairo_t* cr, bool bold, double size);

/// Draws a text laid out once (typeface/laid_out_text.hpp) where `placed` puts it, in its
/// colour: its glyph runs by cairo_show_glyphs in the font it was laid out in, the pixels
/// typeface::show_placed() draws; the current point is then at the text's end, as after
/// typeface::show_text(). The overlays lay a picture's texts out first, then place and draw
/// them from those values.
void draw_placed_text(cairo_t* cr, const typeface::PlacedText& placed);

/// Draw on `cr()` in image coordinates, then `composite_onto(image)` blends what was drawn
/// over the image (source-over, cairo's premultiplied native-endian ARGB converted to RGBA
/// bytes). A canvas over a region holds and blends only that region's pixels (a caption or
/// the plot panel costs its own area per frame, not the frame's); drawing outside it is
/// clipped away.
class CairoCanvas {
 public:
  /// The whole width×height image.
  CairoCanvas(int width, int height);
  /// Only `region` of the image (clipped to it; may be empty).
  CairoCanvas(int width, int height, PixelRegion region);
  ~CairoCanvas();
  CairoCanvas(const CairoCanvas&) = delete;
  CairoCanvas& operator=(const CairoCanvas&) = delete;

  cairo_t* cr() const { return cr_; }
  void composite_onto(RgbaImage& image);

  /// A copy of what has been drawn so far (the region's premultiplied ARGB32 pixels).
  std::vector<unsigned char> snapshot();
  /// Puts back a snapshot of this canvas: the pixels are then exactly as they were when it
  /// was taken, so drawing on from there gives the same pixels as drawing on back then.
  /// The context's state (source, line width, path, …) is not part of it. Throws
  /// std::invalid_argument for a snapshot of another size.
  void restore(const std::vector<unsigned char>& pixels);

 private:
  PixelRegion region_;
  cairo_surface_t* surface_;
  cairo_t* cr_;
};

}  // namespace bookspin::overlay
