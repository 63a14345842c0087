#pragma once
// `bookspin accuracy`: every model × integrator × dt against the exact motion (docs/physics.md
// §8, §10), measured into one value (AccuracyReport), and that value as the report's two CSV
// tables. Its plots are the charts stage's (charts/accuracy_plots.hpp), its files the accuracy
// product's (products/accuracy.hpp).
#include <functional>
#include <string>
#include <vector>

#include "analysis/accuracy.hpp"
#include "common/csv_writer.hpp"
#include "common/stop.hpp"
#include "scene/scene.hpp"

namespace bookspin::jobs {

/// The settings of the long-time energy plot: each of its methods at dt = 1/60 over 100 flip
/// periods, in 400 windows.
inline constexpr double kLongTimeFlips = 100.0;
inline constexpr double kLongTimeDt = 1.0 / 60.0;
inline constexpr int kLongTimeWindows = 400;

struct AccuracyRequest {
  scene::Scene scene;       ///< the book, initial spin and model toggles
  double flips = 10.0;      ///< run length in exact flip periods
  std::vector<double> dts;  ///< time steps to try, time units
  /// The methods to measure (analysis::parse_methods()); empty: analysis::accuracy_methods().
  std::vector<analysis::Method> methods;
  /// Receives the table, a line at a time as each row is measured (no newline).
  std::function<void(const std::string& line)> on_line;
  /// Polled before and after each run ("accuracy runs", "accuracy energy") and inside it every
  /// few dozen steps ("accuracy steps", "accuracy energy steps"): a signal throws Interrupted
  /// before any file is written. May be empty.
  StopPoll stop_signal;
};

/// Everything one report measures, in one value.
struct AccuracyReport {
  double flips = 0.0;                       ///< run length of the rows, in exact flip periods
  std::vector<analysis::Method> methods;    ///< the methods measured, in the table's order
  std::vector<analysis::AccuracyRow> rows;  ///< one per method and dt, method by method
  /// The long-time energy plot's histories (long_time_methods(methods), kLongTimeDt,
  /// kLongTimeFlips, kLongTimeWindows), one per method.
  std::vector<analysis::EnergyHistory> energy;
  CsvTable table;          ///< the accuracy CSV of the above (accuracy_csv)
  CsvTable energy_table;   ///< the long-time energy CSV of the above (energy_csv)
  double spin_rate = 0.0;  ///< |ω0| of the scene's start, rad per time unit (the charts' titles)
};

/// The most steps one method may take at one dt (flips × flip period / dt).
inline constexpr double kMaxAccuracySteps = 1e8;

/// The accuracy CSV's column names, in order (docs/accuracy.md): model, integrator, dt, steps,
/// t_end, orientation_error_rad, …, flips, flips_exact; one row per method and dt.
const std::vector<std::string>& accuracy_csv_columns();

/// The methods of the long-time energy plot for a report of `methods`: the rigid pairs
/// (analysis::rigid_methods()) when `methods` is every method (analysis::accuracy_methods()),
/// else every method of `methods` but the particle model's.
std::vector<analysis::Method> long_time_methods(const std::vector<analysis::Method>& methods);

/// Measures every method of `request.methods` at every dt, then the long-time energy
/// histories; the table goes to request.on_line as it is measured. No files. Throws
/// InputError (the motion has no flip period, a dt that makes fewer than 1 or more than
/// kMaxAccuracySteps steps), Interrupted.
AccuracyReport measure_accuracy(const AccuracyRequest& request);

/// The accuracy CSV of `report` (accuracy_csv_columns()), one row per method and dt: a cell is
/// empty where there is no value (no orientation error after a divergence, no flip period
/// where fewer than two flips were seen, no first flip where none was; docs/outputs.md,
/// "Numbers").
CsvTable accuracy_csv(const AccuracyReport& report);

/// The long-time energy CSV of `report`: t, then one column per history
/// (analysis::Method::label); a diverged run's history is shorter, and its missing windows stay
/// empty.
CsvTable energy_csv(const AccuracyReport& report);

}  // namespace bookspin::jobs
