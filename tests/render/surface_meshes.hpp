#pragma once
// Generated triangle surfaces for the render tests: a box on 8 corners, a torus, a T-shape.
#include <Eigen/Dense>
#include <cmath>
#include <memory>
#include <utility>

#include "render/surface.hpp"

namespace bookspin::render::testing {

struct TestMesh {
  Eigen::Matrix3Xd positions;  ///< 3×V
  Eigen::Matrix3Xi triangles;  ///< 3×N, counter-clockwise seen from outside
};

/// The 12 triangles of a box whose 8 vertices are corners 0…7 (docs/physics.md §1
/// numbering), counter-clockwise seen from outside: faces −x, +x, −y, +y, −z, +z, two
/// triangles each, in that order.
inline Eigen::Matrix3Xi box_triangles() {
  Eigen::Matrix3Xi triangles(3, 12);
  int t = 0;
  for (int d = 0; d < 3; ++d) {
    const int u = (d + 1) % 3, v = (d + 2) % 3;  // e_u × e_v = e_d
    for (int side = 0; side < 2; ++side) {
      int quad[4];
      const int uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      for (int k = 0; k < 4; ++k) quad[k] = (side << d) | (uv[k][0] << u) | (uv[k][1] << v);
      if (side == 0) std::swap(quad[1], quad[3]);  // −d: the reverse turn
      triangles.col(t++) << quad[0], quad[1], quad[2];
      triangles.col(t++) << quad[0], quad[2], quad[3];
    }
  }
  return triangles;
}

/// A torus about z: major radius `major`, tube radius `minor`, nu × nv quads (2·nu·nv
/// triangles), centred at the origin.
inline TestMesh torus(double major, double minor, int nu, int nv) {
  TestMesh mesh;
  mesh.positions.resize(3, nu * nv);
  const double two_pi = 2.0 * 3.14159265358979323846;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const double u = two_pi * i / nu, v = two_pi * j / nv;
      mesh.positions.col(i * nv + j) << (major + minor * std::cos(v)) * std::cos(u),
          (major + minor * std::cos(v)) * std::sin(u), minor * std::sin(v);
    }
  }
  mesh.triangles.resize(3, 2 * nu * nv);
  int t = 0;
  for (int i = 0; i < nu; ++i) {
    for (int j = 0; j < nv; ++j) {
      const int a = i * nv + j, b = ((i + 1) % nu) * nv + j;
      const int c = ((i + 1) % nu) * nv + (j + 1) % nv, d = i * nv + (j + 1) % nv;
      mesh.triangles.col(t++) << a, b, c;
      mesh.triangles.col(t++) << a, c, d;
    }
  }
  return mesh;
}

/// Corners (3×8, §1 numbering) of an axis-aligned box from `low` to `high`.
inline Eigen::Matrix<double, 3, 8> aligned_box(const Eigen::Vector3d& low,
                                               const Eigen::Vector3d& high) {
  Eigen::Matrix<double, 3, 8> corners;
  for (int p = 0; p < 8; ++p) {
    for (int d = 0; d < 3; ++d) corners(d, p) = ((p >> d) & 1) ? high(d) : low(d);
  }
  return corners;
}

/// A T-handle of two boxes (a bar along x on top of a stem along y), 24 triangles.
inline TestMesh t_shape() {
  TestMesh mesh;
  mesh.positions.resize(3, 16);
  mesh.positions.leftCols<8>() = aligned_box({-1.2, 0.3, -0.2}, {1.2, 0.7, 0.2});
  mesh.positions.rightCols<8>() = aligned_box({-0.18, -1.2, -0.18}, {0.18, 0.3, 0.18});
  mesh.triangles.resize(3, 24);
  mesh.triangles.leftCols<12>() = box_triangles();
  mesh.triangles.rightCols<12>() = box_triangles().array() + 8;
  return mesh;
}

/// A topology of `triangles` coloured by `colour(t)` (linear RGB).
template <typename Colour>
std::shared_ptr<const SurfaceTopology> topology_of(const Eigen::Matrix3Xi& triangles, Colour colour,
                                                   bool smooth = false) {
  auto topology = std::make_shared<SurfaceTopology>();
  topology->triangles = triangles;
  topology->face_colours.resize(3, triangles.cols());
  for (Eigen::Index t = 0; t < triangles.cols(); ++t)
    topology->face_colours.col(t) = colour(static_cast<int>(t));
  topology->smooth = smooth;
  return topology;
}

}  // namespace bookspin::render::testing
