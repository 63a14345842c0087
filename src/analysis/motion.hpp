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
/// sign is that of ω and of L along that body axis. A turn-over takes it from one side of 0
/// to the other, past FlipDetector's margin (docs/physics.md §14).
double flip_signal(const physics::Diagnostics& diagnostics, const Eigen::Vector3d& moments);
/// flip_signal(simulator.diagnostics(), moments), the same bits, from the simulator's
/// cos_axis_L alone: a loop that reads the signal after every step and nothing else of the
/// diagnostics (the explorer's, docs/explorer.md "Speed") pays for that cosine only.
double flip_signal(const physics::Simulator& simulator, const Eigen::Vector3d& moments);

/// The turn-overs of a flip signal sampled at increasing times (the flip detector,
/// docs/physics.md §14): a flip is counted when the signal, having been on one side of 0, goes
/// past the margin on the other (from below −margin to above +margin or back), not at every
/// sign change, so a wobble about a stable axis, which keeps |cos(intermediate axis, L)| small,
/// counts none. The side to start from is the sign of the first non-zero sample. Each flip is
/// placed at the last zero crossing before the signal passed the margin, by linear
/// interpolation between the two samples around it (a zero sample keeps the sign before it).
class FlipDetector {
 public:
  /// The default margin, 0.5: the intermediate axis within 60° of ±L (docs/physics.md §14).
  static constexpr double kMargin = 0.5;
  /// `margin` in [0, 1) (a cosine); 0 counts every sign change. Throws std::invalid_argument
  /// outside (a bug: no input sets it).
  explicit FlipDetector(double margin = kMargin);
  /// Feeds the sample `value` (a cosine, dimensionless) at time `t` (time units, increasing).
  void observe(double t, double value);
  int count() const { return count_; }  ///< turn-overs seen so far
  /// Time of the first turn-over; empty before any.
  std::optional<double> first_flip() const;
  /// Mean spacing of the turn-overs, (last − first)/(count − 1); empty below two.
  std::optional<double> flip_period() const;

 private:
  double margin_;
  bool started_ = false;
  double previous_t_ = 0.0, previous_value_ = 0.0;
  int last_sign_ = 0;      ///< sign of the last non-zero sample, 0 before any
  int side_ = 0;           ///< the side the signal was last past the margin on (first: its sign)
  double crossing_ = 0.0;  ///< time of the last zero crossing away from side_
  int count_ = 0;
  double first_ = 0.0, last_ = 0.0;
};

/// The exact motion's first zero of ω about body `axis` after t = 0 (docs/physics.md §14):
/// zeros of sn are T/2 apart, so the first lies in (0, T/2]; bracketed on 64 samples per T/2
/// and bisected to round-off. Empty for steady and separatrix motion (no finite T).
std::optional<double> exact_first_flip(const physics::ExactRotation& exact, int axis);

/// The largest |cos(intermediate principal axis, L)| over the exact motion's orbit
/// (dimensionless, in [0, 1]): |L_2|/|L| where the orbit crosses the plane of the cn axis
/// (docs/physics.md §14), (2E·I3 − L²)·I2/(I3 − I2) about the largest axis and
/// (L² − 2E·I1)·I2/(I2 − I1) about the smallest, over L²; 1 on the separatrix, 0 for steady
/// motion.
double exact_flip_amplitude(const physics::ExactRotation& exact);

/// The exact motion's turn-overs in [0, t_end] (docs/physics.md §14): the zeros of ω about
/// body `axis`, exact_first_flip + k·T/2 ≤ t_end, when the orbit takes the cosine past
/// FlipDetector::kMargin (exact_flip_amplitude), else 0 (a wobble).
int exact_flip_count(const physics::ExactRotation& exact, int axis, double t_end);
/// The same count from exact_first_flip(exact, axis) computed once (`first`), for a caller that
/// asks at many t_end: first + k·T/2 ≤ t_end, 0 for a wobble or no first flip.
int exact_flip_count(const physics::ExactRotation& exact, std::optional<double> first,
                     double t_end);

/// Angle (rad) between two rotations a and b (3×3), 2·asin(‖a − b‖_F / √8): the angle of
/// aᵀb, accurate for tiny angles (‖a − b‖_F = 2√2 sin(θ/2) for rotations).
double rotation_angle_between(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b);

}  // namespace bookspin::analysis
