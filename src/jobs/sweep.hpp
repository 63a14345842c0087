#pragma once
// Parameter sweeps (`bookspin sweep`, docs/physics.md §14), the jobs stage's door to them:
// one physics-only run per grid point, in parallel threads, measured into one table of one row
// per point (the whole grid, or a shard of it for job arrays); the table as its picture reads
// it. The grid is sweep_grid.hpp's, the table and its CSV sweep_csv.hpp's, the shard format
// and the merge of shards sweep_shard.hpp's, the picture charts/sweep_plots.hpp's; the files
// are the sweep product's (products/sweep.hpp).
#include <optional>
#include <string>
#include <vector>

#include "charts/sweep_plots.hpp"
#include "common/stop.hpp"
#include "jobs/sweep_csv.hpp"
#include "jobs/sweep_grid.hpp"
#include "scene/scene.hpp"

namespace bookspin::jobs {

struct SweepRequest {
  std::filesystem::path scene_path;
  std::vector<std::string> overrides;  ///< the user's own --set, applied before the grid's
  /// scene_path parsed with `overrides`, when the caller has it already (it is then not
  /// parsed again); empty: measure_sweep parses it.
  std::optional<scene::Scene> scene;
  std::vector<VaryRange> ranges;
  MeasureList measures;
  int jobs = 0;  ///< threads; 0 = std::thread::hardware_concurrency()
  /// --shard K/N: only the grid points with index ≡ K (mod N), K from 0 to N − 1 (as Slurm's
  /// SLURM_ARRAY_TASK_ID runs with --array=0-(N-1)). shard_count 0: the whole grid.
  int shard_index = 0, shard_count = 0;
  /// Polled by the workers before each point ("sweep point") and by each running point's
  /// physics loop ("sweep steps", every analysis::kStopPollSteps steps): the signal asking the
  /// sweep to stop (SIGINT, SIGTERM), or 0. Running points are then abandoned and Interrupted
  /// is thrown. May be empty.
  StopPoll stop_signal;
};

/// (scene, ranges, measures, shard) => the table of the grid's points (or the shard's).
/// Parses every point's scene first (a bad value is the scene's InputError, naming the key,
/// before any run), runs them on `jobs` threads and returns their rows in grid order. No files.
/// A point whose value the model's engine cannot run (scene::EngineRefusal: ODE's subnormal
/// dt, MuJoCo's smallest mass and moment) is not run: its row's `refused` cell says why.
/// Throws InputError for a comparison scene, or when the engine refuses every point (the
/// first refusal's message); Interrupted when request.stop_signal answers a signal.
SweepTable measure_sweep(const SweepRequest& request);

/// `table` as its picture reads it (charts::sweep_sheet): the ranges as axes, the rows' cells
/// without their grid index.
charts::SweepChart sweep_chart(const SweepTable& table);

}  // namespace bookspin::jobs
