// The face mapping and the CPU mesh (no GL needed).
#include "render/book_faces.hpp"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "render/book_mesh.hpp"
#include "render_test_util.hpp"

namespace bookspin::render {
namespace {

using testing::box_corners;
using testing::default_book;

Eigen::Vector3d axis_vector(const FaceSpec& face) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  n(face.axis) = face.sign;
  return n;
}

TEST(BookFaces, MatchPhysicsDocSection1) {
  const std::pair<const char*, Eigen::Vector3d> expected[] = {
      {"front", {0, 0, 1}},      {"back", {0, 0, -1}}, {"spine", {1, 0, 0}},
      {"fore-edge", {-1, 0, 0}}, {"top", {0, 1, 0}},   {"bottom", {0, -1, 0}}};
  for (const auto& [name, normal] : expected) {
    bool found = false;
    for (const FaceSpec& face : book_faces) {
      if (std::string(face.name) != name) continue;
      found = true;
      EXPECT_EQ(axis_vector(face), normal) << name;
    }
    EXPECT_TRUE(found) << name;
  }
  EXPECT_EQ(book_faces[0].image, FaceImage::front);
  EXPECT_EQ(book_faces[1].image, FaceImage::back);
  EXPECT_EQ(book_faces[2].image, FaceImage::spine);
}

TEST(BookFaces, CornersLieOnTheirFaceAndAreDistinct) {
  for (const FaceSpec& face : book_faces) {
    std::set<int> distinct(face.corners.begin(), face.corners.end());
    EXPECT_EQ(distinct.size(), 4u) << face.name;
    for (int p : face.corners) EXPECT_EQ((p >> face.axis) & 1, face.sign > 0 ? 1 : 0) << face.name;
  }
}

// Texture right × texture down points into the book exactly when the image is not mirrored
// as seen from outside.
TEST(BookFaces, ImagesAreNotMirroredSeenFromOutside) {
  const Eigen::Matrix<double, 3, 8> c = box_corners({1, 1, 1});
  for (const FaceSpec& face : book_faces) {
    const Eigen::Vector3d tl = c.col(face.corners[0]), tr = c.col(face.corners[1]),
                          bl = c.col(face.corners[3]);
    EXPECT_LT((tr - tl).cross(bl - tl).dot(axis_vector(face)), 0.0) << face.name;
  }
}

TEST(BookFaces, FrontTitleIsUprightSeenFromPlusZ) {
  const Eigen::Matrix<double, 3, 8> c = box_corners({1, 1, 1});
  const FaceSpec& front = book_faces[0];
  // Image top edge at +y, image left edge at −x (left as seen from +z with +y up).
  EXPECT_GT(c(1, front.corners[0]), 0.0);
  EXPECT_GT(c(1, front.corners[1]), 0.0);
  EXPECT_LT(c(0, front.corners[0]), 0.0);
  EXPECT_GT(c(0, front.corners[1]), 0.0);
}

TEST(BookFaces, SpineTextRunsAlongY) {
  const Eigen::Matrix<double, 3, 8> c = box_corners({1, 1, 1});
  const FaceSpec& spine = book_faces[2];
  const Eigen::Vector3d along = c.col(spine.corners[1]) - c.col(spine.corners[0]);
  EXPECT_EQ(along, Eigen::Vector3d(0, 1, 0));
}

TEST(BookMesh, HasTwelveVerticesPerFaceWithCentreFan) {
  const auto mesh = build_book_mesh(default_book());
  ASSERT_EQ(mesh.size(), book_faces.size() * vertices_per_face);
  for (std::size_t v = 0; v < mesh.size(); v += 3) {
    EXPECT_FLOAT_EQ(mesh[v].uv[0], 0.5f);
    EXPECT_FLOAT_EQ(mesh[v].uv[1], 0.5f);
  }
}

void expect_outward_normals(const Eigen::Matrix<double, 3, 8>& corners, const char* what) {
  const Eigen::Vector3d centroid = corners.rowwise().mean();
  for (int f = 0; f < 6; ++f) {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int p : book_faces[f].corners) centre += corners.col(p) / 4.0;
    const Eigen::Vector3d n = face_normal(corners, f);
    EXPECT_NEAR(n.norm(), 1.0, 1e-9) << what << " face " << f;
    EXPECT_GT(n.dot(centre - centroid), 0.0) << what << " face " << book_faces[f].name;
  }
}

TEST(BookMesh, NormalsPointOutwardForRotatedStretchedAndMirroredBooks) {
  const Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(1.1, Eigen::Vector3d(0.3, -1, 0.5).normalized()).toRotationMatrix();
  expect_outward_normals(default_book(), "identity");
  expect_outward_normals(default_book(rotation), "rotated");
  Eigen::Matrix3d stretch;
  stretch << 1.6, 0.5, 0, -0.3, 0.7, 0.2, 0.2, 0, 1.9;
  expect_outward_normals(default_book(stretch), "stretched");
  expect_outward_normals(default_book(Eigen::Vector3d(-1, 1, 1).asDiagonal()), "mirrored");
  expect_outward_normals(default_book(rotation * 1e30), "huge");
}

TEST(BookMesh, IdentityNormalsAreTheAxes) {
  for (int f = 0; f < 6; ++f) {
    EXPECT_TRUE(face_normal(default_book(), f).isApprox(axis_vector(book_faces[f]), 1e-12))
        << book_faces[f].name;
  }
}

TEST(BookMesh, NonFiniteCornersGiveNoMesh) {
  Eigen::Matrix<double, 3, 8> corners = default_book();
  corners(2, 5) = std::nan("");
  EXPECT_TRUE(build_book_mesh(corners).empty());
  corners(2, 5) = 1e300;  // finite as a double, infinite as the float GL would see
  EXPECT_TRUE(build_book_mesh(corners).empty());
  corners(2, 5) = -std::numeric_limits<double>::infinity();
  EXPECT_TRUE(build_book_mesh(corners).empty());
}

TEST(BookMesh, HugeButFiniteCornersGiveFiniteVertices) {
  for (const BookVertex& v : build_book_mesh(default_book() * 1e30)) {
    for (float x : v.position) EXPECT_TRUE(std::isfinite(x));
    for (float x : v.normal) EXPECT_TRUE(std::isfinite(x));
  }
}

TEST(BookMesh, CollapsedBookStillGetsUnitNormals) {
  const Eigen::Matrix<double, 3, 8> flat = box_corners({1, 1, 0});  // zero thickness
  for (const BookVertex& v : build_book_mesh(flat)) {
    const Eigen::Vector3f n(v.normal[0], v.normal[1], v.normal[2]);
    EXPECT_NEAR(n.norm(), 1.0f, 1e-5f);
  }
}

}  // namespace
}  // namespace bookspin::render
