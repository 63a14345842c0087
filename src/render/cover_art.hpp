#pragma once
// Internal: the default artwork of each face image, drawn with cairo.
#include "common/rgba_image.hpp"

namespace bookspin::render::art {

/// Sizes follow the default book (a, b, c) = (1.878, 2.9085, 0.5) so texels are square.
inline constexpr int cover_width = 1024, cover_height = 1584;  ///< a × b
inline constexpr int spine_width = 1584, spine_height = 272;   ///< b × c (long side = u)
inline constexpr int pages_width = 1024, pages_height = 256;

RgbaImage front_cover();
RgbaImage back_cover();
RgbaImage spine();
RgbaImage pages();

}  // namespace bookspin::render::art
