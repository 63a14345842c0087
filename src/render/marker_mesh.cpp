#include "render/marker_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/book_mesh.hpp"

namespace bookspin::render {

namespace {

constexpr int tube_segments = 16;

std::array<float, 3> to_float(const Eigen::Vector3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

// Two unit vectors perpendicular to `axis` (unit) and to each other.
std::pair<Eigen::Vector3d, Eigen::Vector3d> perpendiculars(const Eigen::Vector3d& axis) {
  const Eigen::Vector3d helper =
      std::abs(axis.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d u = axis.cross(helper).normalized();
  return {u, axis.cross(u)};
}

void push(std::vector<MarkerVertex>& out, const Eigen::Vector3d& p, const Eigen::Vector3d& n,
          const Eigen::Vector3f& color) {
  out.push_back({to_float(p), to_float(n), {color.x(), color.y(), color.z()}});
}

// A ring of quads from radius r0 at a to radius r1 at b (a cylinder or, with r1 = 0, a cone).
void append_frustum(std::vector<MarkerVertex>& out, const Eigen::Vector3d& a,
                    const Eigen::Vector3d& b, double r0, double r1, const Eigen::Vector3f& color) {
  const Eigen::Vector3d axis = (b - a).normalized();
  const auto [u, w] = perpendiculars(axis);
  const double slope = (r0 - r1) / (b - a).norm();  // tilts the cone's normals forward
  for (int i = 0; i < tube_segments; ++i) {
    const double t0 = 2.0 * std::numbers::pi * i / tube_segments;
    const double t1 = 2.0 * std::numbers::pi * (i + 1) / tube_segments;
    const Eigen::Vector3d d0 = std::cos(t0) * u + std::sin(t0) * w;
    const Eigen::Vector3d d1 = std::cos(t1) * u + std::sin(t1) * w;
    const Eigen::Vector3d n0 = (d0 + slope * axis).normalized();
    const Eigen::Vector3d n1 = (d1 + slope * axis).normalized();
    push(out, a + r0 * d0, n0, color);
    push(out, a + r0 * d1, n1, color);
    push(out, b + r1 * d1, n1, color);
    push(out, a + r0 * d0, n0, color);
    push(out, b + r1 * d1, n1, color);
    push(out, b + r1 * d0, n0, color);
  }
}

Eigen::Vector3d edge_direction(const Eigen::Matrix<double, 3, 8>& corners, int axis) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  const int bit = 1 << axis;
  for (int p = 0; p < 8; ++p) {
    if ((p & bit) == 0) sum += corners.col(p | bit) - corners.col(p);
  }
  return sum / 4.0;
}

double half_diagonal(const Eigen::Matrix<double, 3, 8>& corners) {
  const Eigen::Vector3d centroid = corners.rowwise().mean();
  return (corners.colwise() - centroid).colwise().norm().maxCoeff();
}

void append_body_axes(std::vector<MarkerVertex>& out, const Eigen::Matrix<double, 3, 8>& corners) {
  const Eigen::Vector3d centre = corners.rowwise().mean();
  const double scale = half_diagonal(corners);
  const Eigen::Vector3f colors[3] = {
      {0.95f, 0.22f, 0.20f}, {0.25f, 0.85f, 0.30f}, {0.25f, 0.45f, 1.0f}};
  for (int d = 0; d < 3; ++d) {
    const Eigen::Vector3d edge = edge_direction(corners, d);
    if (!(edge.norm() > 0.0) || !edge.allFinite()) continue;
    // Half the book's extent plus a margin, so every axis sticks out of the book.
    const double length = 0.5 * edge.norm() + 0.3 * scale;
    append_arrow(out, centre, centre + edge.normalized() * length, 0.012 * scale, 0.07 * scale,
                 colors[d]);
  }
}

}  // namespace

void append_arrow(std::vector<MarkerVertex>& out, const Eigen::Vector3d& from,
                  const Eigen::Vector3d& to, double radius, double head_length,
                  const Eigen::Vector3f& color) {
  const double length = (to - from).norm();
  if (!(length > 0.0) || !std::isfinite(length)) return;
  const Eigen::Vector3d axis = (to - from) / length;
  const double head = std::min(head_length, 0.5 * length);
  const Eigen::Vector3d neck = to - axis * head;
  append_frustum(out, from, neck, radius, radius, color);
  if (head > 0.0) {
    append_frustum(out, neck, neck + axis * 1e-6 * length, radius, 2.6 * radius, color);  // collar
    append_frustum(out, neck, to, 2.6 * radius, 0.0, color);
  }
}

std::vector<MarkerVertex> build_markers(const Eigen::Matrix<double, 3, 8>& corners,
                                        const Eigen::Vector3d& angular_momentum_direction,
                                        bool show_angular_momentum, bool show_body_axes) {
  std::vector<MarkerVertex> out;
  const bool drawable = corners_drawable(corners);
  const double scale = drawable ? half_diagonal(corners) : 0.0;
  if (show_body_axes && drawable && scale > 0.0) append_body_axes(out, corners);
  const Eigen::Vector3d l = angular_momentum_direction;
  if (show_angular_momentum && l.allFinite() && l.norm() > 0.0) {
    // Sized by the book when there is one, so it reads as "the same picture" at any scale.
    const double length = scale > 0.0 && std::isfinite(scale) ? 1.3 * scale : 2.2;
    append_arrow(out, Eigen::Vector3d::Zero(), l.normalized() * length, 0.022 * length / 1.3,
                 0.14 * length, {1.0f, 0.85f, 0.15f});
  }
  return out;
}

}  // namespace bookspin::render
