#pragma once
// Every picture's text drawn in any alphabet: cairo's three text calls (cairo_show_text,
// cairo_text_extents, cairo_text_path) with the same arguments, the same units (the context's
// user space, the current point at the text's left baseline origin) and the same current point
// afterwards, in the face and size select() set, plus what that face lacks
// (docs/architecture.md, the typeface stage):
//   - the text is split into bidirectional runs (the Unicode Bidirectional Algorithm, FriBidi;
//     the paragraph left to right, as the pictures' own words are) and the runs are drawn in
//     visual order, so Arabic or Hebrew reads right to left within a left-to-right line;
//   - each character is drawn in the first built-in face that has it: the selected face, DejaVu
//     Sans, Droid Sans Fallback (CJK), Symbola (emoji); a mark or joiner stays with the
//     character before it; a character in none is drawn as the selected face's missing-glyph
//     box;
//   - a run that needs shaping (right to left, a script whose letters join or reorder, a
//     combining mark) is shaped by HarfBuzz in its face; any other run is cairo's own glyphs.
// A text wholly in the selected face, left to right and needing no shaping (every Latin, Greek
// or Cyrillic text) is handed to cairo's call itself: it draws the bytes it always drew.
// Text that is not valid UTF-8 is handed to cairo too, which refuses it as it always did.
// lay_out_text() gives the layout as a value (laid_out_text.hpp): a caller that measures a text,
// places it and draws it lays it out once; show_text() and its siblings lay out and draw at once.
#include <cairo.h>

#include <vector>

#include "typeface/face.hpp"
#include "typeface/laid_out_text.hpp"

namespace bookspin::typeface {

/// `utf8` laid out from the origin in the face and size selected on `cr`, under its current
/// transformation: its glyph runs in visual order and its extents (as text_extents() gives
/// them). `cr` is left as it was.
LaidOutText lay_out_text(cairo_t* cr, const char* utf8);

/// Each request laid out as lay_out_text() lays it out, in its own face and size (the options
/// of select()), in order, in one call; `cr` is left as it was.
std::vector<LaidOutText> lay_out_texts(cairo_t* cr, const std::vector<TextRequest>& requests);

/// Draws `text` at the current point (or the origin when there is none) in the font it was
/// laid out in, as show_text() draws its words (the same bytes where `cr` has the same
/// transformation and font options); afterwards the current point is the end of its advance.
void show_laid_out(cairo_t* cr, const LaidOutText& text);

/// Draws each of `texts` in order where it is placed, as show_laid_out() draws it, in its
/// colour; `cr` is left as it was but for its current point, the last text's end.
void show_placed(cairo_t* cr, const std::vector<PlacedText>& texts);

/// Draws `utf8` at the current point (or the origin when there is none), as cairo_show_text
/// does; afterwards the current point is the end of the text's advance.
void show_text(cairo_t* cr, const char* utf8);

/// The extents `utf8` would be drawn with by show_text() from the origin, as
/// cairo_text_extents gives them: ink box (x_bearing, y_bearing, width, height) and advance,
/// user units.
void text_extents(cairo_t* cr, const char* utf8, cairo_text_extents_t* extents);

/// Appends the outlines of `utf8`, as show_text() would draw it, to the current path, as
/// cairo_text_path does; afterwards the current point is the end of the text's advance.
void text_path(cairo_t* cr, const char* utf8);

}  // namespace bookspin::typeface
