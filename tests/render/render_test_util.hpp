#pragma once
// Helpers shared by the render tests: book corners, pixel statistics.
#include <Eigen/Dense>
#include <cmath>
#include <cstdint>

#include "common/rgba_image.hpp"

namespace bookspin::render::testing {

/// Corners (3×8, docs/physics.md §1 numbering) of an a×b×c box, rotated by R, moved by t.
inline Eigen::Matrix<double, 3, 8> box_corners(
    const Eigen::Vector3d& size, const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity(),
    const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
  Eigen::Matrix<double, 3, 8> corners;
  for (int p = 0; p < 8; ++p) {
    Eigen::Vector3d body;
    for (int d = 0; d < 3; ++d) body(d) = -size(d) / 2 + size(d) * ((p >> d) & 1);
    corners.col(p) = rotation * body + offset;
  }
  return corners;
}

inline Eigen::Matrix<double, 3, 8> default_book(
    const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity(),
    const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
  return box_corners({1.878, 2.9085, 0.5}, rotation, offset);
}

inline Eigen::Vector3d pixel(const RgbaImage& image, int x, int y) {
  const std::uint8_t* p = image.row(y) + 4 * x;
  return {double(p[0]), double(p[1]), double(p[2])};
}

/// Pixels that differ from a background-only image by more than `threshold` (sum of |ΔRGB|).
struct Mask {
  int count = 0;
  int min_x = 1 << 30, min_y = 1 << 30, max_x = -1, max_y = -1;
  double sum_x = 0, sum_y = 0;
  Eigen::Vector3d mean_color = Eigen::Vector3d::Zero();
  double centre_x() const { return 0.5 * (min_x + max_x); }
  double centre_y() const { return 0.5 * (min_y + max_y); }
  double centroid_x() const { return sum_x / count; }
  double width() const { return max_x - min_x + 1; }
  double height() const { return max_y - min_y + 1; }
};

inline Mask difference_mask(const RgbaImage& image, const RgbaImage& background,
                            double threshold = 24) {
  Mask mask;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const Eigen::Vector3d c = pixel(image, x, y);
      if ((c - pixel(background, x, y)).cwiseAbs().sum() <= threshold) continue;
      ++mask.count;
      mask.min_x = std::min(mask.min_x, x);
      mask.max_x = std::max(mask.max_x, x);
      mask.min_y = std::min(mask.min_y, y);
      mask.max_y = std::max(mask.max_y, y);
      mask.sum_x += x;
      mask.sum_y += y;
      mask.mean_color += c;
    }
  }
  if (mask.count > 0) mask.mean_color /= mask.count;
  return mask;
}

}  // namespace bookspin::render::testing
