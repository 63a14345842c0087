#include "render/book_mesh.hpp"

#include <cmath>

#include "render/book_faces.hpp"

namespace bookspin::render {

namespace {

Eigen::Vector3d corner(const Eigen::Matrix<double, 3, 8>& corners, const FaceSpec& face, int k) {
  return corners.col(face.corners[static_cast<std::size_t>(k)]);
}

Eigen::Vector3d face_centre(const Eigen::Matrix<double, 3, 8>& corners, const FaceSpec& face) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k) sum += corner(corners, face, k);
  return sum / 4.0;
}

// Normalizing before the cross product keeps huge (1e200) corners from overflowing.
Eigen::Vector3d safe_unit(const Eigen::Vector3d& v) {
  const double scale = v.cwiseAbs().maxCoeff();
  if (!(scale > 0.0) || !std::isfinite(scale)) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d scaled = v / scale;
  return scaled / scaled.norm();
}

BookVertex make_vertex(const Eigen::Vector3d& p, const Eigen::Vector3d& n, float u, float v) {
  return BookVertex{
      {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())},
      {static_cast<float>(n.x()), static_cast<float>(n.y()), static_cast<float>(n.z())},
      {u, v}};
}

void append_face(const Eigen::Matrix<double, 3, 8>& corners, int face_index,
                 std::vector<BookVertex>& out) {
  const FaceSpec& face = book_faces[static_cast<std::size_t>(face_index)];
  const Eigen::Vector3d n = face_normal(corners, face_index);
  const Eigen::Vector3d centre = face_centre(corners, face);
  for (int k = 0; k < 4; ++k) {
    const int next = (k + 1) % 4;
    const auto& uv0 = face_corner_uv[static_cast<std::size_t>(k)];
    const auto& uv1 = face_corner_uv[static_cast<std::size_t>(next)];
    out.push_back(make_vertex(centre, n, 0.5f, 0.5f));
    out.push_back(make_vertex(corner(corners, face, k), n, uv0[0], uv0[1]));
    out.push_back(make_vertex(corner(corners, face, next), n, uv1[0], uv1[1]));
  }
}

}  // namespace

bool corners_drawable(const Eigen::Matrix<double, 3, 8>& corners) {
  for (int i = 0; i < corners.size(); ++i) {
    if (!std::isfinite(static_cast<float>(corners(i)))) return false;
  }
  return true;
}

Eigen::Vector3d face_normal(const Eigen::Matrix<double, 3, 8>& corners, int face_index) {
  const FaceSpec& face = book_faces[static_cast<std::size_t>(face_index)];
  const Eigen::Vector3d d1 = safe_unit(corner(corners, face, 2) - corner(corners, face, 0));
  const Eigen::Vector3d d2 = safe_unit(corner(corners, face, 3) - corner(corners, face, 1));
  const Eigen::Vector3d centroid = corners.rowwise().mean();
  const Eigen::Vector3d outward = safe_unit(face_centre(corners, face) - centroid);
  Eigen::Vector3d n = safe_unit(d1.cross(d2));
  if (n.isZero()) n = outward;  // collapsed face: the best guess is "away from the middle"
  if (n.dot(outward) < 0.0) n = -n;
  return n;
}

std::vector<BookVertex> build_book_mesh(const Eigen::Matrix<double, 3, 8>& corners) {
  std::vector<BookVertex> vertices;
  if (!corners_drawable(corners)) return vertices;
  vertices.reserve(book_faces.size() * vertices_per_face);
  for (int f = 0; f < static_cast<int>(book_faces.size()); ++f) append_face(corners, f, vertices);
  return vertices;
}

}  // namespace bookspin::render
