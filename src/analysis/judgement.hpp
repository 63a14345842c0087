#pragma once
// The conformance kit's judgement (`bookspin flipcheck judge`, docs/flipcheck.md): a motion
// written by any engine against the exact motion from the same start (docs/physics.md §8,
// §14), and the judgement as a table. Pure: physics and analysis/motion.hpp only, no engine,
// no scene reader and no I/O, so that the explorer page judges with this same code compiled
// to WebAssembly (web/bindings.cpp). The motion comes in as values (jobs/motion_csv.hpp
// parses the file's text); the scenario of a scene file, and a method run from its start, are
// conformance.hpp's.
#include <Eigen/Geometry>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "common/csv_writer.hpp"
#include "common/stop.hpp"
#include "physics/body.hpp"
#include "physics/simulator.hpp"

namespace bookspin::analysis {

/// A conformance scenario: the body, its start and the run (docs/flipcheck.md).
struct Scenario {
  std::string name;
  physics::Body body;             ///< moments (body x, y, z, mass·length²), cage mass
  physics::InitialState initial;  ///< identity orientation, body-frame ω0, jiggle of L
  double dt = 0.0;                ///< time units
  long long steps = 0;            ///< steps of dt
};

/// The limits of a scenario (docs/flipcheck.md, "What a scenario may be"), each reasoned there.
struct ScenarioLimits {
  static constexpr long long max_steps = 10'000'000;  ///< the exact motion at every step
  static constexpr double max_omega = 1e6;            ///< rad per time unit, each component
  static constexpr double min_moment = 1e-30, max_moment = 1e30;  ///< mass·length²
  static constexpr double max_turn = 1e8;       ///< |ω0|·dt·steps, rad: the run's whole spin
  static constexpr std::size_t max_name = 128;  ///< characters
};

/// Why `name` is no scenario name, or "": a name is 1 to 128 letters, digits, '-', '_' and '.',
/// the first a letter or a digit (so that OUT/<name>.json and OUT/<name>/ stay inside OUT).
std::string scenario_name_problem(const std::string& name);

/// Throws InputError "NAME: FIELD: reason" for the first field of `scenario` that no scenario
/// may have (docs/flipcheck.md, "What a scenario may be"): a bad name, a moment or the mass not
/// finite and positive or outside ScenarioLimits, ω0 not finite, beyond ±1e6 or at rest, dt not
/// finite and positive, steps outside 1 … 10^7, a run turning by more than 10^8 rad.
void check_scenario(const Scenario& scenario);

/// The jiggled start every model begins from: ω0 = I_body⁻¹ L0, L0 = I_body ω0 + the jiggle
/// (docs/physics.md §5); body frame (= world frame at t = 0, q0 = identity), rad per time unit.
Eigen::Vector3d start_omega(const Scenario& scenario);

/// One row of a motion: the state after `step` steps of dt.
struct MotionSample {
  long long step = 0;          ///< t = step·dt
  Eigen::Quaterniond q;        ///< orientation, body → world (either sign; normalized here)
  Eigen::Vector3d omega_body;  ///< rad per time unit, body frame
};

/// The pass/fail thresholds of docs/flipcheck.md ("Thresholds"), where each is reasoned.
struct ConformanceThresholds {
  double start = 1e-6;               ///< |ω(0) − ω0| / |ω0|
  double energy_drift = 1e-2;        ///< max |E/E0 − 1|
  double L_drift = 1e-2;             ///< max ||L|/|L0| − 1|
  double first_flip = 0.05;          ///< |first − exact first| as a fraction of T/2
  double orientation_error = 0.1;    ///< rad, the largest over the rows
  double L_direction = 1e-2;         ///< rad: L (world) against the exact L, over the rows
  double separatrix_approach = 0.1;  ///< stable spins: fraction of the way to the separatrix
  /// The rows must show the exact motion's turn-overs: the exact motion sampled at them counts
  /// every one and puts the first within this fraction of T/2 of its time (a fifth of
  /// first_flip), or the motion is refused as too coarse to judge.
  double sampling_first_flip = 0.01;
};

/// |cos(spin axis, L)| below which a spin has tumbled (60° from L), for the motion's tumble
/// time and for whether the exact motion is a stable spin.
inline constexpr double kTumbleCosine = 0.5;

/// How a motion compares with the exact one (docs/flipcheck.md, "What judge measures").
struct Conformance {
  long long stride = 0;     ///< steps between rows
  long long last_step = 0;  ///< the motion's last row
  bool complete = false;  ///< it reaches the scenario's last step (or the stride's last before it)
  double start_error = 0.0;              ///< |ω(0) − ω0| / |ω0|
  double start_orientation_error = 0.0;  ///< rad: q(0) from the scenario's (1, 0, 0, 0)
  /// q(0) is off and the rows' q, their components read in x, y, z, w order, are the exact
  /// motion's within the orientation limit at every row (docs/flipcheck.md, "What judge
  /// measures"): the engine wrote q's components in the wrong order.
  bool q_written_xyzw = false;
  double energy_drift = 0.0;               ///< max |E/E0 − 1| over the rows, E0 its own row 0
  double L_drift = 0.0;                    ///< max ||L|/|L0| − 1|
  int flips = 0;                           ///< turn-overs (FlipDetector on every row)
  int flips_exact = 0;                     ///< exact_flip_count over the motion's span
  std::optional<double> first_flip;        ///< time units
  std::optional<double> first_flip_exact;  ///< exact_first_flip, when the exact motion turns over
  std::optional<double> first_flip_error;  ///< |first/exact − 1| (the accuracy table's)
  double half_period = 0.0;                ///< exact T/2 (infinite for steady motion)
  double orientation_error = 0.0;          ///< rad, the largest over the rows, against the exact R
  long long orientation_error_step = 0;    ///< the row (its step) where it is largest
  double L_direction_error = 0.0;          ///< rad, the largest angle of L (world) from exact L
  long long L_direction_error_step = 0;    ///< the row (its step) where it is largest
  long long energy_drift_step = 0;         ///< the row (its step) where energy_drift is largest
  long long L_drift_step = 0;              ///< the row (its step) where L_drift is largest
  long long separatrix_approach_step = 0;  ///< the row where separatrix_approach is largest
  /// The first row (its step) past each row-wise limit, where one is: where a failure starts,
  /// beside the step where it is worst (a motion turned from step 1000 on is worst at 1853).
  std::optional<long long> energy_drift_past, L_drift_past, L_direction_past, orientation_past,
      separatrix_past;
  bool stable_spin = false;             ///< the exact motion stays a spin about axis 1 or 3
  int spin_axis = 0;                    ///< body axis nearest L at t = 0
  std::optional<double> tumble_time;    ///< first |cos(spin axis, L)| < 0.5
  double separatrix_ratio_drift = 0.0;  ///< max |r/r0 − 1|, r = 2E·I2/L²
  double separatrix_approach = 0.0;     ///< max (r − r0)/(1 − r0): 1 = on the separatrix
  std::vector<std::string> failures;    ///< one phrase per failed threshold
  bool pass() const { return failures.empty(); }
};

/// Judges `motion` (rows in increasing step, the first at step 0, spaced by one stride) against
/// the exact motion of `scenario` (physics::ExactRotation from start_omega). Every measure over
/// the rows given; the motion's E, |L| and the cosines from q and ω by physics::
/// rigid_diagnostics (docs/physics.md §9), as the engines' diagnostics are. An internal error
/// for an empty motion or one not starting at step 0 (the reader checks both). Throws
/// InputError "rows every K steps …" when the rows are too far apart to show the exact motion's
/// turn-overs (ConformanceThresholds::sampling_first_flip: a coarse motion is refused, never
/// judged "0 turn-overs"), naming a stride that shows them. `stop` is asked every 4096 rows
/// ("flipcheck judge rows") and throws Interrupted.
Conformance judge_motion(const Scenario& scenario, const std::vector<MotionSample>& motion,
                         const ConformanceThresholds& thresholds = {}, const StopPoll& stop = {});

/// One line: "PASS" or "FAIL (reasons)", then the measures.
std::string verdict_line(const Conformance& c);

/// One motion judged: the file as given (empty for a motion bookspin ran itself), its name in
/// the tables (the file's name, or the method's label: "mujoco rk4") and how it compares.
struct JudgedMotion {
  std::filesystem::path file;
  std::string name;
  Conformance result;
};

/// The judgement as a table (docs/flipcheck.md, "The judgement CSV"): one row per motion, in
/// the order given, named by JudgedMotion::name; every number in shortest round-trip form, an
/// empty cell where a value does not apply (no flip, not a stable spin); its last two columns
/// what judged it: `version` (bookspin's, common/version.hpp) and `scenario_sha256`, the SHA-256
/// of the scenario's JSON as `flipcheck export` writes it (jobs::scenario_file), which the
/// caller hashes and hands in (docs/flipcheck.md, "Versions"). A value, no I/O.
CsvTable judgement_table(const Scenario& scenario, const std::string& scenario_sha256,
                         const std::vector<JudgedMotion>& judged);

/// One motion judged and written as `flipcheck judge` writes it, for the doors that present
/// one judgement (the page's "Judge a motion" panel, the npm package): the judgement CSV's
/// columns, its one row's cells as the command line writes them (csv_text, read back by
/// csv_cells), that header and row as text, verdict_line, the failures (one phrase each) and
/// whether it passes. A value, no I/O.
struct JudgementRow {
  std::vector<std::string> columns;
  std::vector<std::string> cells;
  std::string csv;
  std::string line;
  std::vector<std::string> failures;
  bool pass = false;
};

/// `motion` judged (judge_motion) against `scenario`, named `name` in the table, whose
/// scenario_sha256 is `scenario_sha256`: its JudgementRow. Throws as judge_motion.
JudgementRow judgement_row(const Scenario& scenario, const std::string& scenario_sha256,
                           const std::vector<MotionSample>& motion, const std::string& name);

/// The judge's rules as text, one "name value" a line: every threshold of the default
/// ConformanceThresholds, the tumble's cosine, the flip detector's margin and the judgement
/// CSV's columns. Hashed with the scenarios into the kit's SHA-256 that VERSION records
/// (docs/flipcheck.md, "Versions"): a rule changed here changes it.
std::string judge_rules();

}  // namespace bookspin::analysis
