#pragma once
// The built-in faces as the text layout draws them (text_layout.cpp): the stage's own; callers
// start from typeface.hpp and text_layout.hpp.
#include <cairo.h>

#include <cstddef>
#include <optional>

#include "typeface/embedded_fonts.hpp"

namespace bookspin::typeface {

/// How many faces are built in: the six of Face, then the fallbacks.
inline constexpr std::size_t kBuiltInFaces = 8;
/// The first fallback: Droid Sans Fallback (CJK), then Symbola (emoji and symbols).
inline constexpr std::size_t kFirstFallback = 6;

/// The cairo face of built-in face `index` (< kBuiltInFaces; the order of Face, then the
/// fallbacks). Made once, kept for the process's life.
cairo_font_face_t* built_in_face(std::size_t index);

/// The font file face `index` was made from (its bytes: HarfBuzz reads them too).
const EmbeddedFont& built_in_file(std::size_t index);

/// Which built-in face `face` is, or nothing when it is none of them.
std::optional<std::size_t> built_in_index(cairo_font_face_t* face);

/// The options every text is drawn with (text_options() in words).
const cairo_font_options_t* built_in_options();

}  // namespace bookspin::typeface
