#pragma once
// The faces every picture's text is drawn in, by name (typeface.hpp selects one on a context),
// and a text asked to be laid out in one (text_layout.hpp's lay_out_texts()).
#include <string>

namespace bookspin::typeface {

/// The faces drawn: the overlays' sans, regular and bold; the covers' serif, bold, italic and
/// the barcode's monospace.
enum class Face { sans, sans_bold, sans_mono, serif, serif_bold, serif_italic };

/// A text to lay out (text_layout.hpp's lay_out_texts()): its words, in `face` at `size` pixels
/// to the em, turned by `angle` (radians, as cairo_rotate turns; a text is laid out as the
/// context it is drawn on is turned: hinting differs); where `max_advance` is positive and the
/// text's advance is over it, laid out again at size × max_advance / advance (a title made
/// smaller to fit its width).
struct TextRequest {
  std::string utf8;
  Face face = Face::sans;
  double size = 0;
  double angle = 0;
  double max_advance = 0;
};

}  // namespace bookspin::typeface
