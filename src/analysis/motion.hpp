#pragma once
// Motion measured in one place: which body axis flips, when it flips, the exact model's first
// flip, and the angle between two orientations (docs/physics.md §8 and §14). Pure math on
// top of src/physics.
#include <Eigen/Core>
#include <optional>

#include "physics/exact_solution.hpp"
#include "physics/simulator.hpp"

namespace bookspin::analysis {

/// Body axis (0 = x, 1 = y, 2 = z) of the intermediate of the three principal moments
/// (body frame, mass·length²): x for the book, y for the presets and meshes (their axes are
/// sorted, docs/physics.md §12). Ties keep axis order (physics::principal_order), so all
/// equal moments give 1. The one place that picks the axis that flips.
int intermediate_axis(const Eigen::Vector3d& moments);

/// The flip signal of a diagnostics row: cos(intermediate principal axis in world, L), whose
/// sign is that of ω and of L along that body axis. Its sign changes are the flips
/// (docs/physics.md §14).
double flip_signal(const physics::Diagnostics& diagnostics, const Eigen::Vector3d& moments);

/// Sign changes of a signal sampled at increasing times (the flip detector). A zero sample
/// keeps the sign before it; each change is placed by linear interpolation between the two
/// samples around it (docs/physics.md §14).
class FlipDetector {
 public:
  /// Feeds the sample `value` at time `t` (time units, increasing).
  void observe(double t, double value);
  int count() const { return count_; }  ///< sign changes seen so far
  /// Time of the first sign change; empty before any.
  std::optional<double> first_flip() const;
  /// Mean spacing of the sign changes, (last − first)/(count − 1); empty below two.
  std::optional<double> flip_period() const;

 private:
  bool started_ = false;
  double previous_t_ = 0.0, previous_value_ = 0.0;
  int last_sign_ = 0;  ///< sign of the last non-zero sample, 0 before any
  int count_ = 0;
  double first_ = 0.0, last_ = 0.0;
};

/// The exact motion's first zero of ω about body `axis` after t = 0 (docs/physics.md §14):
/// zeros of sn are T/2 apart, so the first lies in (0, T/2]; bracketed on 64 samples per T/2
/// and bisected to round-off. Empty for steady and separatrix motion (no finite T).
std::optional<double> exact_first_flip(const physics::ExactRotation& exact, int axis);

/// Angle (rad) between two rotations a and b (3×3), 2·asin(‖a − b‖_F / √8): the angle of
/// aᵀb, accurate for tiny angles (‖a − b‖_F = 2√2 sin(θ/2) for rotations).
double rotation_angle_between(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b);

}  // namespace bookspin::analysis
