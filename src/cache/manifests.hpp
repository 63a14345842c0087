#pragma once
// The manifests of `bookspin render` and `bookspin plot` (output/manifest.hpp has the file
// format): what goes into their head, where they live, which outputs they list.
//
// Head, in this order: manifest format, command, bookspin version and build id (SHA-256 of
// the running executable, so any rebuild with changed code or libraries invalidates), the
// output options, the resolved scene (scene::canonical_json) and the SHA-256 of every file
// the scene reads as bytes (textures). Everything an output depends on and nothing else:
// not --jobs, not the path the scene was given by, not the scene file's comments. The scene
// file's path and SHA-256 go in the manifest's note (recorded, not compared).
#include <filesystem>
#include <string>
#include <vector>

#include "charts/plot_sheet.hpp"
#include "clip/clip_request.hpp"

namespace bookspin::cache {

/// The note of every manifest: the scene file's absolute path and SHA-256. Throws InputError.
std::string manifest_note(const scene::Scene& scene);

/// OUT/<name>/manifest.json.
std::filesystem::path clip_manifest_path(const std::filesystem::path& out_dir,
                                         const std::string& name);
/// The head of the manifest of render_clip(request) (request.scene.frames is the length).
/// Throws InputError if an input file cannot be read.
std::string clip_manifest_head(const clip::ClipRequest& request);
/// Paths relative to OUT of the files render_clip(request) writes: OUT/<name>.mp4, every
/// frame PNG (unless !write_png) and the diagnostics CSVs.
std::vector<std::string> clip_outputs(const clip::ClipRequest& request);

/// The head of any command's manifest: `options` are its output options as JSON members, each
/// line indented by four spaces, comma-separated. Throws InputError.
std::string manifest_head(const std::string& command, const std::string& options,
                          const scene::Scene& scene);

/// OUT/<name>/plot-manifest.json.
std::filesystem::path plot_manifest_path(const std::filesystem::path& out_dir,
                                         const std::string& name);
/// The head of the manifest of write_plot_sheet(request). Throws InputError.
std::string plot_manifest_head(const charts::PlotRequest& request);
/// {"<name>-plot.png"}.
std::vector<std::string> plot_outputs(const charts::PlotRequest& request);

}  // namespace bookspin::cache
