#include "physics/polar.hpp"

#include <Eigen/SVD>
#include <cmath>
#include <limits>

namespace bookspin::physics {

namespace {

constexpr int kMaxIterations = 20;  // scaled Newton needs ≤ 9 even for cond(M) = 1e16
// Near convergence X_{k+1} − U ≈ ½(X_k − U)², so once a step moves X by less than 1e-9
// the new iterate is within ~1e-18 of U: round-off, nothing left to gain.
constexpr double kConverged = 1e-9;
// Scaling only speeds up the first iterations; near convergence ζ ≈ 1 and Higham (2008,
// §8.9) advises switching it off.
constexpr double kStopScaling = 1e-2;

/// X⁻ᵀ = cof(X)/det X, where the cofactor matrix's columns are cross products of X's
/// columns (cheaper and no less accurate than a general 3×3 inverse). Sets `det`.
Eigen::Matrix3d inverse_transpose(const Eigen::Matrix3d& x, double& det) {
  Eigen::Matrix3d cofactors;
  cofactors.col(0) = x.col(1).cross(x.col(2));
  cofactors.col(1) = x.col(2).cross(x.col(0));
  cofactors.col(2) = x.col(0).cross(x.col(1));
  det = x.col(0).dot(cofactors.col(0));
  return cofactors * (1.0 / det);
}

}  // namespace

Eigen::Matrix3d nearest_orthogonal_svd(const Eigen::Matrix3d& m) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return svd.matrixU() * svd.matrixV().transpose();
}

Eigen::Matrix3d nearest_rotation(const Eigen::Matrix3d& m) {
  Eigen::Matrix3d x = m;
  double change = std::numeric_limits<double>::infinity();
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    double det = 0.0;
    const Eigen::Matrix3d x_inv_t = inverse_transpose(x, det);
    if (!(det > 0.0) || !std::isfinite(det)) break;  // reflection, singular or NaN: SVD
    double zeta = 1.0;
    if (change > kStopScaling) zeta = std::sqrt(std::sqrt(x_inv_t.squaredNorm() / x.squaredNorm()));
    const Eigen::Matrix3d next = (0.5 * zeta) * x + (0.5 / zeta) * x_inv_t;
    change = (next - x).norm();
    x = next;
    if (change <= kConverged) return x;
  }
  return nearest_orthogonal_svd(m);
}

}  // namespace bookspin::physics
