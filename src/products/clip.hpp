#pragma once
// The clip product (`bookspin render`): a scene's videos, frames and diagnostics CSVs, or a
// comparison's, with their manifest (docs/outputs.md). Every path a clip writes is named here
// and nowhere else; the frame loop itself is the clip stage's (clip/clip.hpp).
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "cache/freshness.hpp"
#include "clip/clip_request.hpp"
#include "common/stop.hpp"
#include "scene/scene.hpp"

namespace bookspin::products {

/// Every path a render of one scene into OUT writes.
struct ClipLayout {
  std::filesystem::path manifest;  ///< OUT/<name>/manifest.json
  /// OUT/<name>.<format> for each of render.formats, in their order.
  std::vector<std::filesystem::path> videos;
  std::filesystem::path frames_dir;  ///< OUT/<name>/frames (frame file names: output)
  /// OUT/<name>/diagnostics.csv, or for a comparison OUT/<name>/diagnostics-<tile>.csv per
  /// tile, in tile order.
  std::vector<std::filesystem::path> csvs;
};

/// The layout of `scene` rendered into `out_dir`. No I/O.
ClipLayout clip_layout(const std::filesystem::path& out_dir, const scene::Scene& scene);

/// What `bookspin render` asks for.
struct ClipJob {
  scene::Scene scene;                         ///< validated; scene.frames is the clip's length
  std::filesystem::path out_dir;              ///< OUT
  bool write_png = true;                      ///< false: videos and CSVs only
  int png_compression = -1;                   ///< 0–9; −1: render.png_compression
  int jobs = 0;                               ///< worker threads; 0: every core
  cache::Freshness freshness;                 ///< --force, --verify and the remake note
  std::function<void(int done)> on_progress;  ///< see clip::ClipRequest
  StopPoll stop_signal;                       ///< see clip::ClipRequest
};

/// The frame loop's request for `job`: its scene, options and the layout's paths.
clip::ClipRequest clip_request(const ClipJob& job);

/// The manifest head of `job` (cache::manifest_head: "render", the PNG options, the scene).
/// Throws InputError if an input file cannot be read.
std::string clip_manifest_head(const ClipJob& job);

/// What make_clip() did.
struct ClipOutcome {
  cache::Outcome outcome = cache::Outcome::made;
  clip::ClipResult result;  ///< the frame loop's result (when made)
  /// The run's warnings without the "bookspin: warning: " prefix (the MP4 made by libx264
  /// rather than render.codec's encoder, and why; divergences): this run's when made, the ones
  /// recorded in the manifest when up to date.
  std::vector<std::string> warnings;
};

/// (scene, options) => OUT/<scene>.<format> for each format, OUT/<scene>/frames/,
/// OUT/<scene>/diagnostics*.csv + manifest.
/// Renders `job` unless its manifest says the outputs are up to date, then writes the
/// manifest (its note records the scene file, the warnings and, with an MP4, the H.264 encoder
/// that made it: "mp4_encoder", libx264 where render.codec's fell back). Same errors as
/// clip::render_clip(), and InputError for an unreadable input file.
ClipOutcome make_clip(const ClipJob& job);

}  // namespace bookspin::products
