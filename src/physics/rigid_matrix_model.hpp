#pragma once
// Rigid body with an orientation matrix (paper §4, docs/physics.md §3, Baraff 1997).
#include "physics/rigid_body.hpp"
#include "physics/rigid_integrators.hpp"

namespace bookspin::physics {

/// State: orientation R (3×3, body→world, not forced to stay a rotation) and the constant
/// world angular momentum L. Euler step (paper): ω = R I_body⁻¹ Rᵀ L, R += dt·[ω]× R, then
/// optionally R ← U Vᵀ from the SVD R = U Σ Vᵀ (computed as the polar factor of R, see
/// polar.hpp; the same matrix as JacobiSVD's U Vᵀ to round-off). Corners are R·body
/// corners, so an unnormalized R stretches the book (paper Figure 10). The other
/// integrators (rk4, implicit-midpoint, splitting, splitting4, rescaled-euler: docs/physics.md §10)
/// advance the same state; an implicit-midpoint step that does not converge ends the run (finite()
/// false, divergence_reason() says why) and leaves R as it was.
class RigidMatrixModel final : public RigidBody {
 public:
  RigidMatrixModel(const Body& body, const ModelConfig& config);
  /// RigidMatrixModel(book_body(book), config).
  RigidMatrixModel(const Book& book, const ModelConfig& config)
      : RigidMatrixModel(book_body(book), config) {}
  void reset(const InitialState& initial) override;
  Corners corners() const override;
  Diagnostics diagnostics() const override;
  double cos_axis_L(int axis) const override { return axis_cosine(matrix(), L_, axis); }
  bool finite() const override;

  /// R at the last step's end (for the splittings: the lagging R turned by the pending
  /// outer half-flow, see SplittingStepper).
  /// The model's R (3×3, body→world) as integrated: not a rotation without normalization.
  Eigen::Matrix3d matrix() const;
  Eigen::Matrix3d orientation() const override;

 private:
  void free_step(double dt) override;
  void apply_pending_flow() override;
  Eigen::Vector3d omega_world(const Eigen::Matrix3d& R) const;
  Eigen::Matrix3d derivative(const Eigen::Matrix3d& R) const;
  void euler_step(double dt);
  void normalize();

  Eigen::Matrix3d R_ = Eigen::Matrix3d::Identity();  ///< lags for the splittings
};

}  // namespace bookspin::physics
