#pragma once
// The frame that flows from the renderer to the sinks.
#include <cstdint>
#include <vector>

namespace bookspin {

/// An 8-bit RGBA image, row-major, top row first, 4 bytes per pixel (R, G, B, A).
struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  ///< size width·height·4

  RgbaImage() = default;
  RgbaImage(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h * 4, 0) {}
  std::uint8_t* row(int y) { return pixels.data() + static_cast<std::size_t>(y) * width * 4; }
  const std::uint8_t* row(int y) const {
    return pixels.data() + static_cast<std::size_t>(y) * width * 4;
  }
};

}  // namespace bookspin
