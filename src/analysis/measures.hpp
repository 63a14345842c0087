#pragma once
// The measures of one run of a scene (docs/physics.md §14), as one table: a measure's name
// (CSV column and `--measure` word), its plot label and the field that holds it. Adding a
// measure is a row of measure_table() and its value in measure_run().
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"

namespace bookspin::analysis {

/// Every measure of one run; empty where it is undefined (no flip, fewer than two flips, a
/// diverged run's orientation). Times in time units, angles in rad. The *_exact fields are
/// the exact model's values for the same initial state (docs/physics.md §8): flip_period =
/// ExactRotation::flip_period() = 2K(k)/λ, first_flip = the first zero of the exact ω about
/// the intermediate axis (exact_first_flip); empty for steady and separatrix motion.
struct RunMeasures {
  std::optional<double> first_flip;         ///< first flip (FlipDetector on flip_signal)
  std::optional<double> flip_period;        ///< mean spacing of the flips (needs two)
  std::optional<double> energy_drift;       ///< max over every step of |E/E0 − 1|
  std::optional<double> orientation_error;  ///< angle of R_exactᵀ R_model at the run's end
  std::optional<double> diverged_at;        ///< t of the step that diverged; empty if none
  /// Rotation about L over the first period of the body-frame motion (TwistMeter,
  /// docs/physics.md §19), rad in (−π, π]; empty before a period ends, for a run that leaves
  /// the pole's hemisphere, and for steady and separatrix motion.
  std::optional<double> twist;
  std::optional<double> first_flip_exact, flip_period_exact;
  std::optional<double> twist_exact;  ///< Montgomery's 2E·T/|L| − Ω (analysis::twist_exact)
};

/// One row of the measure table.
struct Measure {
  std::string_view name;        ///< CSV column and `--measure` word, e.g. "first_flip"
  std::string_view axis_label;  ///< y label of its sweep plot
  bool log_scale;               ///< plotted on a log axis
  std::optional<double> RunMeasures::*value;
  /// The exact model's column ("first_flip_exact") and field, or empty and null.
  std::string_view exact_name;
  std::optional<double> RunMeasures::*exact;
};

/// The table, in the order the help text lists it: first_flip, flip_period, energy_drift,
/// orientation_error, diverged_at, twist.
const std::vector<Measure>& measure_table();

/// The row named `name`, or null.
const Measure* find_measure(std::string_view name);

/// "first_flip, flip_period, …": the names of the table, for messages and help.
std::string measure_names();

/// Runs `scene` (not a comparison) for its whole length, (frames − 1)·steps_per_frame steps
/// of dt, evaluating the flip signal and E after every step (not every frame), and measures
/// it. A diverging run stops there and is measured up to its last finite step. The
/// orientation is physics::Simulator::orientation() (the best-fit rotation for the models
/// that deform) against the exact R(t). `stop` (may be empty), asked every kStopPollSteps
/// steps, abandons the run: it then returns at once and its measures mean nothing (the caller
/// discards them; a sweep stopped by a signal).
RunMeasures measure_run(const scene::Scene& scene, const std::function<bool()>& stop = {});

/// Steps between two questions of measure_run's `stop`: a few milliseconds of the slowest
/// model (the particle book), so that a stopped sweep's running points end within a second.
inline constexpr long long kStopPollSteps = 64;

/// The twist of one run (docs/physics.md §19), rad in (−π, π]: `measured` by a TwistMeter
/// over the first body-frame period of `scene`'s model (not a comparison), stepped by dt past
/// the clip's end if the period is longer, for at most twice the exact period T; empty when
/// the run diverges, leaves the pole's hemisphere or takes longer. `closed_form` is
/// twist_exact() of the same initial state. Both empty for steady and separatrix motion.
struct TwistMeasure {
  std::optional<double> measured, closed_form;
};
TwistMeasure measure_twist(const scene::Scene& scene);

}  // namespace bookspin::analysis
