#pragma once
// Parameter sweeps (`bookspin sweep`, docs/physics.md §14), the jobs stage's door to them:
// one physics-only run per grid point, in parallel threads, measured and written as one CSV
// row per point plus a picture; shards of the grid for job arrays, and their merge. The grid
// is sweep_grid.hpp's, the table and its CSV sweep_csv.hpp's, the shard format
// sweep_shard.hpp's, the picture charts/sweep_plots.hpp's.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "common/stop.hpp"
#include "jobs/sweep_csv.hpp"
#include "jobs/sweep_grid.hpp"
#include "scene/scene.hpp"

namespace bookspin::jobs {

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
/// before any run), runs them on `jobs` threads, and writes the layout's CSV and picture
/// (charts::sweep_sheet: line plots, or for two keys a heat map per measure), or for a shard
/// only the layout's shard CSV (write_sweep_shard). Returns the paths written. Throws
/// InputError for a comparison scene, OutputError when a file cannot be written.
SweepResult run_sweep(const SweepRequest& request);

/// Reads shard CSVs into their sweep's table (read_sweep_shards: every shard of one sweep, its
/// grid covered exactly once; a missing shard is named by the layout's shard path) and writes
/// the layout's CSV and picture, byte-identical to the one-process sweep's. Throws InputError
/// naming the file (and line), OutputError when a file cannot be written.
std::vector<std::filesystem::path> merge_sweep(const std::vector<std::filesystem::path>& shards,
                                               const SweepLayout& layout);

}  // namespace bookspin::jobs
