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
// §8.9) advises switching it off. Σ(σᵢ − 1/σᵢ)² below this: within ~5% of orthogonal.
constexpr double kStopScaling = 1e-2;

/// The cofactor matrix cof(X) = det(X)·X⁻ᵀ: its columns are cross products of X's columns.
Eigen::Matrix3d cofactors(const Eigen::Matrix3d& x) {
  Eigen::Matrix3d c;
  c.col(0) = x.col(1).cross(x.col(2));
  c.col(1) = x.col(2).cross(x.col(0));
  c.col(2) = x.col(0).cross(x.col(1));
  return c;
}

}  // namespace

Eigen::Matrix3d nearest_orthogonal_svd(const Eigen::Matrix3d& m) {
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(m, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return svd.matrixU() * svd.matrixV().transpose();
}

// One iteration costs a cofactor matrix, a determinant, one division and a blend; the
// scaling and convergence tests are off the critical path (the branches predict well).
Eigen::Matrix3d nearest_rotation(const Eigen::Matrix3d& m) {
  Eigen::Matrix3d x = m;
  bool scaling = true;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration) {
    const Eigen::Matrix3d c = cofactors(x);
    const double det = x.col(0).dot(c.col(0));
    if (!(det > 0.0) || !std::isfinite(det)) break;  // reflection, singular or NaN: SVD
    double zeta = 1.0;
    if (scaling) {
      // ‖X‖² + ‖X⁻¹‖² − 6 = Σ(σᵢ − 1/σᵢ)² ≥ 0 measures how far X is from orthogonal.
      const double norm2 = x.squaredNorm(), inverse_norm2 = c.squaredNorm() / (det * det);
      if (norm2 + inverse_norm2 - 6.0 < kStopScaling)
        scaling = false;
      else
        zeta = std::sqrt(std::sqrt(inverse_norm2 / norm2));  // (‖X⁻¹‖_F / ‖X‖_F)^½
    }
    // ½(ζX + ζ⁻¹X⁻ᵀ) with X⁻ᵀ = cof/det.
    const Eigen::Matrix3d next = (0.5 * zeta) * x + (0.5 / (zeta * det)) * c;
    const double change2 = (next - x).squaredNorm();
    x = next;
    if (change2 <= kConverged * kConverged) return x;
  }
  return nearest_orthogonal_svd(m);
}

}  // namespace bookspin::physics
