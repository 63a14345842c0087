#pragma once
// Shape measures shared by all simulators (docs/physics.md §9).
#include <array>

#include "physics/body.hpp"
#include "physics/book.hpp"
#include "physics/simulator.hpp"

namespace bookspin::physics {

/// The 28 corner pairs (i < j), in the order (0,1), (0,2), …, (6,7).
const std::array<std::pair<int, int>, 28>& corner_pairs();

/// Largest relative length change max |len/rest − 1| over the 28 corner pairs.
/// `corners` and `rest` are 3×8; `rest` gives the rest lengths. Dimensionless.
double strain_max(const Corners& corners, const Corners& rest);

/// The rotation R (3×3, det +1) minimising Σ |R·rest_p − current_p|² over the 8 corners
/// (Kabsch 1976, via the polar decomposition of current·restᵀ with Eigen's JacobiSVD).
/// `current` must be centred on its centroid; both are 3×8.
Eigen::Matrix3d best_fit_rotation(const Corners& current, const Corners& rest);

/// ‖MᵀM − I‖_F of a 3×3 matrix.
double orthogonality_error(const Eigen::Matrix3d& m);

/// The skew matrix [w]× with [w]× v = w × v.
Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& w);

/// Largest magnitude a state variable may reach before the run counts as diverged.
inline constexpr double kDivergenceLimit = 1e6;

/// True if every entry is finite and below kDivergenceLimit in magnitude.
template <typename Derived>
bool is_sane(const Eigen::MatrixBase<Derived>& m) {
  return m.allFinite() && m.cwiseAbs().maxCoeff() < kDivergenceLimit;
}

/// Diagnostics of a rigid model whose corners are `M · body.cage.body_corners()` (M is R or
/// R(q), possibly not a rotation), with principal moments body.moments. L is the world
/// angular momentum. Equations: docs/physics.md §3, §9, §12 (cos_principal_L).
Diagnostics rigid_diagnostics(const Body& body, const Eigen::Matrix3d& M, const Eigen::Vector3d& L,
                              double t);
/// rigid_diagnostics(book_body(book), M, L, t).
Diagnostics rigid_diagnostics(const Book& book, const Eigen::Matrix3d& M, const Eigen::Vector3d& L,
                              double t);

/// Diagnostics of a motion given rather than integrated (the exact motion, a replayed one):
/// rigid_diagnostics(body, R, L, t) for the pose, with ω (`omega_body`, body frame) and the
/// energy (`energy_kinetic`, all of it) the motion's own, the quaternion's norm 1, and the axis
/// cosines 0 where L = 0 (no direction to compare). docs/physics.md §9.
Diagnostics prescribed_diagnostics(const Body& body, const Eigen::Matrix3d& R,
                                   const Eigen::Vector3d& L, double t,
                                   const Eigen::Vector3d& omega_body, double energy_kinetic);

/// cos(M's column `axis`, L): the cosine of a body axis placed by M (3×3, body → world) with L
/// (world), as rigid_diagnostics gives it in cos_axis_L.
inline double axis_cosine(const Eigen::Matrix3d& M, const Eigen::Vector3d& L, int axis) {
  const Eigen::Vector3d a = M.col(axis);
  return a.dot(L) / (a.norm() * L.norm());
}

/// cos_principal_L from cos_axis_L: the body axes' cosines in principal_order(moments).
Eigen::Vector3d principal_cosines(const Eigen::Vector3d& cos_axis_L,
                                  const Eigen::Vector3d& moments);

/// L0 = I_body·ω0 + jiggle_delta_L(seed, jiggle), I_body = diag(moments) (body frame =
/// principal frame): world angular momentum at reset (identity R).
Eigen::Vector3d initial_angular_momentum(const Eigen::Vector3d& moments,
                                         const InitialState& initial);
/// initial_angular_momentum(book.principal_moments(), initial).
Eigen::Vector3d initial_angular_momentum(const Book& book, const InitialState& initial);

}  // namespace bookspin::physics
