#pragma once
// CPU side of the book: triangles built from the 8 world-space corners every frame.
#include <Eigen/Dense>
#include <array>
#include <vector>

namespace bookspin::render {

/// One vertex as uploaded to GL (interleaved, tightly packed floats).
struct BookVertex {
  std::array<float, 3> position;  ///< world
  std::array<float, 3> normal;    ///< world, unit, the face's outward normal
  std::array<float, 2> uv;        ///< texture coordinates, v = 0 at the image's top row
};

/// Vertices per face: 4 triangles fanned around the face centre, so a non-planar
/// (stretched, exploded) quad is drawn symmetrically instead of split along one diagonal.
inline constexpr int vertices_per_face = 12;

/// The book as 6 faces × vertices_per_face vertices, in book_faces order.
/// corners: 3×8, world, column p = corner p (docs/physics.md §1 numbering). Drawn exactly as
/// given (no re-orthonormalization). Normals: cross product of the face diagonals, turned to
/// point away from the centroid of the 8 corners. Returns an empty vector when a corner is
/// not finite in single precision (a diverged book is not drawn).
std::vector<BookVertex> build_book_mesh(const Eigen::Matrix<double, 3, 8>& corners);

/// The outward unit normal of face `face` (index into book_faces) for the given corners
/// (3×8, world); falls back to centroid→face-centre if the diagonals are degenerate.
Eigen::Vector3d face_normal(const Eigen::Matrix<double, 3, 8>& corners, int face);

/// True if every corner is finite once converted to float (what GL will see).
bool corners_drawable(const Eigen::Matrix<double, 3, 8>& corners);

}  // namespace bookspin::render
