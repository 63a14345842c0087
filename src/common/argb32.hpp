#pragma once
// cairo's pixel format ↔ RgbaImage, per pixel: the one place that knows that cairo's
// CAIRO_FORMAT_ARGB32 is a native-endian 32-bit word, alpha in the top byte, colour
// premultiplied by alpha.
#include <algorithm>
#include <cstdint>
#include <cstring>

namespace bookspin::argb32 {

/// The ARGB32 word at `pixel` (4 bytes of a cairo image surface's data).
inline std::uint32_t load(const unsigned char* pixel) {
  std::uint32_t word;
  std::memcpy(&word, pixel, 4);
  return word;
}

inline std::uint32_t alpha(std::uint32_t word) { return word >> 24; }

/// Writes the straight (un-premultiplied) RGBA of `word` to dst[0..3]; a fully transparent
/// pixel becomes transparent black.
inline void to_straight_rgba(std::uint32_t word, std::uint8_t* dst) {
  const std::uint32_t a = alpha(word);
  const auto straight = [a](std::uint32_t c) {
    return static_cast<std::uint8_t>(a == 0 ? 0
                                            : std::min<std::uint32_t>(255, (c * 255 + a / 2) / a));
  };
  dst[0] = straight((word >> 16) & 0xff);
  dst[1] = straight((word >> 8) & 0xff);
  dst[2] = straight(word & 0xff);
  dst[3] = static_cast<std::uint8_t>(a);
}

/// Blends `word` over the opaque RGB at dst[0..2] (source-over with premultiplied colour:
/// out = src + dst·(1 − a)); dst[3] is left as it is.
inline void blend_over_opaque(std::uint32_t word, std::uint8_t* dst) {
  const std::uint32_t a = alpha(word);
  if (a == 0) return;
  const std::uint32_t keep = 255 - a;
  const std::uint32_t rgb[3] = {(word >> 16) & 255u, (word >> 8) & 255u, word & 255u};
  for (int c = 0; c < 3; ++c)
    dst[c] = static_cast<std::uint8_t>(rgb[c] + (dst[c] * keep + 127) / 255);
}

}  // namespace bookspin::argb32
