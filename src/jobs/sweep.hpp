#pragma once
// Parameter sweeps (`bookspin sweep`, docs/physics.md §14): one physics-only run per grid
// point, in parallel threads, measured and written as one CSV row per point plus a plot;
// shards of the grid for job arrays, and their merge.
#include <Eigen/Dense>
#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "analysis/measures.hpp"
#include "common/stop.hpp"
#include "jobs/sweep_grid.hpp"
#include "overlay/plot.hpp"
#include "physics/simulator.hpp"
#include "scene/scene.hpp"

namespace bookspin::jobs {

/// The measures a sweep writes, in the order given: rows of analysis::measure_table().
using MeasureList = std::vector<const analysis::Measure*>;

/// Parses "first_flip,flip_period,…" (comma-separated names of analysis::measure_table(), no
/// repeats). Throws InputError ("--measure TEXT: reason") on an unknown or repeated name or
/// an empty list.
MeasureList parse_measures(const std::string& text);

/// A sweep's table: the varied keys, the measures, and the exact reference columns
/// (`first_flip_exact` where first_flip is measured, `flip_period_exact` likewise).
struct SweepTable {
  std::string scene_name;
  std::vector<VaryRange> ranges;
  MeasureList measures;
  std::vector<std::string> header;  ///< CSV column names, in order
  /// (grid index, cells) per row, cells as written (%.17g or empty), sorted by index.
  std::vector<std::pair<std::size_t, std::vector<std::string>>> rows;
};

/// Where a sweep's files go: the sweep product names them (products/sweep.hpp).
struct SweepPaths {
  std::filesystem::path csv;  ///< the full CSV
  std::filesystem::path png;  ///< its plots
  /// The CSV of shard k of n (k from 0).
  std::function<std::filesystem::path(int k, int n)> shard;
};

/// The paths of the sweep of the scene called `scene_name`.
using SweepLayout = std::function<SweepPaths(const std::string& scene_name)>;

struct SweepRequest {
  std::filesystem::path scene_path;
  std::vector<std::string> overrides;  ///< the user's own --set, applied before the grid's
  /// scene_path parsed with `overrides`, when the caller has it already (it is then not
  /// parsed again); empty: run_sweep parses it.
  std::optional<scene::Scene> scene;
  std::vector<VaryRange> ranges;
  MeasureList measures;
  int jobs = 0;  ///< threads; 0 = std::thread::hardware_concurrency()
  /// --shard K/N: only the grid points with index ≡ K (mod N), K from 0 to N − 1 (as Slurm's
  /// SLURM_ARRAY_TASK_ID runs with --array=0-(N-1)). shard_count 0: the whole grid.
  int shard_index = 0, shard_count = 0;
  SweepLayout layout;  ///< where the CSV, the plots or the shard go
  /// Polled by the workers before each point ("sweep point") and by each running point's
  /// physics loop ("sweep steps", every analysis::kStopPollSteps steps): the signal asking the
  /// sweep to stop (SIGINT, SIGTERM), or 0. Running points are then abandoned and nothing is
  /// written. May be empty.
  StopPoll stop_signal;
};

struct SweepResult {
  std::vector<std::filesystem::path> written;
  int signal = 0;  ///< the stop signal that ended the sweep early (nothing written), or 0
};

/// Parses every point's scene first (a bad value is the scene's InputError, naming the key,
/// before any run), runs them on `jobs` threads, and writes the layout's CSV and plots
/// (sweep_plots; for two keys a heat map per measure, charts::heat_map_sheet), or for a shard
/// only the layout's shard CSV (a first
/// line "# bookspin sweep shard …" recording the scene name, the SHA-256 of the resolved
/// scene in canonical form after --set (scene::canonical_json), bookspin's build id, the grid
/// size, the ranges and the measures, then a grid_index column before the full CSV's;
/// docs/physics.md §14). Returns the paths written. Throws InputError
/// for a comparison scene, OutputError when a file cannot be written.
SweepResult run_sweep(const SweepRequest& request);

/// Reads shard CSVs (LF or CRLF line endings), checks they are shards of one sweep (same
/// scene name, scene SHA-256, build, grid, measures and N; same header) that cover its grid
/// exactly once, and writes the layout's CSV and plots, byte-identical to the
/// one-process sweep's. Throws InputError naming the file (and line): unreadable, not a
/// shard, a shard line without scene hash or build, another sweep (naming the first field
/// that differs), a mismatched header, a row of another shard or an index outside the grid, a
/// cell that is not a finite number (empty is allowed for a measure, not for a varied value),
/// a duplicate grid point, a missing one (naming the shard file that should hold it).
std::vector<std::filesystem::path> merge_sweep(const std::vector<std::filesystem::path>& shards,
                                               const SweepLayout& layout);

/// The full CSV's column names, in order: the varied keys (VaryRange::key), the measures'
/// names, then the exact columns (Measure::exact_name) of the measures that have one.
std::vector<std::string> sweep_csv_header(const std::vector<VaryRange>& ranges,
                                          const MeasureList& measures);

/// Writes the full CSV (header, then one line per row without the grid index) to `out`.
void write_sweep_csv(const SweepTable& table, std::ostream& out);

/// One plot per measure against the first varied key (log axis where it was :log), one line
/// per combination of the other keys' values, the exact curve dashed beside the measured one.
std::vector<overlay::PlotSpec> sweep_plots(const SweepTable& table);

}  // namespace bookspin::jobs
