#include "render/surface.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace bookspin::render {

namespace {

// Scaling by the largest component first keeps huge (1e38) coordinates from overflowing.
Eigen::Vector3d safe_unit(const Eigen::Vector3d& v) {
  const double scale = v.cwiseAbs().maxCoeff();
  if (!(scale > 0.0) || !std::isfinite(scale)) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d scaled = v / scale;
  return scaled / scaled.norm();
}

Eigen::Vector3d doubled_area_normal(const Eigen::Matrix3Xd& positions,
                                    const Eigen::Matrix3Xi& triangles, Eigen::Index t) {
  const Eigen::Vector3d a = positions.col(triangles(0, t));
  const Eigen::Vector3d b = positions.col(triangles(1, t));
  const Eigen::Vector3d c = positions.col(triangles(2, t));
  return (b - a).cross(c - a);
}

}  // namespace

int validate_topology(const SurfaceTopology& topology) {
  const Eigen::Index n = topology.triangles.cols();
  if (n == 0) throw std::invalid_argument("surface topology: no triangles");
  if (topology.face_colours.cols() != n)
    throw std::invalid_argument("surface topology: " + std::to_string(n) + " triangles but " +
                                std::to_string(topology.face_colours.cols()) + " face colours");
  if (topology.triangles.minCoeff() < 0)
    throw std::invalid_argument("surface topology: negative vertex index");
  const bool colours_ok = topology.face_colours.allFinite() &&
                          topology.face_colours.minCoeff() >= 0.0f &&
                          topology.face_colours.maxCoeff() <= 1.0f;
  if (!colours_ok)
    throw std::invalid_argument("surface topology: face colours must be finite, in [0, 1]");
  return topology.triangles.maxCoeff() + 1;
}

Eigen::Matrix3Xf face_normals(const Eigen::Matrix3Xd& positions,
                              const Eigen::Matrix3Xi& triangles) {
  Eigen::Matrix3Xf normals(3, triangles.cols());
  for (Eigen::Index t = 0; t < triangles.cols(); ++t)
    normals.col(t) = safe_unit(doubled_area_normal(positions, triangles, t)).cast<float>();
  return normals;
}

Eigen::Matrix3Xf vertex_normals(const Eigen::Matrix3Xd& positions,
                                const Eigen::Matrix3Xi& triangles) {
  Eigen::Matrix3Xd sums = Eigen::Matrix3Xd::Zero(3, positions.cols());
  for (Eigen::Index t = 0; t < triangles.cols(); ++t) {
    const Eigen::Vector3d n = doubled_area_normal(positions, triangles, t);
    for (int k = 0; k < 3; ++k) sums.col(triangles(k, t)) += n;
  }
  Eigen::Matrix3Xf normals(3, positions.cols());
  for (Eigen::Index v = 0; v < positions.cols(); ++v)
    normals.col(v) = safe_unit(sums.col(v)).cast<float>();
  return normals;
}

bool positions_drawable(const Eigen::Matrix3Xd& positions) {
  for (Eigen::Index i = 0; i < positions.size(); ++i) {
    if (!std::isfinite(static_cast<float>(positions(i)))) return false;
  }
  return true;
}

}  // namespace bookspin::render
