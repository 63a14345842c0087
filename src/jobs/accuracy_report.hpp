#pragma once
// `bookspin accuracy`: every model × integrator × dt against the exact motion, as a table,
// a CSV and plots (docs/physics.md §8, §10). Measured first, into one value (AccuracyReport);
// then that value is handed once to the writer of the report's files.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "analysis/accuracy.hpp"
#include "common/stop.hpp"
#include "scene/scene.hpp"

namespace bookspin::jobs {

/// Where the report goes (the accuracy product names every path).
struct AccuracyPaths {
  std::filesystem::path csv;                 ///< one row per method and dt
  std::filesystem::path png;                 ///< error against dt, log–log
  std::filesystem::path work_precision_png;  ///< error against cost, from the rows
  std::filesystem::path energy_vs_dt_png;    ///< energy error against dt, from the rows
  std::filesystem::path energy_png;          ///< the long-time energy plot
  std::filesystem::path energy_csv;          ///< its data: t, one column per method
};

/// The settings of the long-time energy plot: each of its methods at dt = 1/60 over 100 flip
/// periods, in 400 windows.
inline constexpr double kLongTimeFlips = 100.0;
inline constexpr double kLongTimeDt = 1.0 / 60.0;
inline constexpr int kLongTimeWindows = 400;

struct AccuracyRequest {
  scene::Scene scene;  ///< the book, initial spin and model toggles
  AccuracyPaths paths;
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

/// Everything one report measures, in one value: what write_accuracy_report() writes.
struct AccuracyReport {
  double flips = 0.0;                       ///< run length of the rows, in exact flip periods
  std::vector<analysis::Method> methods;    ///< the methods measured, in the table's order
  std::vector<analysis::AccuracyRow> rows;  ///< one per method and dt, method by method
  /// The long-time energy plot's histories (long_time_methods(methods), kLongTimeDt,
  /// kLongTimeFlips, kLongTimeWindows), one per method.
  std::vector<analysis::EnergyHistory> energy;
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

/// Writes `report` to `paths`: the CSV (its flip_period and flip_period_error cells empty where
/// fewer than two flips were seen), the error plot, the work–precision plot, the energy error
/// against dt, the energy plot and its CSV. Returns the paths written, in that order. Throws
/// OutputError.
std::vector<std::filesystem::path> write_accuracy_report(const AccuracyPaths& paths,
                                                         const AccuracyReport& report);

/// write_accuracy_report(request.paths, measure_accuracy(request)).
std::vector<std::filesystem::path> run_accuracy(const AccuracyRequest& request);

}  // namespace bookspin::jobs
