#pragma once
// CPU side of the markers (3D, drawn by GL; "overlay" is the 2D drawing on frames): the
// angular-momentum arrow and the body axes, as lit solids (thin tubes with cone tips) rather than
// GL lines, whose width core profiles may not honour.
#include <Eigen/Dense>
#include <array>
#include <vector>

namespace bookspin::render {

struct MarkerVertex {
  std::array<float, 3> position;  ///< world
  std::array<float, 3> normal;    ///< world, unit
  std::array<float, 3> color;     ///< sRGB, 0..1
};

/// A tube from `from` to `to` (world) ending in a cone of length head_length (0 = none).
void append_arrow(std::vector<MarkerVertex>& out, const Eigen::Vector3d& from,
                  const Eigen::Vector3d& to, double radius, double head_length,
                  const Eigen::Vector3f& color);

/// The markers for one frame. corners: 3×8 world (docs/physics.md §1); an axis d runs from the
/// centroid along the mean of the four corner edges along d (corner1 − corner0 for x, …),
/// sticking out of the book. The yellow L arrow starts at the origin along
/// angular_momentum_direction (skipped if zero or non-finite). Axes are skipped if the
/// corners are not drawable.
std::vector<MarkerVertex> build_markers(const Eigen::Matrix<double, 3, 8>& corners,
                                        const Eigen::Vector3d& angular_momentum_direction,
                                        bool show_angular_momentum, bool show_body_axes);

}  // namespace bookspin::render
