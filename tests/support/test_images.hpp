#pragma once
// Deterministic synthetic frames for the sink tests.
#include <cstdint>

#include "common/rgba_image.hpp"

namespace bookspin::test {

struct Square {
  int x, y, size;
};

/// The red square's place in frame `index` of a clip: it moves 3 px per frame.
inline Square moving_square(int index) { return {8 + 3 * index, 30, 24}; }

/// A smooth gradient whose blue shifts with `index`, plus an opaque red square
/// at moving_square(index). Smooth content so lossy codecs reproduce it well.
inline RgbaImage moving_square_frame(int width, int height, int index) {
  RgbaImage image(width, height);
  const Square square = moving_square(index);
  for (int y = 0; y < height; ++y) {
    std::uint8_t* p = image.row(y);
    for (int x = 0; x < width; ++x, p += 4) {
      const bool inside = x >= square.x && x < square.x + square.size && y >= square.y &&
                          y < square.y + square.size;
      p[0] = inside ? 220 : static_cast<std::uint8_t>(40 + x * 150 / width);
      p[1] = inside ? 30 : static_cast<std::uint8_t>(60 + y * 150 / height);
      p[2] = inside ? 30 : static_cast<std::uint8_t>(80 + index * 4);
      p[3] = 255;
    }
  }
  return image;
}

/// A smooth gradient: red = x, green = y (mod 256), blue 90, opaque. Content under an overlay,
/// so that the overlay's pixels can be told from it.
inline RgbaImage gradient_frame(int width, int height) {
  RgbaImage image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.row(y) + 4 * x;
      p[0] = static_cast<std::uint8_t>(x), p[1] = static_cast<std::uint8_t>(y), p[2] = 90;
      p[3] = 255;
    }
  }
  return image;
}

/// Pseudo-random bytes, alpha included (exercises every PNG filter and makes
/// video incompressible).
inline RgbaImage noise_frame(int width, int height, std::uint32_t seed) {
  RgbaImage image(width, height);
  std::uint32_t state = seed * 2654435761u + 1;
  for (auto& byte : image.pixels) {
    state = state * 1664525u + 1013904223u;  // LCG; the high byte is random enough here
    byte = static_cast<std::uint8_t>(state >> 24);
  }
  return image;
}

}  // namespace bookspin::test
