#include "products/sweep.hpp"

#include <sstream>

#include "cache/make_cached.hpp"
#include "charts/sweep_plots.hpp"
#include "common/errors.hpp"
#include "jobs/sweep_shard.hpp"
#include "output/atomic_output.hpp"
#include "output/output_dir.hpp"
#include "output/png_writer.hpp"
#include "output/staged_files.hpp"

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

/// table => the sweep's CSV and picture at `paths`, made first and then written.
std::vector<fs::path> write_sweep(const jobs::SweepTable& table, const SweepPaths& paths) {
  std::ostringstream csv;
  jobs::write_sweep_csv(table, csv);
  const charts::SweepChart chart = jobs::sweep_chart(table);
  const RgbaImage picture = charts::sweep_sheet(chart);
  output::prepare_output_dir(paths.csv.parent_path());
  output::StagedFiles files;
  files.text(paths.csv, csv.str());
  files.png(paths.png, picture);
  files.commit();
  return {paths.csv, paths.png};
}

/// The refused points of `table` into `done` (SweepOutcome::refused).
void count_refused(const jobs::SweepTable& table, SweepOutcome& done) {
  done.points = table.rows.size();
  for (const auto& row : table.rows) {
    if (row.second.back().empty()) continue;
    if (done.refused++ == 0) done.first_refusal = row.second.back();
  }
}

}  // namespace

SweepPaths sweep_paths(const fs::path& out_dir, const std::string& scene_name) {
  return {out_dir / (scene_name + "-sweep.csv"), out_dir / (scene_name + "-sweep.png"),
          shard_in(out_dir, scene_name)};
}

fs::path sweep_manifest_path(const fs::path& out_dir, const std::string& scene_name) {
  return out_dir / scene_name / "sweep-manifest.json";
}

SweepOutcome make_sweep(const SweepJob& job) {
  const JsonObject options = sweep_options(job);
  jobs::SweepRequest request;
  request.scene_path = job.scene_path;
  request.overrides = job.overrides;
  for (const auto& v : job.vary) request.ranges.push_back(jobs::parse_vary(v));
  if (job.measures.empty()) throw InputError("sweep: give --measure M[,M…]");
  request.measures = jobs::parse_measures(job.measures);
  request.jobs = job.jobs;
  request.shard_index = job.shard_index;
  request.shard_count = job.shard_count;
  request.stop_signal = job.stop_signal;
  request.scene = scene::parse_scene(job.scene_path, job.overrides);
  const scene::Scene& scene = *request.scene;
  SweepOutcome done;
  done.name = scene.name;
  const SweepPaths paths = sweep_paths(job.out_dir, scene.name);
  const fs::path manifest = sweep_manifest_path(job.out_dir, scene.name);
  if (job.shard_count > 0) {
    const jobs::SweepTable table = jobs::measure_sweep(request);
    count_refused(table, done);
    const std::string text = jobs::sweep_shard_text(
        table, scene, jobs::SweepGrid(request.ranges).size(), job.shard_index, job.shard_count);
    const fs::path shard = paths.shard(job.shard_index, job.shard_count);
    output::prepare_output_dir(shard.parent_path());
    output::write_text_file(shard, text);
    done.written = {shard};
    return done;
  }
  const cache::CachedOutputs cached{
      scene.name + "-sweep",  manifest, "sweep", options, job.out_dir, &scene,
      /*all_or_nothing=*/true};
  done.outcome = cache::make_cached(cached, job.freshness, [&] {
    const jobs::SweepTable table = jobs::measure_sweep(request);
    count_refused(table, done);
    done.written = write_sweep(table, paths);
    return cache::Made{done.written};
  });
  return done;
}

std::vector<fs::path> merge_sweep_shards(const std::vector<fs::path>& shards,
                                         const fs::path& out_dir) {
  const fs::path beside = shards.empty() ? out_dir : shards.front().parent_path();
  const jobs::SweepTable table = jobs::read_sweep_shards(
      shards, [&](const std::string& name, int k, int n) { return shard_in(beside, name)(k, n); });
  const SweepPaths paths = sweep_paths(out_dir, table.scene_name);
  return write_sweep(table, paths);
}

}  // namespace bookspin::products
