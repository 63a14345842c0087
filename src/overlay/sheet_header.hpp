#pragma once
// A sheet's header: lines of text on top of a picture, the first bold, wrapped to its width.
#include <cairo.h>

#include <string>
#include <vector>

#include "typeface/laid_out_text.hpp"

namespace bookspin::overlay {

/// `header` as a sheet `width` pixels wide draws it: the first line (the bold title, at `font`)
/// whole where it fits in width − 2·font, else as many of its words as fit, the rest leading
/// the next line; each line after it broken at spaces where it would run past width − 2·font
/// (drawn at 0.8·font from x = font): a list ("a · b · c") between its items, the dot kept at
/// the line's end, other text between words; an item or word longer than that on a line of
/// its own.
std::vector<std::string> wrap_sheet_header(cairo_t* cr, const std::vector<std::string>& header,
                                           double font, double width);

/// Draws a sheet's `header` lines on `cr` from its top, the first bold at `font` pixels, the
/// others regular at 0.8·font, 1.35 line heights apart; returns the last line's baseline (y,
/// pixels).
double draw_sheet_header(cairo_t* cr, const std::vector<std::string>& header, double font);

/// A sheet's header laid out once: its lines as wrap_sheet_header() wraps them, each laid out
/// in its face and size, and where draw_sheet_header() draws them: each line's baseline (y,
/// pixels from the top; x = font).
struct SheetHeader {
  std::vector<typeface::LaidOutText> lines;
  std::vector<double> baselines;
  double x = 0;
  double bottom = 0;  ///< the last line's baseline
};

/// `header` wrapped to a sheet `width` pixels wide and laid out, drawn as draw_sheet_header()
/// draws the wrapped lines.
SheetHeader lay_out_sheet_header(cairo_t* cr, const std::vector<std::string>& header, double font,
                                 double width);

}  // namespace bookspin::overlay
