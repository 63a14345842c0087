// `bookspin sweep`: parses the ranges, measures and shard, and calls the pipeline
// (docs/physics.md §14).
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cache/freshness.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/subcommand.hpp"
#include "common/errors.hpp"
#include "products/sweep.hpp"

namespace bookspin::cli {

namespace {

struct SweepOptions {
  std::string scene_path;              ///< empty with --merge
  std::vector<std::string> overrides;  ///< --set, before the grid's own
  std::vector<std::string> vary;       ///< "KEY=START:STOP:COUNT[:log]"
  std::string measures;                ///< "first_flip,flip_period,…"
  int jobs = 0;                        ///< threads; 0 = hardware threads
  std::string shard;                   ///< "K/N", K from 0; empty = the whole grid
  std::string out_dir = "out";
  std::vector<std::string> merge;  ///< shard CSVs to merge instead of running
  bool force = false;   ///< run even when OUT/<scene>/sweep-manifest.json says up to date
  bool verify = false;  ///< up-to-date check hashes the CSV and PNG (else sizes only)
};

/// "K/N" with 0 ≤ K < N (K counts from 0, as SLURM_ARRAY_TASK_ID with --array=0-(N-1)).
void parse_shard(const std::string& text, int& k, int& n) {
  const auto slash = text.find('/');
  char* end_k = nullptr;
  char* end_n = nullptr;
  const std::string k_text = text.substr(0, slash);
  const std::string n_text = slash == std::string::npos ? "" : text.substr(slash + 1);
  const long kk = std::strtol(k_text.c_str(), &end_k, 10);
  const long nn = std::strtol(n_text.c_str(), &end_n, 10);
  if (k_text.empty() || n_text.empty() || *end_k != '\0' || *end_n != '\0' || nn < 1 ||
      nn > 1000000 || kk < 0 || kk >= nn) {
    throw InputError("--shard " + text +
                     ": expected K/N with 0 <= K < N (K counts from 0, like "
                     "SLURM_ARRAY_TASK_ID with --array=0-(N-1))");
  }
  k = static_cast<int>(kk);
  n = static_cast<int>(nn);
}

/// Runs a parameter sweep (physics only, docs/physics.md §14) and writes
/// OUT/<scene>-sweep.csv and .png, or one shard's CSV, or merges shard CSVs.
int sweep_command(const SweepOptions& options) {
  std::vector<std::filesystem::path> written;
  if (!options.merge.empty()) {
    if (!options.scene_path.empty() || !options.vary.empty() || !options.measures.empty() ||
        !options.shard.empty()) {
      throw InputError(
          "sweep --merge: takes only the shard files and -o (the sweep is in their first line)");
    }
    for (const auto& file : options.merge) written.emplace_back(file);
    written = products::merge_sweep_shards(written, options.out_dir);
  } else {
    if (options.scene_path.empty()) throw InputError("sweep: give a SCENE file (or --merge FILE…)");
    products::SweepJob job;
    job.scene_path = options.scene_path;
    job.overrides = options.overrides;
    job.vary = options.vary;
    job.measures = options.measures;
    if (options.jobs < 0) throw InputError("-j " + std::to_string(options.jobs) + ": must be >= 0");
    job.jobs = options.jobs;
    if (!options.shard.empty()) parse_shard(options.shard, job.shard_index, job.shard_count);
    job.out_dir = options.out_dir;
    job.freshness = {options.force, options.verify, remake_note};
    job.stop_signal = stop_poll();
    const products::SweepOutcome done = products::make_sweep(job);
    if (done.outcome == cache::Outcome::up_to_date) {
      std::cout << "up to date: " << done.name << "-sweep" << std::endl;
      return kExitOk;
    }
    written = done.written;
    if (done.refused > 0)
      std::cerr << "bookspin: note: the engine refused " << done.refused << " of the "
                << done.points << " points (first: " << done.first_refusal
                << "); their rows' refused column says why" << std::endl;
  }
  for (const auto& path : written) std::printf("wrote %s\n", path.c_str());
  return kExitOk;
}

}  // namespace

Subcommand add_sweep(CLI::App& cli) {
  const auto stored = std::make_shared<SweepOptions>();
  SweepOptions& options = *stored;
  CLI::App* cmd = cli.add_subcommand(
      "sweep",
      "Physics-only runs over a grid of scene values, measured: one CSV row per point and a plot");
  cmd->add_option("SCENE", options.scene_path, "Scene file (TOML), one model (no [[compare]])");
  cmd->add_option("--set", options.overrides, kSetHelp)->take_all()->allow_extra_args(false);
  cmd->add_option("--vary", options.vary,
                  "KEY=START:STOP:COUNT[:log] (repeatable; the grid is the product, the first "
                  "--vary slowest), KEY a scalar scene key or a component such as "
                  "initial.angular_velocity[1]")
      ->allow_extra_args(false);
  cmd->add_option("--measure", options.measures,
                  "Comma-separated: first_flip, flip_period, energy_drift, orientation_error, "
                  "diverged_at, twist");
  cmd->add_option("-j,--jobs", options.jobs, "Threads (0 = hardware threads)")
      ->capture_default_str();
  cmd->add_option("--shard", options.shard,
                  "K/N: only grid points with index = K mod N (K from 0, as SLURM_ARRAY_TASK_ID); "
                  "writes OUT/<scene>-sweep.shard-K-of-N.csv");
  add_out_option(cmd, options.out_dir, "Output directory");
  cmd->add_option("--merge", options.merge,
                  "Merge shard CSVs into OUT/<scene>-sweep.csv and .png instead of running")
      ->allow_extra_args(true);
  add_freshness_flags(cmd, options.force, options.verify, "OUT/<scene>/sweep-manifest.json");
  return {cmd, [stored] { return sweep_command(*stored); }};
}

}  // namespace bookspin::cli
