#include "products/sweep.hpp"

#include "cache/manifest_head.hpp"
#include "common/errors.hpp"

namespace bookspin::products {

namespace fs = std::filesystem;

namespace {

/// DIR/<name>-sweep.shard-K-of-N.csv.
std::function<fs::path(int, int)> shard_in(const fs::path& dir, const std::string& name) {
  return [dir, name](int k, int n) {
    return dir / (name + "-sweep.shard-" + std::to_string(k) + "-of-" + std::to_string(n) + ".csv");
  };
}

/// The sweep's output options for its manifest: the ranges and the measures as given.
JsonObject sweep_options(const SweepJob& job) {
  JsonArray vary;
  for (const std::string& v : job.vary) vary.push_back({v});
  return {{"vary", {std::move(vary)}}, {"measures", {job.measures}}};
}

}  // namespace

jobs::SweepPaths sweep_paths(const fs::path& out_dir, const std::string& scene_name) {
  return {out_dir / (scene_name + "-sweep.csv"), out_dir / (scene_name + "-sweep.png"),
          shard_in(out_dir, scene_name)};
}

fs::path sweep_manifest_path(const fs::path& out_dir, const std::string& scene_name) {
  return out_dir / scene_name / "sweep-manifest.json";
}

SweepOutcome make_sweep(const SweepJob& job) {
  jobs::SweepRequest request;
  request.layout = [out = job.out_dir](const std::string& name) { return sweep_paths(out, name); };
  request.scene_path = job.scene_path;
  request.overrides = job.overrides;
  for (const auto& v : job.vary) request.ranges.push_back(jobs::parse_vary(v));
  if (job.measures.empty()) throw InputError("sweep: give --measure M[,M…]");
  request.measures = jobs::parse_measures(job.measures);
  request.jobs = job.jobs;
  request.shard_index = job.shard_index;
  request.shard_count = job.shard_count;
  request.stop_signal = job.stop_signal;
  SweepOutcome done;
  jobs::SweepResult result;
  if (job.shard_count > 0) {
    result = jobs::run_sweep(request);
  } else {
    request.scene = scene::parse_scene(job.scene_path, job.overrides);
    const scene::Scene& scene = *request.scene;
    done.name = scene.name;
    const fs::path manifest = sweep_manifest_path(job.out_dir, scene.name);
    const JsonObject options = sweep_options(job);
    const CachedOutputs cached{scene.name + "-sweep", manifest,
                               cache::manifest_head("sweep", options, scene), job.out_dir, &scene};
    done.outcome = make_cached(cached, job.freshness, [&]() -> std::optional<Made> {
                     result = jobs::run_sweep(request);
                     if (result.signal != 0) return std::nullopt;
                     return Made{result.written};
                   }).outcome;
  }
  if (result.signal != 0) done.outcome = Outcome::interrupted;
  done.signal = result.signal;
  done.written = result.written;
  return done;
}

std::vector<fs::path> merge_sweep_shards(const std::vector<fs::path>& shards,
                                         const fs::path& out_dir) {
  const fs::path beside = shards.empty() ? out_dir : shards.front().parent_path();
  return jobs::merge_sweep(shards, [&](const std::string& name) {
    jobs::SweepPaths paths = sweep_paths(out_dir, name);
    paths.shard = shard_in(beside, name);
    return paths;
  });
}

}  // namespace bookspin::products
