#pragma once
// Closed triangle meshes for the lattice tests: a box, a cylinder and a T made of two boxes,
// and the move into the principal frame (docs/physics.md §11, §13).
#include <Eigen/Core>
#include <cmath>
#include <vector>

#include "physics/mass_properties.hpp"

namespace bookspin::physics::testing {

struct Surface {
  Eigen::Matrix3Xd vertices;
  Eigen::Matrix3Xi triangles;
};

/// The box [lo, hi] wound outward; vertex p at lo + (hi − lo)·bits(p) (bit 0 = x), the
/// numbering of Book::body_corners().
inline Surface box_surface(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  Surface s;
  s.vertices.resize(3, 8);
  for (int p = 0; p < 8; ++p)
    for (int d = 0; d < 3; ++d) s.vertices(d, p) = ((p >> d) & 1) ? hi[d] : lo[d];
  s.triangles.resize(3, 12);
  s.triangles << 0, 0, 1, 1, 0, 0, 2, 2, 0, 0, 4, 4,  //
      4, 6, 3, 7, 1, 5, 6, 7, 2, 3, 5, 7,             //
      6, 2, 7, 5, 5, 4, 7, 3, 3, 1, 7, 6;
  return s;
}

/// Both surfaces as one mesh of two shells.
inline Surface join(const Surface& a, const Surface& b) {
  Surface s;
  s.vertices.resize(3, a.vertices.cols() + b.vertices.cols());
  s.vertices << a.vertices, b.vertices;
  s.triangles.resize(3, a.triangles.cols() + b.triangles.cols());
  s.triangles << a.triangles, (b.triangles.array() + static_cast<int>(a.vertices.cols())).matrix();
  return s;
}

/// A closed prism of `segments` sides around the z axis, radius r, z in [0, height].
inline Surface cylinder_surface(double r, double height, int segments) {
  Surface s;
  s.vertices.resize(3, 2 + 2 * segments);
  s.vertices.col(0) << 0, 0, 0;
  s.vertices.col(1) << 0, 0, height;
  for (int i = 0; i < segments; ++i) {
    const double a = 2.0 * M_PI * i / segments;
    s.vertices.col(2 + i) << r * std::cos(a), r * std::sin(a), 0.0;
    s.vertices.col(2 + segments + i) << r * std::cos(a), r * std::sin(a), height;
  }
  s.triangles.resize(3, 4 * segments);
  for (int i = 0; i < segments; ++i) {
    const int b0 = 2 + i, b1 = 2 + (i + 1) % segments, t0 = b0 + segments, t1 = b1 + segments;
    s.triangles.col(4 * i) << 0, b1, b0;
    s.triangles.col(4 * i + 1) << 1, t0, t1;
    s.triangles.col(4 * i + 2) << b0, b1, t1;
    s.triangles.col(4 * i + 3) << b0, t1, t0;
  }
  return s;
}

/// A T-handle: a bar 4 × 0.6 × 0.6 along x and a stem 0.6 × 2 × 0.6 along y on its middle,
/// two shells that touch.
inline Surface t_surface() {
  return join(box_surface({-2.0, -0.3, -0.3}, {2.0, 0.3, 0.3}),
              box_surface({-0.3, 0.3, -0.3}, {0.3, 2.3, 0.3}));
}

/// The same surface in its principal frame (centre of mass at the origin, x, y, z along the
/// principal axes of ascending moment); `props` gets its mass properties at mass `mass`.
inline Surface principal(const Surface& s, double mass, MassProperties& props) {
  const MassPropertiesResult r = mass_properties(s.vertices, s.triangles);
  props = with_mass(r.properties, mass);
  Surface out = s;
  out.vertices = props.principal_axes * (s.vertices.colwise() - props.center_of_mass);
  return out;
}

}  // namespace bookspin::physics::testing
