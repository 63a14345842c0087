#include "render/pixel_box.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bookspin::render {

namespace {

// GL rasterizes in single precision and places MSAA samples inside the pixel; two pixels
// of slack cover both with room to spare.
constexpr double kMarginPixels = 2.0;

}  // namespace

ScreenBounds::ScreenBounds(const Eigen::Matrix4f& view_projection, int width, int height)
    : view_projection_(view_projection.cast<double>()),
      width_(width),
      height_(height),
      min_x_(std::numeric_limits<double>::infinity()),
      min_y_(std::numeric_limits<double>::infinity()),
      max_x_(-std::numeric_limits<double>::infinity()),
      max_y_(-std::numeric_limits<double>::infinity()) {}

void ScreenBounds::add(const std::array<float, 3>& world) {
  const Eigen::Vector4d clip =
      view_projection_ * Eigen::Vector4d(world[0], world[1], world[2], 1.0);
  // In front of the near plane means z ≥ −w with w > 0; anything else gets clipped.
  if (!(clip.w() > 0.0) || !(clip.z() >= -clip.w()) || !clip.allFinite()) {
    whole_ = true;
    return;
  }
  const double x = (clip.x() / clip.w() + 1.0) * 0.5 * width_;
  const double y = (clip.y() / clip.w() + 1.0) * 0.5 * height_;
  min_x_ = std::min(min_x_, x);
  min_y_ = std::min(min_y_, y);
  max_x_ = std::max(max_x_, x);
  max_y_ = std::max(max_y_, y);
}

PixelRegion ScreenBounds::box() const {
  if (whole_) return whole_frame(width_, height_);
  if (min_x_ > max_x_) return {};
  auto clamp = [](double v, int hi) {
    return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(hi)));
  };
  const int x0 = clamp(std::floor(min_x_ - kMarginPixels), width_);
  const int y0 = clamp(std::floor(min_y_ - kMarginPixels), height_);
  const int x1 = clamp(std::ceil(max_x_ + kMarginPixels), width_);
  const int y1 = clamp(std::ceil(max_y_ + kMarginPixels), height_);
  return {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
}

}  // namespace bookspin::render
