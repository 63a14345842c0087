#pragma once
// Rigid body with a quaternion (paper §4.4, docs/physics.md §4, Baraff 1997).
#include <Eigen/Geometry>

#include "physics/rigid_body.hpp"
#include "physics/rigid_integrators.hpp"

namespace bookspin::physics {

/// State: q = (w, x, y, z) and the constant world angular momentum L. Euler step:
/// R(q) from the unit-quaternion formula (Eigen's toRotationMatrix(), which does not divide
/// by |q|²), ω = R(q) I_body⁻¹ R(q)ᵀ L (world frame), q += ½ dt (0, ω) ⊗ q, then optionally
/// q /= |q|. The same R(q) places the corners, so with |q| = s ≠ 1 the book is drawn as
/// (1 − s²) I + s² R(q/s): it distorts and pulsates (paper Figures 11–12). The other
/// integrators (rk4, implicit-midpoint, splitting, splitting4, rescaled-euler: docs/physics.md §10)
/// evaluate ω from R(q/|q|) instead; an implicit-midpoint step that does not converge ends the run
/// (finite() false, divergence_reason() says why) and leaves q as it was.
class RigidQuaternionModel final : public RigidBody {
 public:
  RigidQuaternionModel(const Body& body, const ModelConfig& config);
  /// RigidQuaternionModel(book_body(book), config).
  RigidQuaternionModel(const Book& book, const ModelConfig& config)
      : RigidQuaternionModel(book_body(book), config) {}
  void reset(const InitialState& initial) override;
  Corners corners() const override;
  Diagnostics diagnostics() const override;
  double cos_axis_L(int axis) const override {
    return axis_cosine(quaternion().toRotationMatrix(), L_, axis);
  }
  bool finite() const override;

  /// q at the last step's end (for the splittings: the lagging q turned by the pending
  /// outer half-flow, see SplittingStepper).
  /// The model's q (body→world) as integrated: not of unit length without normalization.
  Eigen::Quaterniond quaternion() const;
  Eigen::Matrix3d orientation() const override;

 private:
  void free_step(double dt) override;
  void apply_pending_flow() override;
  Eigen::Vector4d derivative(const Eigen::Vector4d& q_coeffs) const;
  Eigen::Vector3d body_momentum() const;
  void raw_euler_step(double dt);
  void unit_euler_step(double dt);

  Eigen::Quaterniond q_ = Eigen::Quaterniond::Identity();  ///< lags for the splittings
};

}  // namespace bookspin::physics
