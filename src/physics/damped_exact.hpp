#pragma once
// The exact motion of a torque-free body slowed by isotropic drag (docs/physics.md §21): the
// free motion of physics::ExactRotation in the stretched time s(t), its ω and L scaled by the
// decay g(t) = |L(t)|/|L0|.
#include <Eigen/Dense>

#include "physics/drag.hpp"
#include "physics/exact_solution.hpp"

namespace bookspin::physics {

/// Exact motion under the drag torque of `drag` (DragLaw::linear: τ = −c L; quadratic:
/// τ = −(r/|L0|)|L| L), from the identity orientation with body-frame ω0. Writing
/// L_body(t) = g(t)·M, Euler's equations become dM/ds = M × I⁻¹M with ds = g dt, so (§21)
///   ω(t) = g(t)·ω_free(s(t)),  L_body(t) = g(t)·L_free,body(s(t)),  R(t) = R_free(s(t)),
///   L_world(t) = g(t)·L0,  E(t) = g(t)²·E0,
/// with ω_free, R_free those of ExactRotation(moments, ω0). Without drag (law none or rate 0)
/// every value is ExactRotation's at t, bit for bit. Units as ExactRotation's; the rate in
/// 1 per time unit.
class DampedExactRotation {
 public:
  /// Throws std::invalid_argument as ExactRotation does, and for a rate that is not finite.
  DampedExactRotation(const Eigen::Vector3d& moments, const Eigen::Vector3d& omega0_body, Drag drag,
                      ExactParts parts = ExactParts::omega_and_orientation);

  /// Body-frame ω(t), rad per time unit. Throws std::invalid_argument for a t beyond the law's
  /// range (drag_defined_until).
  Eigen::Vector3d omega_body(double t) const;
  /// Body-frame L(t) = I ω(t).
  Eigen::Vector3d angular_momentum_body(double t) const;
  /// World L(t) = g(t)·L0: its direction is fixed.
  Eigen::Vector3d angular_momentum_world(double t) const;
  /// R(t), body→world: the free orientation at s(t).
  Eigen::Matrix3d orientation(double t) const;
  /// Kinetic energy ½ ω·I ω = g(t)² E0.
  double energy(double t) const;
  /// Time between the first flips measured from t (T/2 in stretched time turned back into
  /// time, docs/physics.md §21); infinite for a steady motion, the separatrix, or when the drag
  /// stops the body before the next flip (the linear law's s never passes 1/c).
  double flip_period_at(double t) const;
  /// s(t) and g(t) (drag.hpp).
  double stretched(double t) const;
  double decay(double t) const { return drag_decay(drag_, t); }

  const ExactRotation& free() const { return free_; }
  const Drag& drag() const { return drag_; }

 private:
  ExactRotation free_;
  Drag drag_;
};

/// The time t at which the stretched time is s (the inverse of stretched_time); infinite where
/// s is never reached (linear law: s ≥ 1/c). docs/physics.md §21.
double time_of_stretched(const Drag& drag, double s);

}  // namespace bookspin::physics
