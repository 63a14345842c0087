// `bookspin sweep`: parses the ranges, measures and shard, and calls the pipeline
// (docs/physics.md §14).
#include <cstdio>
#include <cstdlib>
#include <optional>

#include "cache/manifests.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "common/errors.hpp"
#include "jobs/sweep.hpp"
#include "output/manifest.hpp"
#include "scene/canonical.hpp"

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

/// The sweep's output options for its manifest: the ranges and the measures as given.
std::string sweep_options_json(const SweepOptions& options) {
  std::string json = "    \"vary\": [";
  for (std::size_t i = 0; i < options.vary.size(); ++i)
    json.append(i == 0 ? "" : ", ").append(scene::json_string(options.vary[i]));
  return json.append("],\n    \"measures\": ")
      .append(scene::json_string(options.measures))
      .append("\n");
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
    written = jobs::merge_sweep(written, options.out_dir);
  } else {
    if (options.scene_path.empty()) throw InputError("sweep: give a SCENE file (or --merge FILE…)");
    jobs::SweepRequest request;
    request.scene_path = options.scene_path;
    request.overrides = options.overrides;
    for (const auto& v : options.vary) request.ranges.push_back(jobs::parse_vary(v));
    if (options.measures.empty()) throw InputError("sweep: give --measure M[,M…]");
    request.measures = jobs::parse_measures(options.measures);
    if (options.jobs < 0) throw InputError("-j " + std::to_string(options.jobs) + ": must be >= 0");
    request.jobs = options.jobs;
    if (!options.shard.empty())
      parse_shard(options.shard, request.shard_index, request.shard_count);
    request.out_dir = options.out_dir;
    request.stop_signal = interrupt_signal;
    // A whole sweep (not a shard) skips when its manifest says it is up to date
    // (output/manifest.hpp), like render and plot.
    jobs::SweepResult result;
    if (!options.shard.empty()) {
      result = jobs::run_sweep(request);
    } else {
      request.scene = scene::parse_scene(options.scene_path, options.overrides);
      const scene::Scene& scene = *request.scene;
      const cache::CacheOutcome outcome = run_cached(
          {std::filesystem::path(options.out_dir) / scene.name / "sweep-manifest.json",
           cache::manifest_head("sweep", sweep_options_json(options), scene), options.out_dir,
           options.force, options.verify,
           [&]() -> std::optional<cache::JobOutputs> {
             result = jobs::run_sweep(request);
             if (result.signal != 0) return std::nullopt;
             cache::JobOutputs made{cache::manifest_note(scene), {}};
             for (const auto& path : result.written)
               made.outputs.push_back(path.lexically_relative(options.out_dir).generic_string());
             return made;
           }},
          scene.name + "-sweep");
      if (outcome == cache::CacheOutcome::up_to_date) return kExitOk;
    }
    if (result.signal != 0) {
      std::fprintf(stderr, "bookspin: sweep interrupted; nothing written\n");
      return 128 + result.signal;
    }
    written = result.written;
  }
  for (const auto& path : written) std::printf("wrote %s\n", path.c_str());
  return kExitOk;
}

}  // namespace bookspin::cli
