#pragma once
// The accuracy product (`bookspin accuracy`, docs/accuracy.md): every method against the
// exact motion as a table, a CSV and plots, with its manifest (docs/outputs.md). Every path
// it writes is named here; the measuring is the jobs stage's (jobs/accuracy_report.hpp). An
// unchanged report is not measured again: its ns/step column is the timing of the run that
// made it.
#include <filesystem>
#include <string>
#include <vector>

#include "jobs/accuracy_report.hpp"
#include "products/outcome.hpp"

namespace bookspin::products {

/// Every path an accuracy report of one scene into OUT writes.
struct AccuracyLayout {
  /// OUT/<name>-accuracy.csv, -accuracy.png, -work-precision.png, -energy-vs-dt.png,
  /// -energy.png and -energy.csv.
  jobs::AccuracyPaths report;
  std::filesystem::path manifest;  ///< OUT/<name>/accuracy-manifest.json
  /// The report's files in the order the report writes them.
  std::vector<std::filesystem::path> outputs() const;
};

/// The layout of `scene`'s accuracy report in `out_dir`. No I/O.
AccuracyLayout accuracy_layout(const std::filesystem::path& out_dir, const scene::Scene& scene);

/// What `bookspin accuracy` asks for: the jobs stage's request, with its paths left to
/// accuracy_layout().
struct AccuracyJob {
  jobs::AccuracyRequest request;  ///< everything but request.paths
  std::filesystem::path out_dir;
  Freshness freshness;  ///< --force (measure even when up to date), --verify, the remake note
};

/// The manifest head of `job` ("accuracy", the flips, the dt list and the methods, the
/// scene). Throws InputError.
std::string accuracy_manifest_head(const AccuracyJob& job);

/// Runs the report (jobs::run_accuracy: measured, then written) into the accuracy layout unless
/// its manifest says it is up to date, then writes the manifest. Same errors as
/// jobs::run_accuracy.
Outcome make_accuracy(const AccuracyJob& job);

}  // namespace bookspin::products
