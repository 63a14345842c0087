#pragma once
// Text captions composited over a rendered frame (cairo, the built-in DejaVu Sans of typeface.hpp).
#include <cairo.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "common/colour.hpp"
#include "common/pixel_rect.hpp"
#include "common/rgba_image.hpp"

namespace bookspin::overlay {

/// The smallest text of the overlays where the frame has room for it, pixels: a chart shown at
/// its own size, and in a clip from 960 × 540 up the panel's plots, the sphere's and
/// Poinsot's labels and a comparison's tiles' captions (docs/outputs.md, "Pictures").
inline constexpr double kMinFont = 12.0;

enum class CaptionStyle { normal, warning };

struct CaptionLine {
  std::string text;
  CaptionStyle style = CaptionStyle::normal;
  bool bold = false;
};

/// Draws `lines` in a translucent dark box at the top-left corner of `image` (RGBA, top row
/// first). The font size scales with the image height (about 2.6% of it, at least 10 px: 12 px and
/// more from a frame 462 px high).
void draw_caption(RgbaImage& image, const std::vector<CaptionLine>& lines);

/// A line across a caption under its first line, drawn as a run's curves are in the plots
/// (its colour, dashed or not): the caption of a comparison's tile is then that run's legend.
struct CaptionKey {
  Rgb colour;
  bool dashed = false;
};

/// Where and how large a caption is drawn (pixels); zeros keep the defaults of
/// draw_caption(image, lines).
struct CaptionLayout {
  double x = 0, y = 0;            ///< top-left corner of the box (0, 0: a margin of 0.6 font sizes)
  double font_size = 0;           ///< 0: 2.6% of the image height, at least 10
  double max_width = 0;           ///< widest box allowed; the font shrinks to fit (0: no limit)
  std::optional<CaptionKey> key;  ///< none: no line
};

/// Same, placed and sized by `layout`.
void draw_caption(RgbaImage& image, const std::vector<CaptionLine>& lines,
                  const CaptionLayout& layout);

class CairoCanvas;

/// draw_caption for the frames of one clip, whose first lines (title, model) stay the same:
/// the box and the lines that were the same as the previous frame's are kept drawn, and
/// each frame adds only the lines after them over a copy. The pixels are exactly
/// draw_caption's.
class CaptionPainter {
 public:
  CaptionPainter();
  ~CaptionPainter();
  CaptionPainter(const CaptionPainter&) = delete;
  CaptionPainter& operator=(const CaptionPainter&) = delete;

  /// As draw_caption(image, lines, layout).
  void draw(RgbaImage& image, const std::vector<CaptionLine>& lines, const CaptionLayout& layout);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// The height (pixels) of the box draw_caption draws for `lines` lines at `font_size`: 1.35
/// font sizes a line and 0.6 of padding, and half a font size more under the first line where
/// it is `keyed` (CaptionLayout::key); its bottom is the box's top (CaptionLayout::y, or 0.6
/// font sizes by default) plus this.
double caption_height(std::size_t lines, double font_size, bool keyed = false);

/// The default caption's font size (pixels) in an image `image_height` pixels high.
double default_caption_font(int image_height);

/// The font size (pixels) draw_caption would use for `lines` at `font_size` within a box of
/// at most `max_width` pixels, so several captions can share the smallest.
double caption_font_size(const std::vector<CaptionLine>& lines, double font_size, double max_width);

/// `line` broken after its commas into as few lines as fit a caption box of `max_width` pixels
/// at `font_size` (each comma kept at the end of its line), at most `max_lines` of them; the
/// line whole where it fits, and where `max_lines` are too few, the last holds the rest (the
/// box's font then shrinks to fit it: caption_font_size).
std::vector<CaptionLine> wrap_at_commas(const CaptionLine& line, double font_size, double max_width,
                                        std::size_t max_lines);

/// Draws one large centred warning banner near the bottom of `image` (e.g. "diverged at
/// t = 31.35"), white on red, centred on column `centre_x` (pixels; < 0: the middle).
void draw_banner(RgbaImage& image, const std::string& text, double centre_x = -1.0);

/// Draws a title strip's text over `strip` (pixels, within `image`; its background is the
/// caller's): `title` in bold at the left and "t = 12.3" (`t` in time units, one decimal) at
/// the right, in light grey, half the strip's height high and centred on it vertically.
/// A comparison's header above its tiles.
void draw_title_strip(RgbaImage& image, const PixelRect& strip, const std::string& title, double t);

}  // namespace bookspin::overlay
