#include "clip/body_drawing.hpp"

#include <cmath>
#include <stdexcept>

namespace bookspin::clip {

namespace {

bool bit(int p, int d) { return ((p >> d) & 1) != 0; }

/// Throws unless corner p = corner 0 + size ∘ bits(p) for size = corner 7 − corner 0 > 0.
void check_box(const Eigen::Matrix<double, 3, 8>& rest, const Eigen::Vector3d& size) {
  if (!rest.allFinite() || !(size.minCoeff() > 0.0))
    throw std::invalid_argument(
        "trilinear_deform: rest corners must be finite with corner 7 > corner 0 on every axis");
  for (int p = 0; p < 8; ++p) {
    for (int d = 0; d < 3; ++d) {
      const double expected = rest(d, 0) + (bit(p, d) ? size(d) : 0.0);
      if (std::abs(rest(d, p) - expected) > 1e-9 * size(d))
        throw std::invalid_argument(
            "trilinear_deform: rest corners are not an axis-aligned box numbered as "
            "docs/physics.md §1");
    }
  }
}

}  // namespace

Eigen::Matrix3Xd trilinear_deform(const Eigen::Matrix<double, 3, 8>& rest_corners,
                                  const Eigen::Matrix<double, 3, 8>& world_corners,
                                  const Eigen::Matrix3Xd& rest_vertices) {
  const Eigen::Vector3d origin = rest_corners.col(0);
  const Eigen::Vector3d size = rest_corners.col(7) - origin;
  check_box(rest_corners, size);
  Eigen::Matrix3Xd world(3, rest_vertices.cols());
  for (Eigen::Index v = 0; v < rest_vertices.cols(); ++v) {
    const Eigen::Vector3d t = (rest_vertices.col(v) - origin).cwiseQuotient(size);
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (int p = 0; p < 8; ++p) {
      double weight = 1.0;
      for (int d = 0; d < 3; ++d) weight *= bit(p, d) ? t(d) : 1.0 - t(d);
      sum += weight * world_corners.col(p);
    }
    world.col(v) = sum;
  }
  return world;
}

}  // namespace bookspin::clip
