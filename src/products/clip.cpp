#include "products/clip.hpp"

#include <sstream>

#include "analysis/frame_source.hpp"
#include "cache/make_cached.hpp"
#include "clip/clip.hpp"
#include "common/json_writer.hpp"
#include "output/manifest.hpp"

namespace bookspin::products {

namespace fs = std::filesystem;

namespace {

/// The warnings of a clip, without the "bookspin: warning: " prefix: the MP4's encoder fallback
/// (render.codec's encoder missing or refusing to open, and why), then its divergences.
std::vector<std::string> clip_warnings(const std::string& name, const clip::ClipResult& result) {
  std::vector<std::string> warnings;
  if (!result.encoder_fallback.empty()) warnings.push_back(name + ": " + result.encoder_fallback);
  if (result.diverged_at) {
    warnings.push_back(analysis::divergence_warning(
        name + ": simulation", *result.diverged_at, result.divergence_reason,
        "the clip holds its last frame before the blow-up"));
  }
  for (const auto& tile : result.diverged_tiles) {
    warnings.push_back(analysis::divergence_warning(name + ": panel '" + tile.label + "'", tile.t,
                                                    "", "its tile holds the last finite frame"));
  }
  return warnings;
}

/// The clip's part of its manifest's note (recorded, not compared): its warnings and, with an
/// MP4, the H.264 encoder that made it. The head holds render.codec, the encoder asked for;
/// this is the one used, libx264 when that one fell back.
std::string clip_note(const std::vector<std::string>& warnings, const clip::ClipResult& result) {
  std::string note = output::warnings_note(warnings);
  if (!result.mp4_encoder.empty())
    note += json_member_lines({{"mp4_encoder", {result.mp4_encoder}}}, "manifest note", 2, false);
  return note;
}

/// OUT/<name>.<format>: a video of the clip.
fs::path video_path(const fs::path& out_dir, const scene::Scene& scene, const std::string& format) {
  return out_dir / (scene.name + "." + format);
}

/// Every file a render of `job` writes.
std::vector<fs::path> clip_outputs(const ClipJob& job, const ClipLayout& layout) {
  std::vector<fs::path> files = layout.videos;
  if (job.write_png) {
    for (int i = 0; i < job.scene.frames; ++i)
      files.push_back(layout.frames_dir / clip::frame_file_name(i));
  }
  files.insert(files.end(), layout.csvs.begin(), layout.csvs.end());
  return files;
}

}  // namespace

ClipLayout clip_layout(const fs::path& out_dir, const scene::Scene& scene) {
  ClipLayout layout;
  const fs::path folder = out_dir / scene.name;
  layout.manifest = folder / "manifest.json";
  for (const std::string& format : scene.render.formats)
    layout.videos.push_back(video_path(out_dir, scene, format));
  layout.frames_dir = folder / "frames";
  if (scene.compare.empty()) {
    layout.csvs.push_back(folder / "diagnostics.csv");
  } else {
    for (const auto& tile : scene.compare)
      layout.csvs.push_back(folder / ("diagnostics-" + tile.name + ".csv"));
  }
  return layout;
}

clip::ClipRequest clip_request(const ClipJob& job) {
  const ClipLayout layout = clip_layout(job.out_dir, job.scene);
  clip::ClipRequest request;
  request.scene = job.scene;
  const auto video = [&job](const char* format) {
    return video_path(job.out_dir, job.scene, format);
  };
  request.paths = {video("mp4"), video("webm"), video("gif"), layout.frames_dir,
                   layout.csvs.front()};
  request.tile_csvs.assign(layout.csvs.begin() + 1, layout.csvs.end());
  request.write_png = job.write_png;
  request.png_compression = job.png_compression;
  request.jobs = job.jobs;
  request.on_progress = job.on_progress;
  request.stop_signal = job.stop_signal;
  return request;
}

namespace {

/// Every output of a clip's run is put in place together, or none (clip::render_clip).
cache::CachedOutputs clip_cached(const ClipJob& job, const ClipLayout& layout) {
  const int compression =
      job.png_compression >= 0 ? job.png_compression : job.scene.render.png_compression;
  const JsonObject options{{"png", {job.write_png}},
                           {"png_compression", {std::int64_t{compression}}}};
  return {job.scene.name, layout.manifest,        "render", options, job.out_dir,
          &job.scene,     /*all_or_nothing=*/true};
}

}  // namespace

std::string clip_manifest_head(const ClipJob& job) {
  return cache::cached_head(clip_cached(job, clip_layout(job.out_dir, job.scene)));
}

ClipOutcome make_clip(const ClipJob& job) {
  const ClipLayout layout = clip_layout(job.out_dir, job.scene);
  const clip::ClipRequest request = clip_request(job);
  const cache::CachedOutputs cached{clip_cached(job, layout)};
  ClipOutcome done;
  const std::vector<fs::path> outputs = clip_outputs(job, layout);
  done.outcome = cache::make_cached(cached, job.freshness, [&] {
    // Every output of the run is put in place together, or none (clip::render_clip).
    done.result = clip::render_clip(request);
    done.warnings = clip_warnings(cached.name, done.result);
    return cache::Made{outputs, clip_note(done.warnings, done.result)};
  });
  if (done.outcome == cache::Outcome::up_to_date)
    done.warnings = output::read_manifest(layout.manifest).warnings;
  return done;
}

}  // namespace bookspin::products
