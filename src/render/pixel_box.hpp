#pragma once
// Internal: the part of the frame a draw can touch, so that a frame redraws, clears and
// resolves only where the book was or is (the rest of the frame is the unchanging
// background).
#include <algorithm>
#include <array>
#include <vector>

#include <Eigen/Dense>

namespace bookspin::render {

/// Pixels [x0, x1) × [y0, y1) in GL window coordinates (row 0 at the bottom).
struct PixelBox {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  static PixelBox whole(int width, int height) { return {0, 0, width, height}; }
  bool empty() const { return x1 <= x0 || y1 <= y0; }
  int width() const { return std::max(0, x1 - x0); }
  int height() const { return std::max(0, y1 - y0); }
  /// The smallest box holding both.
  PixelBox united(const PixelBox& other) const {
    if (empty()) return other;
    if (other.empty()) return *this;
    return {std::min(x0, other.x0), std::min(y0, other.y0), std::max(x1, other.x1),
            std::max(y1, other.y1)};
  }
};

/// Accumulates a conservative bounding box, in pixels, of world points drawn with
/// `view_projection` into a width×height frame. A point at or behind the near plane makes
/// it the whole frame: clipping can then put the geometry anywhere.
class ScreenBounds {
 public:
  ScreenBounds(const Eigen::Matrix4f& view_projection, int width, int height);
  void add(const std::array<float, 3>& world);
  /// Grown by a margin for rasterization rules and multisample positions, clamped to the
  /// frame; empty if no point was added.
  PixelBox box() const;

 private:
  Eigen::Matrix4d view_projection_;
  int width_, height_;
  bool whole_ = false;
  double min_x_, min_y_, max_x_, max_y_;
};

/// The box of every vertex in `vertices` (anything with a `position` array).
template <typename Vertex>
void add_vertices(ScreenBounds& bounds, const std::vector<Vertex>& vertices) {
  for (const Vertex& v : vertices) bounds.add(v.position);
}

}  // namespace bookspin::render
