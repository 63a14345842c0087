#pragma once
// Book geometry: size, mass, corners and inertia (docs/physics.md §1).
#include <Eigen/Dense>

namespace bookspin::physics {

/// The 8 corners of the book as columns (3×8). Corner p has coordinate
/// -size/2 + size·bit(p, d) on axis d (bit 0 = x, bit 1 = y, bit 2 = z).
using Corners = Eigen::Matrix<double, 3, 8>;

/// A solid cuboid book, centre of mass at the origin of its body frame.
/// Body axes: x spine→fore-edge (length a), y height (b), z thickness (c).
struct Book {
  Eigen::Vector3d size{1.878, 2.9085, 0.5};  ///< (a, b, c), length units
  double mass = 8.0;                         ///< M, mass units

  /// Corners in the body frame (3×8), numbering of docs/physics.md §1.
  Corners body_corners() const;
  /// Solid-cuboid inertia, body frame (3×3, diagonal):
  /// I_body = (M/12)·diag(b²+c², a²+c², a²+b²). Source: any mechanics textbook, paper §4.
  Eigen::Matrix3d inertia_body() const;
  /// Diagonal of inertia_body() (principal moments I_x, I_y, I_z).
  Eigen::Vector3d principal_moments() const;
};

}  // namespace bookspin::physics
