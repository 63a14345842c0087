#pragma once
// `bookspin accuracy`: every model × integrator × dt against the exact motion, as a table,
// a CSV and plots (docs/physics.md §8, §10).
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace bookspin::jobs {

struct AccuracyRequest {
  scene::Scene scene;  ///< the book, initial spin and model toggles
  std::filesystem::path out_dir;
  double flips = 10.0;      ///< run length in exact flip periods
  std::vector<double> dts;  ///< time steps to try, time units
  /// Receives the table, a line at a time as each row is measured (no newline).
  std::function<void(const std::string& line)> on_line;
};

/// The most steps one method may take at one dt (flips × flip period / dt).
inline constexpr double kMaxAccuracySteps = 1e8;

/// Measures every method of analysis::all_methods() at every dt and writes, under OUT,
/// <scene>-accuracy.csv, <scene>-accuracy.png (error against dt, log–log),
/// <scene>-work-precision.png, <scene>-energy.png and <scene>-energy.csv. Returns the paths
/// written. The CSV's flip_period and flip_period_error cells are empty where fewer than two
/// flips were seen. Throws InputError (the motion has no flip period, a dt that makes fewer
/// than 1 or more than kMaxAccuracySteps steps), OutputError.
std::vector<std::filesystem::path> run_accuracy(const AccuracyRequest& request);

}  // namespace bookspin::jobs
