// The matrix model's normalization: Newton's polar iteration must give the rotation the
// SVD gives (it replaced JacobiSVD for speed; docs/physics.md §3).
#include "physics/polar.hpp"

#include <gtest/gtest.h>

#include <random>

namespace bookspin::physics {
namespace {

Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> normal;
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  return q.normalized().toRotationMatrix();
}

Eigen::Matrix3d random_matrix(std::mt19937_64& rng, double scale) {
  std::uniform_real_distribution<double> uniform(-scale, scale);
  Eigen::Matrix3d m;
  for (int i = 0; i < 9; ++i) m.data()[i] = uniform(rng);
  return m;
}

double max_gap(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

// What one Euler step of the matrix model leaves: a rotation plus a small perturbation.
TEST(Polar, NearRotationsMatchTheSvd) {
  std::mt19937_64 rng(7);
  for (double size : {1e-12, 1e-8, 1e-5, 1e-3}) {
    for (int i = 0; i < 2000; ++i) {
      const Eigen::Matrix3d m = random_rotation(rng) + random_matrix(rng, size);
      ASSERT_LT(max_gap(physics::nearest_rotation(m), physics::nearest_orthogonal_svd(m)), 1e-14)
          << "perturbation " << size << "\n"
          << m;
    }
  }
}

// Far from orthogonal, but well conditioned (the gap scales with the condition number).
TEST(Polar, StronglyNonOrthogonalMatricesMatchTheSvd) {
  std::mt19937_64 rng(11);
  int tried = 0;
  while (tried < 2000) {
    const Eigen::Matrix3d m =
        random_rotation(rng) * (Eigen::Matrix3d::Identity() + random_matrix(rng, 0.6));
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(m);
    if (m.determinant() <= 0.0 || svd.singularValues()(0) > 10.0 * svd.singularValues()(2))
      continue;
    ++tried;
    ASSERT_LT(max_gap(physics::nearest_rotation(m), physics::nearest_orthogonal_svd(m)), 1e-14)
        << m;
  }
}

TEST(Polar, ResultIsARotation) {
  std::mt19937_64 rng(3);
  for (int i = 0; i < 1000; ++i) {
    const Eigen::Matrix3d r =
        physics::nearest_rotation(random_rotation(rng) + random_matrix(rng, 0.1));
    EXPECT_LT((r.transpose() * r - Eigen::Matrix3d::Identity()).norm(), 1e-15);
    EXPECT_NEAR(r.determinant(), 1.0, 1e-15);
  }
}

// A reflection (det < 0) has no nearest rotation of the polar kind: the SVD's U Vᵀ, as
// before, is returned unchanged.
TEST(Polar, NegativeDeterminantFallsBackToTheSvd) {
  const Eigen::Matrix3d m = Eigen::Vector3d(1.0, 1.2, -0.9).asDiagonal();
  EXPECT_EQ(physics::nearest_rotation(m), physics::nearest_orthogonal_svd(m));
}

TEST(Polar, IsDeterministic) {
  std::mt19937_64 rng(5);
  const Eigen::Matrix3d m = random_rotation(rng) + random_matrix(rng, 1e-4);
  const Eigen::Matrix3d first = physics::nearest_rotation(m);
  for (int i = 0; i < 10; ++i) EXPECT_EQ(physics::nearest_rotation(m), first);
}

}  // namespace
}  // namespace bookspin::physics
