#pragma once
// The bookspin subcommands. Each returns the process exit status.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli/run_guarded.hpp"

namespace bookspin::cli {

struct SimulateOptions {
  std::string scene_path;
  std::vector<std::string> overrides;  ///< "key=value", value in TOML syntax
  std::string csv_path = "-";          ///< "-" is standard output
};

int simulate_command(const SimulateOptions& options);

struct RenderArgs {
  std::string scene_path;
  std::vector<std::string> overrides;
  std::string out_dir = "out";
  int frames = 0;  ///< --frames: > 0 is appended to `overrides` as time.frames by run_cli
  bool no_png = false;
  int jobs = 0;              ///< worker threads; 0 = number of cores
  int png_compression = -1;  ///< deflate level 0–9 for the frames; −1 = render.png_compression
  bool force = false;        ///< render even when OUT/<scene>/manifest.json says up to date
  bool verify = false;       ///< up-to-date check hashes every output (else sizes only)
  /// `--format mp4,webm,gif` as given (overrides render.formats); empty optional: not given.
  std::optional<std::string> formats;
};

/// The video formats of `--format LIST` (comma-separated, blanks around names ignored).
/// Throws InputError "--format: …" for an empty list, an unknown or a repeated name.
std::vector<std::string> parse_format_list(const std::string& list);

/// Renders a scene's clip (products::make_clip: its videos, frames, diagnostics CSVs and
/// manifest). Prints "up to date: <name>" and renders nothing when the manifest matches this
/// run and its outputs are all there.
int render_command(const RenderArgs& options);

struct AccuracyOptions {
  std::string scene_path;
  std::vector<std::string> overrides;
  std::string out_dir = "out";
  double flips = 10.0;
  std::vector<double> dts{1.0 / 15, 1.0 / 30, 1.0 / 60, 1.0 / 120, 1.0 / 240};
  std::string methods = "all";  ///< analysis::parse_methods()
  bool force = false;
  bool verify = false;
};

/// Every model × integrator × dt against the exact solution: table on stdout,
/// OUT/<scene>-accuracy.csv and a log-log plot OUT/<scene>-accuracy.png.
int accuracy_command(const AccuracyOptions& options);

/// Prints the EGL/GL and FFmpeg set-up.
int info_command();

struct PlotOptions {
  std::string scene_path;
  std::vector<std::string> overrides;
  std::string out_dir = "out";
  int width = 1600;     ///< pixels
  int height = 1000;    ///< pixels
  bool force = false;   ///< plot even when OUT/<scene>/plot-manifest.json says up to date
  bool verify = false;  ///< up-to-date check hashes the PNG (else its size only)
};

/// Simulates a scene (every panel of a comparison) over its whole run and writes
/// OUT/<scene>-plot.png: the plot panel's curves (body-frame ω, E/E0 − 1, shape error)
/// against time, without the cursor.
int plot_command(const PlotOptions& options);

struct GalleryOptions {
  std::string out_dir = "out";
  std::vector<std::string> scene_paths;
  bool force = false;  ///< write the page even when OUT/gallery-manifest.json says up to date
};

/// Writes OUT/index.html: for each scene its title, description, poster frame, clip
/// (<video>), static plot and diagnostics CSVs, each only where the file exists under OUT.
int gallery_command(const GalleryOptions& options);

struct InertiaOptions {
  std::string mesh_path;
  double mass = 0.0;     ///< total mass; 0 = not given (use density)
  double density = 1.0;  ///< mass per length³, after scaling
  double scale = 1.0;    ///< multiplies the file's coordinates
  bool json = false;     ///< one JSON object instead of the table
};

/// Prints a mesh file's volume, mass, centre of mass, inertia about the centre of mass and
/// principal frame (docs/physics.md §11); warnings on stderr.
int inertia_command(const InertiaOptions& options);

/// Every product's on_remake: tells the user on stderr why the existing manifest of the output
/// called `name` did not match ("bookspin: note: NAME: making it again: REASON").
void remake_note(const std::string& name, const std::string& reason);

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

/// Runs a parameter sweep (physics only, docs/physics.md §14) and writes
/// OUT/<scene>-sweep.csv and .png, or one shard's CSV, or merges shard CSVs.
int sweep_command(const SweepOptions& options);

struct ExportOptions {
  std::string scene_path;
  std::vector<std::string> overrides;
  std::string out_dir = "out";
  int frames = 0;       ///< --frames: > 0 is appended to `overrides` as time.frames by run_cli
  bool gltf = false;    ///< --gltf: the only format so far, and required
  bool force = false;   ///< export even when OUT/<scene>/gltf-manifest.json says up to date
  bool verify = false;  ///< up-to-date check hashes the .glb (else its size only)
};

/// Writes OUT/<scene>.glb (products::make_gltf): the body and its motion as animated glTF,
/// unless its manifest says it is up to date.
int export_command(const ExportOptions& options);

struct ExploreOptions {
  std::vector<std::string> scene_paths;  ///< the page's scenes, in this order
  std::string out_dir = "out";
  std::string shell;     ///< the page without data; empty: web/explorer-shell.html beside bookspin
  bool engines = false;  ///< also the JavaScript engines (explorer-engines.js beside the shell)
};

/// Writes OUT/explorer.html (products::write_explorer_page): the explorer page with these scenes.
/// The default shell missing (the page's program not built: web/build.sh) is exit 1 with a
/// line saying how to build it; a --shell that is not one is an input error.
int explore_command(const ExploreOptions& options);

/// Parses argv and runs the chosen subcommand.
int run_cli(int argc, char** argv);

}  // namespace bookspin::cli
