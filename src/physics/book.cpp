#include "physics/book.hpp"

namespace bookspin::physics {

Corners Book::body_corners() const {
  Corners corners;
  for (int p = 0; p < 8; ++p) {
    for (int d = 0; d < 3; ++d) {
      const double bit = (p >> d) & 1;
      corners(d, p) = -0.5 * size[d] + size[d] * bit;
    }
  }
  return corners;
}

Eigen::Vector3d Book::principal_moments() const {
  const double a2 = size.x() * size.x(), b2 = size.y() * size.y(), c2 = size.z() * size.z();
  return (mass / 12.0) * Eigen::Vector3d(b2 + c2, a2 + c2, a2 + b2);
}

Eigen::Matrix3d Book::inertia_body() const { return principal_moments().asDiagonal(); }

std::optional<Book> book_with_moments(const Eigen::Vector3d& moments, double mass) {
  const double x = moments.x(), y = moments.y(), z = moments.z();
  const Eigen::Vector3d squares = (6.0 / mass) * Eigen::Vector3d(y + z - x, x + z - y, x + y - z);
  if (!(mass > 0.0) || !squares.allFinite() || !(squares.minCoeff() > 0.0)) return std::nullopt;
  Book book;
  book.size = squares.cwiseSqrt();
  book.mass = mass;
  return book;
}

}  // namespace bookspin::physics
