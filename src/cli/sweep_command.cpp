// `bookspin sweep`: parses the ranges, measures and shard, and calls the pipeline
// (docs/physics.md §14).
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <optional>

#include "cache/freshness.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "common/errors.hpp"
#include "products/sweep.hpp"

namespace bookspin::cli {

namespace {

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

}  // namespace

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
  }
  for (const auto& path : written) std::printf("wrote %s\n", path.c_str());
  return kExitOk;
}

}  // namespace bookspin::cli
