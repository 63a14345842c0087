#pragma once
// How far each model × integrator is from the exact motion (docs/physics.md §8–10). The door of
// src/analysis: pure computation on top of src/physics (timing by std::chrono only).
#include <functional>
#include <string>
#include <vector>

#include "analysis/motion.hpp"
#include "physics/exact_solution.hpp"
#include "physics/simulator.hpp"

namespace bookspin::analysis {

/// One row of the accuracy report: a model × integrator pair and its name as every table,
/// chart and manifest prints it.
struct Method {
  Method() = default;
  /// `kind` × `integrator`, labelled "<model> <integrator>" in physics' names
  /// ("rigid-quaternion rk4", "mujoco implicit").
  Method(physics::ModelKind kind, physics::Integrator integrator);

  physics::ModelKind kind{};
  physics::Integrator integrator{};
  std::string label;
};

/// bookspin's own supported pairs except "exact": particle × {euler, symplectic-euler,
/// velocity-verlet}, rigid-matrix and rigid-quaternion × {euler, rk4, implicit-midpoint,
/// splitting, splitting4, rescaled-euler}.
std::vector<Method> all_methods();

/// The rows of `bookspin accuracy`: all_methods(), then engine_methods().
std::vector<Method> accuracy_methods();

/// The other engines' modes (docs/engines.md), each engine's default first: mujoco × {euler,
/// rk4, implicit}, bullet × {implicit-body, implicit-world, explicit, none}, ode × {step,
/// quickstep, none}.
std::vector<Method> engine_methods();

/// The rigid pairs only (rigid-matrix and rigid-quaternion × every rigid integrator).
std::vector<Method> rigid_methods();

/// The methods a comma-separated list names, in the order of accuracy_methods() and each
/// once: "all" (accuracy_methods()), "engines" (engine_methods()), "rigid" (rigid_methods()),
/// a model kind ("mujoco": every mode of it) or "KIND:INTEGRATOR" ("rigid-quaternion:rk4").
/// Throws InputError ("--methods TEXT: reason") for an empty list or item, an unknown name,
/// the exact model (the reference itself) or a pair the model does not support.
std::vector<Method> parse_methods(const std::string& list);

/// The most steps measure() times for AccuracyRow::ns_per_step (docs/accuracy.md: "up to
/// 200,000 steps of each method").
constexpr long kMaxTimedSteps = 200000;

struct AccuracySettings {
  physics::Body body;  ///< any body: the book, a preset or a mesh (docs/physics.md §12)
  physics::InitialState initial;
  physics::ModelConfig model;  ///< normalize, damping, k; kind and integrator are replaced
  double flips = 10.0;         ///< run length in flip periods T/2 = 2K(k)/λ
  /// The clock measure() reads before and after the steps it times (nanoseconds from any
  /// fixed origin); empty: std::chrono::steady_clock. A test hands in its own clock to see
  /// what the time is divided by, without timing anything.
  std::function<double()> clock_ns = {};
};

struct AccuracyRow {
  Method method;
  double dt = 0.0;
  long steps = 0;
  double t_end = 0.0;
  /// Angle (rad) of R_exactᵀ R at t_end, R = Simulator::orientation() (the best-fit rotation
  /// for the particle models, the nearest rotation for the rigid ones).
  double orientation_error = 0.0;
  double energy_drift = 0.0;       ///< max |E/E0 − 1| over the run
  double L_drift = 0.0;            ///< max ||L|/|L0| − 1| over the run
  double flip_period = 0.0;        ///< mean spacing of the flips (FlipDetector); NaN if < 2
  double flip_period_error = 0.0;  ///< |flip_period / exact − 1|; NaN if < 2 flips seen
  /// First flip (FlipDetector) and |first_flip / exact first flip − 1|; NaN if none seen.
  double first_flip = 0.0;
  double first_flip_error = 0.0;
  int flips = 0;        ///< flips seen over the run (FlipDetector::count)
  int flips_exact = 0;  ///< the exact motion's turn-overs in [0, t_end] (exact_flip_count)
  /// Wall time of step() alone (ns): a fresh run's first min(steps, kMaxTimedSteps) steps
  /// timed, divided by that count.
  double ns_per_step = 0.0;
  bool diverged = false;
  std::string divergence_reason;  ///< the simulator's reason, if it gave one
};

/// Runs one method at one dt from `settings.initial` for `settings.flips` exact flip periods.
/// Throws InputError if the exact motion has no flip period (separatrix or a
/// pure principal-axis spin). `stop` (may be empty), asked every few dozen steps, abandons the
/// run: it returns at once and the row means nothing (the caller discards it).
AccuracyRow measure(const AccuracySettings& settings, const physics::ExactRotation& exact,
                    const Method& method, double dt, const std::function<bool()>& stop = {});

/// The exact reference for `settings` (same jiggled initial L as every model).
physics::ExactRotation exact_reference(const AccuracySettings& settings);

/// Relative energy error of one method along a long run: for each of the equal windows of
/// the run, the largest |E/E0 − 1| over its steps (E the model's total energy, E0 at t = 0),
/// plotted at the window's end time t (time units). Stops at a divergence.
struct EnergyHistory {
  Method method;
  double dt = 0.0;
  std::vector<double> t;
  std::vector<double> relative_error;
  bool diverged = false;
};

/// Runs `method` at step `dt` for `flips` exact flip periods in `windows` windows. `stop` as
/// measure()'s: the history is then cut short and means nothing.
EnergyHistory energy_history(const AccuracySettings& settings, const physics::ExactRotation& exact,
                             const Method& method, double dt, double flips, int windows,
                             const std::function<bool()>& stop = {});

/// Orientation error at time t_end of `method` at step `dt` (no flip bookkeeping; for
/// convergence-order checks).
double orientation_error_at(const AccuracySettings& settings, const physics::ExactRotation& exact,
                            const Method& method, double dt, double t_end);

}  // namespace bookspin::analysis
