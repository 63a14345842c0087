#pragma once
// The twist: how far a free body turns about its fixed angular momentum L over one period of
// its body-frame motion (Montgomery 1991; docs/physics.md §19). Measured from a run's
// orientations (TwistMeter) and in closed form (twist_exact). Pure math on top of src/physics.
#include <Eigen/Core>
#include <optional>

#include "physics/exact_solution.hpp"

namespace bookspin::analysis {

/// The angle `angle` (rad) brought into (−π, π] by whole turns.
double wrap_angle(double angle);

/// The pole of the twist frame (docs/physics.md §19): the unit body axis (body frame) that
/// L_b = Rᵀ L circles, the largest moment's in case A and the smallest's in case B, with the
/// sign of L_b along it (which never changes). Empty for steady and separatrix motion.
std::optional<Eigen::Vector3d> twist_pole(const physics::ExactRotation& exact);

/// The solid angle Ω (sr) that L_b/|L| encloses in one period T of the exact body-frame
/// motion on the side of `pole`, positive when L_b goes counterclockwise about the pole seen
/// from outside the sphere (docs/physics.md §19): Ω = ∮ (1 − cos ϑ) dφ in polar angles ϑ, φ
/// about the pole, integrated over t ∈ [0, T] from the exact L_b(t) and ω(t) by the
/// trapezoid rule (periodic and analytic: geometric convergence), the points doubled until
/// two sums agree to 1e-13. Empty for steady and separatrix motion.
std::optional<double> polhode_solid_angle(const physics::ExactRotation& exact);

/// Montgomery's twist in closed form, Δθ = 2E·T/|L| − Ω (rad, wrapped into (−π, π]), from
/// the exact energy E, |L|, the period T of ω (ExactRotation::period()) and Ω of
/// polhode_solid_angle(): the angle by which R(T) turns the body about L (R(0) = I).
/// Source: R. Montgomery, "How much does the rigid body rotate?", Am. J. Phys. 59 (1991);
/// docs/physics.md §19. Empty for steady and separatrix motion.
std::optional<double> twist_exact(const physics::ExactRotation& exact);

/// Measures the twist of a run (docs/physics.md §19) from its orientations: after every step
/// it takes R (3×3, body→world), ω (body frame, rad per time unit) and L (world). It follows
/// m = Rᵀ L/|L| in polar angles (ϑ, φ) about the pole (body frame) and the angle θ about L of
/// the world image R·(pole × m)/|pole × m| in a fixed world plane normal to L; the period
/// ends when φ has turned once, placed between two steps by cubic Hermite interpolation of
/// φ (its rate from ω: φ̇ = ((a·m)(m·ω) − a·ω)/(1 − (a·m)²)), and θ there is interpolated the
/// same way (θ̇ = m·ω + φ̇ (a·m)). twist() = θ(T) − θ(0), wrapped into (−π, π].
class TwistMeter {
 public:
  /// `pole`: twist_pole() of the run's initial state (unit, body frame).
  explicit TwistMeter(const Eigen::Vector3d& pole);
  /// The state at time t (increasing; the first call is the start of the period).
  void observe(double t, const Eigen::Matrix3d& R, const Eigen::Vector3d& omega_body,
               const Eigen::Vector3d& L_world);
  /// True once one period has been measured, or the run left the pole's hemisphere (then
  /// twist() stays empty): further samples change nothing.
  bool done() const { return done_; }
  /// The twist over the first period (rad, (−π, π]); empty before it ends.
  std::optional<double> twist() const { return twist_; }

 private:
  struct Sample {
    double t, phi, phi_dot, theta, theta_dot;  ///< φ and θ unwrapped (rad)
  };
  Eigen::Vector3d pole_, b_, c_;  ///< body frame: the pole and two axes normal to it
  Eigen::Vector3d l_, g1_, g2_;   ///< world: L/|L| at the start and a plane normal to it
  bool started_ = false, done_ = false;
  Sample first_{}, previous_{};
  std::optional<double> twist_;
};

}  // namespace bookspin::analysis
