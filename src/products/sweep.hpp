#pragma once
// The sweep product (`bookspin sweep`, docs/physics.md §14): a parameter sweep's CSV and
// plots with their manifest, one shard's CSV of a job array, or the merge of shards. Every
// path a sweep writes is named here; the runs, the table and the shard format are the jobs
// stage's (jobs/sweep.hpp).
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "cache/freshness.hpp"
#include "common/stop.hpp"
#include "jobs/sweep.hpp"

namespace bookspin::products {

/// Where a sweep's files go.
struct SweepPaths {
  std::filesystem::path csv;  ///< the full CSV
  std::filesystem::path png;  ///< its plots
  /// The CSV of shard k of n (k from 0).
  std::function<std::filesystem::path(int k, int n)> shard;
};

/// Every path a sweep of the scene called `scene_name` into `out_dir` writes:
/// OUT/<name>-sweep.csv, OUT/<name>-sweep.png, shards OUT/<name>-sweep.shard-K-of-N.csv.
SweepPaths sweep_paths(const std::filesystem::path& out_dir, const std::string& scene_name);

/// OUT/<name>/sweep-manifest.json.
std::filesystem::path sweep_manifest_path(const std::filesystem::path& out_dir,
                                          const std::string& scene_name);

/// What `bookspin sweep SCENE` asks for.
struct SweepJob {
  std::filesystem::path scene_path;
  std::vector<std::string> overrides;  ///< the user's --set, before the grid's own
  std::vector<std::string> vary;       ///< "KEY=START:STOP:COUNT[:log]" as given
  std::string measures;                ///< "first_flip,flip_period,…" as given
  int jobs = 0;                        ///< threads; 0: hardware threads
  /// Shard k of n (k from 0); n = 0: the whole grid, which is cached by its manifest.
  int shard_index = 0, shard_count = 0;
  std::filesystem::path out_dir;
  cache::Freshness freshness;  ///< --force, --verify (the CSV's and PNG's hashes), remake note
  StopPoll stop_signal;        ///< polled by the workers (jobs::SweepRequest)
};

struct SweepOutcome {
  cache::Outcome outcome = cache::Outcome::made;
  std::string name;                            ///< the scene's name
  std::vector<std::filesystem::path> written;  ///< when made
  /// When made: the points the engine refused (their rows' `refused` cell) and the first's
  /// reason.
  std::size_t refused = 0, points = 0;
  std::string first_refusal;
};

/// (scene, ranges, measures) => OUT/<scene>-sweep.csv and -sweep.png + manifest, or with a
/// shard K/N => OUT/<scene>-sweep.shard-K-of-N.csv.
/// Parses the scene, the ranges and the measures (InputError naming what is wrong), then
/// measures the sweep (jobs::measure_sweep) unless its manifest says it is up to date (a shard
/// is always measured and has no manifest), and writes its CSV and picture, or the shard
/// (jobs::sweep_shard_text). Throws InputError, OutputError, Interrupted.
SweepOutcome make_sweep(const SweepJob& job);

/// shards => OUT/<scene>-sweep.csv and -sweep.png.
/// Reads shard CSVs into their sweep's table (jobs::read_sweep_shards; a missing shard is
/// named beside the given ones) and writes the one-process sweep's CSV and picture, byte for
/// byte. Returns the paths written. Throws InputError naming the file (and line), OutputError.
std::vector<std::filesystem::path> merge_sweep_shards(
    const std::vector<std::filesystem::path>& shards, const std::filesystem::path& out_dir);

}  // namespace bookspin::products
