#pragma once
// A text laid out once, as a value (text_layout.hpp's lay_out_text() makes it): its glyph runs,
// each glyph's place and the character it draws, and its extents. A caller measures, places and
// draws a text from this one value, and reads where each piece of it goes (which glyph is left
// of which, a mark above or below its letter) without drawing it.
#include <cairo.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace bookspin::typeface {

/// One glyph placed: its `index` in its run's face and its origin (`x`, `y`, user units from
/// the text's origin, the left end of its baseline; y grows down, as cairo's), and `cluster`:
/// the byte offset in the text of the first character it draws (a mark shaped onto its letter,
/// or a ligature, shares the cluster of the character it stands for).
struct PlacedGlyph {
  unsigned long index = 0;
  double x = 0, y = 0;
  std::size_t cluster = 0;
};

/// Glyphs of one face, left to right as drawn: `face` its index among the built-in ones
/// (built_in.hpp), `font_face` the cairo face they are drawn in; `right_to_left` where its
/// characters read right to left (their clusters then fall from left to right).
struct GlyphRun {
  std::size_t face = 0;
  std::shared_ptr<cairo_font_face_t> font_face;
  bool right_to_left = false;
  std::vector<PlacedGlyph> glyphs;
};

/// A text laid out in the font and size selected on the context it was laid out on, from the
/// origin: its glyph runs, in the order drawn, which cairo_show_glyphs draws as they are (in
/// each run's face, the font matrix and options). `whole`: a text that needs no layout (wholly
/// in the selected face, left to right, unshaped: every Latin, Greek or Cyrillic text; or not
/// UTF-8), which show_laid_out() hands to cairo's own call: its one run is cairo's own glyphs
/// (none where it is not UTF-8). `extents`: as cairo_text_extents gives them (ink box
/// x_bearing, y_bearing, width, height, and the advance), user units.
struct LaidOutText {
  std::string utf8;
  /// The font it was laid out in (drawing sets it again): the selected face, the font matrix
  /// and the font options.
  std::shared_ptr<cairo_font_face_t> font_face;
  cairo_matrix_t font_matrix{1, 0, 0, 1, 0, 0};
  std::shared_ptr<cairo_font_options_t> font_options;
  bool whole = false;
  std::vector<GlyphRun> runs;
  cairo_text_extents_t extents{};
};

/// A laid-out text placed to be drawn (text_layout.hpp's show_placed()): the context moved to
/// (`x`, `y`) and turned by `angle` (radians, as cairo_rotate turns it), the text's origin then
/// at (`origin_x`, `origin_y`) in that frame, in the colour (`r`, `g`, `b`).
struct PlacedText {
  const LaidOutText* text = nullptr;
  double x = 0, y = 0, angle = 0;
  double origin_x = 0, origin_y = 0;
  double r = 0, g = 0, b = 0;
};

}  // namespace bookspin::typeface
