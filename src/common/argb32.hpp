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

/// blend_over_opaque for `count` pixels in a row: src (ARGB32 words) over dst (RGBA bytes),
/// the same bytes, computed two channels at a time. Exact: for 0 ≤ t ≤ 65534,
/// t / 255 = (t + 1 + t / 256) / 256 (integer division), and t = dst·(255 − a) + 127 ≤ 65152
/// leaves the 16-bit lanes room; a lane's carry past 8 bits is masked off as the uint8_t
/// cast does.
inline void blend_row_over_opaque(const unsigned char* src, std::uint8_t* dst, int count) {
#if !defined(__BYTE_ORDER__) || __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
  for (int x = 0; x < count; ++x) blend_over_opaque(load(src + 4 * x), dst + 4 * x);
  return;
#endif
  for (int x = 0; x < count; ++x, src += 4, dst += 4) {
    const std::uint32_t word = load(src);
    // No branch for a = 0 (keep = 255, colour 0): (d·255 + 127) / 255 = d leaves dst as it
    // is, as blend_over_opaque's early return does; without it the loop vectorizes.
    const std::uint32_t keep = 255 - alpha(word);
    std::uint32_t d;
    std::memcpy(&d, dst, 4);  // bytes R, G, B, A: little-endian R in the low byte
    const std::uint32_t t_rb = (d & 0x00FF00FFu) * keep + 0x007F007Fu;  // R and B lanes
    const std::uint32_t t_g = ((d >> 8) & 0xFFu) * keep + 127u;
    const std::uint32_t rb =
        ((t_rb + 0x00010001u + ((t_rb >> 8) & 0x00FF00FFu)) >> 8) & 0x00FF00FFu;
    const std::uint32_t g = (t_g + 1u + (t_g >> 8)) >> 8;
    // ARGB32 holds R in bits 16–23 and B in bits 0–7: swapped into the R, B lanes.
    const std::uint32_t src_rb = ((word >> 16) & 0xFFu) | ((word & 0xFFu) << 16);
    const std::uint32_t out = ((rb + src_rb) & 0x00FF00FFu) |
                              ((((word >> 8) & 0xFFu) + g) & 0xFFu) << 8 | (d & 0xFF000000u);
    std::memcpy(dst, &out, 4);
  }
}

}  // namespace bookspin::argb32
