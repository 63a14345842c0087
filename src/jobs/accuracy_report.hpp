#pragma once
// `bookspin accuracy`: every model × integrator × dt against the exact motion, as a table,
// a CSV and plots (docs/physics.md §8, §10).
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "charts/accuracy_plots.hpp"
#include "common/stop.hpp"
#include "scene/scene.hpp"

namespace bookspin::jobs {

/// Where the report goes (the accuracy product names every path).
struct AccuracyPaths {
  std::filesystem::path csv;  ///< one row per method and dt
  std::filesystem::path png;  ///< error against dt, log–log
  charts::AccuracyPlotPaths plots;
};

struct AccuracyRequest {
  scene::Scene scene;  ///< the book, initial spin and model toggles
  AccuracyPaths paths;
  double flips = 10.0;      ///< run length in exact flip periods
  std::vector<double> dts;  ///< time steps to try, time units
  /// The methods to measure (analysis::parse_methods()); empty: analysis::accuracy_methods().
  std::vector<analysis::Method> methods;
  /// Receives the table, a line at a time as each row is measured (no newline).
  std::function<void(const std::string& line)> on_line;
  /// Polled before and after each run ("accuracy runs") and inside it every few dozen steps
  /// ("accuracy steps"), and so in the long-time energy runs (charts::write_accuracy_plots): a
  /// signal throws Interrupted before any file is written. May be empty.
  StopPoll stop_signal;
};

/// The most steps one method may take at one dt (flips × flip period / dt).
inline constexpr double kMaxAccuracySteps = 1e8;

/// The accuracy CSV's column names, in order (docs/accuracy.md): model, integrator, dt, steps,
/// t_end, orientation_error_rad, …, flips, flips_exact; one row per method and dt.
const std::vector<std::string>& accuracy_csv_columns();

/// Measures every method of `request.methods` at every dt and writes the CSV, the error plot,
/// the work–precision plot, the energy error against dt, the energy plot and its CSV. Returns the
/// paths written. The CSV's flip_period and flip_period_error cells are empty where fewer than two
/// flips were seen. Throws InputError (the motion has no flip period, a dt that makes fewer
/// than 1 or more than kMaxAccuracySteps steps), OutputError.
std::vector<std::filesystem::path> run_accuracy(const AccuracyRequest& request);

}  // namespace bookspin::jobs
