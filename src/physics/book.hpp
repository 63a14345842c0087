#pragma once
// Book geometry: size, mass, corners and inertia (docs/physics.md §1).
#include <Eigen/Dense>
#include <optional>

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

/// The book of mass `mass` (> 0) whose principal moments about body x, y, z are `moments`
/// (mass·length²): the inverse of Book::principal_moments(), a² = 6(I_y + I_z − I_x)/M,
/// b² = 6(I_x + I_z − I_y)/M, c² = 6(I_x + I_y − I_z)/M. nullopt where a side would not be
/// positive and finite: moments that break the triangle inequality (I_x + I_y > I_z and its
/// turns, which every real body's moments keep) have no such box. docs/physics.md §1.
std::optional<Book> book_with_moments(const Eigen::Vector3d& moments, double mass);

}  // namespace bookspin::physics
