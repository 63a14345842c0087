// trilinear_deform: the rest surface carried by the box's 8 corners.
#include "clip/body_drawing.hpp"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

namespace bookspin::clip {
namespace {

/// Corners (3×8, docs/physics.md §1 numbering) of a box of `size` centred at `centre`.
Eigen::Matrix<double, 3, 8> box(const Eigen::Vector3d& size,
                                const Eigen::Vector3d& centre = Eigen::Vector3d::Zero()) {
  Eigen::Matrix<double, 3, 8> corners;
  for (int p = 0; p < 8; ++p) {
    for (int d = 0; d < 3; ++d) corners(d, p) = centre(d) - size(d) / 2 + size(d) * ((p >> d) & 1);
  }
  return corners;
}

Eigen::Matrix3Xd random_points(std::mt19937& rng, int count, double spread) {
  std::uniform_real_distribution<double> u(-spread, spread);
  Eigen::Matrix3Xd points(3, count);
  for (Eigen::Index i = 0; i < points.size(); ++i) points(i) = u(rng);
  return points;
}

TEST(TrilinearDeform, AnAffineMapOfTheCornersMovesEveryVertexByThatMap) {
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::Matrix3d m;
  for (Eigen::Index i = 0; i < m.size(); ++i) m(i) = u(rng);
  m += 1.5 * Eigen::Matrix3d::Identity();  // well away from singular, far from orthogonal
  ASSERT_GT((m.transpose() * m - Eigen::Matrix3d::Identity()).norm(), 0.5);
  const Eigen::Vector3d shift(0.3, -2.0, 1.25);
  const Eigen::Matrix<double, 3, 8> rest = box({1.878, 2.9085, 0.5});
  const Eigen::Matrix<double, 3, 8> world = (m * rest).colwise() + shift;
  // Inside the box and outside it (extrapolated by the same formula).
  const Eigen::Matrix3Xd vertices = random_points(rng, 500, 2.0);
  const Eigen::Matrix3Xd moved = trilinear_deform(rest, world, vertices);
  const Eigen::Matrix3Xd expected = (m * vertices).colwise() + shift;
  ASSERT_EQ(moved.cols(), vertices.cols());
  EXPECT_LT((moved - expected).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(TrilinearDeform, WorksForABoxNotCentredAtTheOrigin) {
  // A body's box need not be centred on its centre of mass (a T-handle's is not).
  std::mt19937 rng(7);
  const Eigen::Matrix<double, 3, 8> rest = box({2.0, 0.4, 1.0}, {0.1, -0.7, 0.2});
  Eigen::Matrix3d rotation =
      Eigen::AngleAxisd(0.9, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Matrix<double, 3, 8> world = rotation * rest;
  const Eigen::Matrix3Xd vertices = random_points(rng, 100, 1.0);
  EXPECT_LT((trilinear_deform(rest, world, vertices) - rotation * vertices).cwiseAbs().maxCoeff(),
            1e-12);
}

TEST(TrilinearDeform, CornersMapToCornersAndTheCentreToTheirMean) {
  const Eigen::Matrix<double, 3, 8> rest = box({1.0, 2.0, 3.0});
  // A non-affine deformation: every corner moved on its own.
  std::mt19937 rng(3);
  const Eigen::Matrix<double, 3, 8> world = rest + random_points(rng, 8, 0.4);
  Eigen::Matrix3Xd vertices(3, 9);
  vertices.leftCols<8>() = rest;
  vertices.col(8).setZero();
  const Eigen::Matrix3Xd moved = trilinear_deform(rest, world, vertices);
  EXPECT_LT((moved.leftCols<8>() - world).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT((moved.col(8) - world.rowwise().mean()).cwiseAbs().maxCoeff(), 1e-15);
  // The middle of edge 0–1 goes to the middle of the moved edge, whatever the other corners do.
  Eigen::Matrix3Xd edge_middle = 0.5 * (rest.col(0) + rest.col(1));
  EXPECT_LT((trilinear_deform(rest, world, edge_middle) - 0.5 * (world.col(0) + world.col(1)))
                .cwiseAbs()
                .maxCoeff(),
            1e-15);
}

TEST(TrilinearDeform, RejectsRestCornersThatAreNotABoxInTheDocumentedOrder) {
  const Eigen::Matrix<double, 3, 8> rest = box({1.0, 2.0, 3.0});
  const Eigen::Matrix3Xd vertex = Eigen::Vector3d::Zero();
  Eigen::Matrix<double, 3, 8> swapped = rest;
  swapped.col(1).swap(swapped.col(2));
  EXPECT_THROW(trilinear_deform(swapped, rest, vertex), std::invalid_argument);
  Eigen::Matrix<double, 3, 8> flat = rest;
  flat.row(2).setZero();
  EXPECT_THROW(trilinear_deform(flat, rest, vertex), std::invalid_argument);
  const Eigen::Matrix<double, 3, 8> rotated =
      Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ()).toRotationMatrix() * rest;
  EXPECT_THROW(trilinear_deform(rotated, rest, vertex), std::invalid_argument);
}

}  // namespace
}  // namespace bookspin::clip
