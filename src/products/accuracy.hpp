#pragma once
// The accuracy product (`bookspin accuracy`, docs/accuracy.md): every method against the
// exact motion as a table, a CSV and plots. Every path it writes is named here; the
// measuring is the jobs stage's (jobs/accuracy_report.hpp). Not cached: each run measures
// anew (its ns/step column is a timing).
#include <filesystem>
#include <vector>

#include "jobs/accuracy_report.hpp"

namespace bookspin::products {

/// Every path an accuracy report of `scene` into `out_dir` writes: OUT/<name>-accuracy.csv,
/// -accuracy.png, -work-precision.png, -energy.png and -energy.csv.
jobs::AccuracyPaths accuracy_paths(const std::filesystem::path& out_dir, const scene::Scene& scene);

/// What `bookspin accuracy` asks for: the jobs stage's request, with its paths left to
/// accuracy_paths().
struct AccuracyJob {
  jobs::AccuracyRequest request;  ///< everything but request.paths
  std::filesystem::path out_dir;
};

/// Runs the report (jobs::run_accuracy) into the accuracy layout. Returns the paths
/// written. Same errors as jobs::run_accuracy.
std::vector<std::filesystem::path> make_accuracy(const AccuracyJob& job);

}  // namespace bookspin::products
