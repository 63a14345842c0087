#pragma once
// The plot product (`bookspin plot`): a scene's panel curves over its whole run as one PNG,
// with its manifest (docs/outputs.md). The drawing is the charts stage's (plot_sheet.hpp).
#include <filesystem>
#include <functional>
#include <string>

#include "cache/freshness.hpp"
#include "common/stop.hpp"
#include "scene/scene.hpp"

namespace bookspin::products {

/// Every path a plot of one scene into OUT writes.
struct PlotLayout {
  std::filesystem::path png;       ///< OUT/<name>-plot.png
  std::filesystem::path manifest;  ///< OUT/<name>/plot-manifest.json
};

/// The layout of `scene`'s plot in `out_dir`. No I/O.
PlotLayout plot_layout(const std::filesystem::path& out_dir, const scene::Scene& scene);

/// What `bookspin plot` asks for.
struct PlotJob {
  scene::Scene scene;  ///< a single or a comparison scene (every tile is plotted)
  std::filesystem::path out_dir;
  int width = 1280;            ///< pixels
  int height = 800;            ///< pixels
  cache::Freshness freshness;  ///< --force, --verify (the PNG's hash) and the remake note
  /// Polled before every frame of the run ("plot frames") and before the PNG goes in place
  /// ("plot files"): a signal throws Interrupted and the earlier plot and its manifest stay as
  /// they were.
  StopPoll stop;
};

/// The manifest head of `job` ("plot", the image size, the scene). Throws InputError.
std::string plot_manifest_head(const PlotJob& job);

/// (scene, width, height) => OUT/<scene>-plot.png + manifest.
/// Unless its manifest says the plot is up to date: runs the scene (analysis::run_frames),
/// draws its sheet (charts::plot_sheet_image) and writes the PNG, then the manifest. Throws
/// InputError, OutputError.
cache::Outcome make_plot(const PlotJob& job);

}  // namespace bookspin::products
