#pragma once
// The one rectangle type: columns [x, x + width), rows [y, y + height), in pixels. Which way
// y runs is the user's: image rows (top first) everywhere but inside the renderer, where it
// is GL window coordinates (row 0 at the bottom).
#include <algorithm>

namespace bookspin {

template <typename T>
struct Rect {
  T x{}, y{}, width{}, height{};

  T right() const { return x + width; }
  T bottom() const { return y + height; }
  bool empty() const { return !(width > T{}) || !(height > T{}); }
};

/// Fractional pixels: layouts (tiles, the panel column, text boxes).
using PixelRect = Rect<double>;
/// Whole pixels: regions of an image or a framebuffer.
using PixelRegion = Rect<int>;

/// The smallest region holding both (an empty one holds nothing).
inline PixelRegion united(const PixelRegion& a, const PixelRegion& b) {
  if (a.empty()) return b;
  if (b.empty()) return a;
  const int x = std::min(a.x, b.x), y = std::min(a.y, b.y);
  return {x, y, std::max(a.right(), b.right()) - x, std::max(a.bottom(), b.bottom()) - y};
}

}  // namespace bookspin
