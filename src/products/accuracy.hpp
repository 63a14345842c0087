#pragma once
// The accuracy product (`bookspin accuracy`, docs/accuracy.md): every method against the
// exact motion as a table, a CSV and plots, with its manifest (docs/outputs.md). Every path
// it writes is named here; the measuring is the jobs stage's (jobs/accuracy_report.hpp). An
// unchanged report is not measured again: its ns/step column is the timing of the run that
// made it.
#include <filesystem>
#include <string>
#include <vector>

#include "cache/freshness.hpp"
#include "jobs/accuracy_report.hpp"

namespace bookspin::products {

/// Every path an accuracy report of one scene into OUT writes.
struct AccuracyLayout {
  std::filesystem::path csv;                 ///< OUT/<name>-accuracy.csv: a row per method, dt
  std::filesystem::path png;                 ///< OUT/<name>-accuracy.png: error against dt
  std::filesystem::path work_precision_png;  ///< OUT/<name>-work-precision.png: against cost
  std::filesystem::path energy_vs_dt_png;    ///< OUT/<name>-energy-vs-dt.png
  std::filesystem::path turnovers_png;       ///< OUT/<name>-turnovers.png: counted / exact
  std::filesystem::path energy_png;          ///< OUT/<name>-energy.png: the long-time energy
  std::filesystem::path energy_csv;          ///< OUT/<name>-energy.csv: its data
  std::filesystem::path manifest;            ///< OUT/<name>/accuracy-manifest.json
  /// The report's files in the order the report writes them.
  std::vector<std::filesystem::path> outputs() const;
};

/// The layout of `scene`'s accuracy report in `out_dir`. No I/O.
AccuracyLayout accuracy_layout(const std::filesystem::path& out_dir, const scene::Scene& scene);

/// What `bookspin accuracy` asks for: the jobs stage's request, and where.
struct AccuracyJob {
  jobs::AccuracyRequest request;
  std::filesystem::path out_dir;
  cache::Freshness
      freshness;  ///< --force (measure even when up to date), --verify, the remake note
};

/// The manifest head of `job` ("accuracy", the flips, the dt list and the methods, the
/// scene). Throws InputError.
std::string accuracy_manifest_head(const AccuracyJob& job);

/// (scene, flips, dts, methods) => OUT/<scene>-accuracy.csv, its four plots, -energy.csv +
/// manifest.
/// Unless its manifest says the report is up to date: measures it (jobs::measure_accuracy),
/// draws its plots (charts::accuracy_images) and writes the accuracy layout, then the
/// manifest. Same errors as jobs::measure_accuracy, and OutputError.
cache::Outcome make_accuracy(const AccuracyJob& job);

}  // namespace bookspin::products
