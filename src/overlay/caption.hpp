#pragma once
// Text captions composited over a rendered frame (cairo, DejaVu Sans through fontconfig).
#include <string>
#include <vector>

#include "common/rgba_image.hpp"

namespace bookspin::overlay {

enum class CaptionStyle { normal, warning };

struct CaptionLine {
  std::string text;
  CaptionStyle style = CaptionStyle::normal;
  bool bold = false;
};

/// Draws `lines` in a translucent dark box at the top-left corner of `image` (RGBA, top row
/// first). The font size scales with the image height (about 2.6% of it, at least 10 px).
void draw_caption(RgbaImage& image, const std::vector<CaptionLine>& lines);

/// Draws one large centred warning banner near the bottom of `image` (e.g. "diverged at
/// t = 31.35"), white on red.
void draw_banner(RgbaImage& image, const std::string& text);

}  // namespace bookspin::overlay
