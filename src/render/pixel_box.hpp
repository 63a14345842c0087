#pragma once
// Internal: the part of the frame a draw can touch, so that a frame redraws, clears and
// resolves only where the book was or is (the rest of the frame is the unchanging
// background).
#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <vector>

#include "common/pixel_rect.hpp"

namespace bookspin::render {

/// The whole width×height frame.
inline PixelRegion whole_frame(int width, int height) { return {0, 0, width, height}; }

/// Accumulates a conservative bounding box, in pixels, of world points drawn with
/// `view_projection` into a width×height frame. A point at or behind the near plane makes
/// it the whole frame: clipping can then put the geometry anywhere.
class ScreenBounds {
 public:
  ScreenBounds(const Eigen::Matrix4f& view_projection, int width, int height);
  void add(const std::array<float, 3>& world);
  /// Grown by a margin for rasterization rules and multisample positions, clamped to the
  /// frame; empty if no point was added.
  PixelRegion box() const;

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
