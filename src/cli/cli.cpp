// The command line: every subcommand's options and help texts (CLI11), parsed into the
// options structs of commands.hpp and handed to the subcommand's function; the exit status
// of bad options (2) and of each command (run_guarded.hpp).
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>

#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/run_guarded.hpp"
#include "output/output_dir.hpp"
#include "scene/scene.hpp"

namespace bookspin::cli {

namespace {

constexpr const char* kSetHelp =
    "Override a scene key, value in TOML syntax (repeatable), e.g. --set time.dt=0.01 "
    "--set model.kind='\"rigid-matrix\"' --set book.size=[1,2,0.5]";

/// A finite number > 0 (CLI::PositiveNumber lets NaN and infinity through).
const CLI::Validator kFinitePositive(
    [](std::string& text) -> std::string {
      double value = 0.0;
      if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value) || !(value > 0.0))
        return "Value " + text + " is not a finite positive number";
      return {};
    },
    "POSITIVE");

/// A finite number in [low, high] ((low, high] when `low_open`), printed in short form.
CLI::Validator finite_range(double low, double high, bool low_open = false) {
  const char open = low_open ? '(' : '[';
  char description[64];
  std::snprintf(description, sizeof description, "FINITE in %c%g - %g]", open, low, high);
  return CLI::Validator(
      [low, high, low_open, open](std::string& text) -> std::string {
        double value = 0.0;
        if (CLI::detail::lexical_cast(text, value) && std::isfinite(value) && value >= low &&
            value <= high && !(low_open && value == low))
          return {};
        char message[128];
        std::snprintf(message, sizeof message, "Value %s not a finite number in %c%g, %g]",
                      text.c_str(), open, low, high);
        return message;
      },
      description);
}

/// The range of a scene key's limit (scene/limits.hpp), for an option that stands for it.
CLI::Validator finite_range(const scene::Limit& limit) {
  return finite_range(limit.min, limit.max, limit.min_open);
}

void add_simulate(CLI::App& cli, SimulateOptions& options) {
  CLI::App* cmd = cli.add_subcommand(
      "simulate", "Run a scene's simulation without rendering and write the diagnostics CSV");
  cmd->add_option("SCENE", options.scene_path, "Scene file (TOML)")->required();
  cmd->add_option("--set", options.overrides, kSetHelp)->take_all()->allow_extra_args(false);
  cmd->add_option("--csv", options.csv_path,
                  "Output CSV, one row per frame (frame 0 = initial state); '-' for stdout")
      ->capture_default_str();
}

/// --force and --verify of the commands that skip up-to-date outputs.
void add_freshness_flags(CLI::App* cmd, bool& force, bool& verify, const std::string& manifest) {
  cmd->add_flag("--force", force,
                "Make the outputs even when " + manifest + " says they are up to date");
  cmd->add_flag("--verify", verify,
                "Up-to-date check: compare every output's SHA-256 with the manifest, not only "
                "its size");
}

void add_render(CLI::App& cli, RenderArgs& options) {
  CLI::App* cmd = cli.add_subcommand(
      "render",
      "Render a scene to OUT/<scene>.mp4 (and/or .webm, .gif), OUT/<scene>/frames/ and "
      "OUT/<scene>/diagnostics.csv");
  cmd->add_option("SCENE", options.scene_path, "Scene file (TOML)")->required();
  cmd->add_option("-o,--out", options.out_dir, "Output directory")->capture_default_str();
  cmd->add_option("--set", options.overrides, kSetHelp)->take_all()->allow_extra_args(false);
  cmd->add_option("--frames", options.frames,
                  "Render only the first N frames (overrides time.frames)")
      ->check(CLI::Range(1, scene::kMaxFrames));
  cmd->add_flag("--no-png", options.no_png, "Skip the PNG frames (MP4 and CSV only)");
  cmd->add_option("-j,--jobs", options.jobs,
                  "Worker threads for PNG compression and encoding (default: all cores)")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--png-compression", options.png_compression,
                  "zlib level of the PNG frames, 0 (fastest) … 9 (smallest); overrides "
                  "render.png_compression")
      ->check(CLI::Range(0, 9));
  cmd->add_option("--format", options.formats,
                  "Videos to write, comma-separated: mp4 (H.264), webm (VP9), gif (640 px, "
                  "15 frames/s by default); overrides render.formats (default mp4)");
  add_freshness_flags(cmd, options.force, options.verify, "OUT/<scene>/manifest.json");
}

void add_export(CLI::App& cli, ExportOptions& options) {
  CLI::App* cmd = cli.add_subcommand(
      "export",
      "Export a scene's body and its motion for other programs: --gltf writes "
      "OUT/<scene>.glb (glTF 2.0 binary, one animation, keyframes at render.fps)");
  cmd->add_option("SCENE", options.scene_path, "Scene file (TOML), one model (no [[compare]])")
      ->required();
  cmd->add_flag("--gltf", options.gltf, "Write OUT/<scene>.glb")->required();
  cmd->add_option("-o,--out", options.out_dir, "Output directory")->capture_default_str();
  cmd->add_option("--set", options.overrides, kSetHelp)->take_all()->allow_extra_args(false);
  cmd->add_option("--frames", options.frames,
                  "Export only the first N frames (overrides time.frames)")
      ->check(CLI::Range(1, scene::kMaxFrames));
  add_freshness_flags(cmd, options.force, options.verify, "OUT/<scene>/gltf-manifest.json");
}

void add_explore(CLI::App& cli, ExploreOptions& options) {
  CLI::App* cmd = cli.add_subcommand(
      "explore",
      "Write OUT/explorer.html: the physics in the browser, one file that opens from "
      "disk, with these scenes (docs/explorer.md)");
  cmd->add_option("SCENE", options.scene_paths, "Scene files (TOML)")->required();
  cmd->add_option("-o,--out", options.out_dir, "Output directory")->capture_default_str();
  cmd->add_option("--shell", options.shell,
                  "The page without its scenes, as web/build.sh writes it (default: "
                  "web/explorer-shell.html beside the bookspin program)");
  cmd->add_flag("--engines", options.engines,
                "Also run the JavaScript engines cannon-es, Rapier and Jolt in the page, as "
                "models (about 8 MB more; docs/explorer.md)");
}

void add_accuracy(CLI::App& cli, AccuracyOptions& options) {
  CLI::App* cmd = cli.add_subcommand(
      "accuracy", "Compare every model and integrator with the exact solution over a range of dt");
  cmd->add_option("SCENE", options.scene_path, "Scene file (TOML): book, initial spin, toggles")
      ->required();
  cmd->add_option("--set", options.overrides, kSetHelp)->take_all()->allow_extra_args(false);
  cmd->add_option("-o,--out", options.out_dir, "Output directory for the CSV and the plot")
      ->capture_default_str();
  cmd->add_option("--flips", options.flips, "Run length in exact flip periods")
      ->check(finite_range(1.0, 1000.0))
      ->capture_default_str();
  cmd->add_option("--dt", options.dts, "Time steps to try (time units)")
      ->check(finite_range(scene::limit("time.dt")))
      ->take_all();
  cmd->add_option("--methods", options.methods,
                  "Methods to measure, comma-separated: all, engines, rigid, a model kind "
                  "(every mode of it) or KIND:INTEGRATOR, e.g. engines,rigid-quaternion:rk4")
      ->capture_default_str();
  add_freshness_flags(cmd, options.force, options.verify, "OUT/<scene>/accuracy-manifest.json");
}

void add_plot(CLI::App& cli, PlotOptions& options) {
  CLI::App* cmd = cli.add_subcommand(
      "plot",
      "Simulate a scene and plot its diagnostics over the whole run into OUT/<scene>-plot.png");
  cmd->add_option("SCENE", options.scene_path,
                  "Scene file (TOML); a comparison scene plots every panel")
      ->required();
  cmd->add_option("--set", options.overrides, kSetHelp)->take_all()->allow_extra_args(false);
  cmd->add_option("-o,--out", options.out_dir, "Output directory")->capture_default_str();
  cmd->add_option("--width", options.width, "Image width in pixels")
      ->check(CLI::Range(320, scene::kMaxDimension))
      ->capture_default_str();
  cmd->add_option("--height", options.height, "Image height in pixels")
      ->check(CLI::Range(240, scene::kMaxDimension))
      ->capture_default_str();
  add_freshness_flags(cmd, options.force, options.verify, "OUT/<scene>/plot-manifest.json");
}

void add_gallery(CLI::App& cli, GalleryOptions& options) {
  CLI::App* cmd = cli.add_subcommand(
      "gallery", "Write OUT_DIR/index.html listing each scene's clip, poster frame and plot");
  cmd->add_option("OUT_DIR", options.out_dir,
                  "Folder holding the rendered clips; the page goes there")
      ->required();
  cmd->add_option(
         "SCENES", options.scene_paths,
         "Scene files (TOML); the page orders them (paper figures first, see docs/outputs.md)")
      ->required();
  cmd->add_flag("--force", options.force,
                "Write the page even when OUT_DIR/gallery-manifest.json says it is up to date");
}

void add_inertia(CLI::App& cli, InertiaOptions& options) {
  CLI::App* cmd = cli.add_subcommand(
      "inertia",
      "Print the volume, mass, centre of mass and inertia tensor of a closed mesh (OBJ, STL, "
      "glTF 2.0) of uniform density");
  cmd->add_option("MESH", options.mesh_path, "Mesh file: .obj, .stl, .gltf or .glb")->required();
  CLI::Option* mass = cmd->add_option("--mass", options.mass, "Total mass (instead of --density)")
                          ->check(kFinitePositive);
  CLI::Option* density =
      cmd->add_option("--density", options.density, "Mass per unit volume, after --scale")
          ->check(kFinitePositive)
          ->capture_default_str();
  mass->excludes(density);
  cmd->add_option("--scale", options.scale, "Multiply every coordinate of the file by S")
      ->check(kFinitePositive)
      ->capture_default_str();
  cmd->add_flag("--json", options.json, "Print one JSON object (full precision) instead");
}

void add_sweep(CLI::App& cli, SweepOptions& options) {
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
  cmd->add_option("-o,--out", options.out_dir, "Output directory")->capture_default_str();
  cmd->add_option("--merge", options.merge,
                  "Merge shard CSVs into OUT/<scene>-sweep.csv and .png instead of running")
      ->allow_extra_args(true);
  add_freshness_flags(cmd, options.force, options.verify, "OUT/<scene>/sweep-manifest.json");
}

int report(const std::string& message, int code) {
  std::cerr << "bookspin: error: " << message << '\n';
  return code;
}

/// llvmpipe sizes its rasterizer thread pool by the cores unless told otherwise; `render
/// --jobs` caps it too. Set once, before any GL context exists (GPU drivers ignore it).
void cap_gl_threads(const CLI::App& cli, int jobs) {
  if (cli.got_subcommand("render") && jobs > 0)
    setenv("LP_NUM_THREADS", std::to_string(jobs).c_str(), /*overwrite=*/0);
}

/// `--frames N` is `--set time.frames=N`, after the user's own --set (so it wins).
void frames_as_override(int frames, std::vector<std::string>& overrides) {
  if (frames > 0) overrides.push_back("time.frames=" + std::to_string(frames));
}

}  // namespace

int run_cli(int argc, char** argv) {
  install_interrupt_handlers();  // first, so an early Ctrl-C is handled the same way
  CLI::App cli{"bookspin: simulate and render the unstable rotation of a book", "bookspin"};
  cli.require_subcommand(1);
  SimulateOptions simulate;
  add_simulate(cli, simulate);
  RenderArgs render;
  add_render(cli, render);
  ExportOptions export_options;
  add_export(cli, export_options);
  ExploreOptions explore;
  add_explore(cli, explore);
  AccuracyOptions accuracy;
  add_accuracy(cli, accuracy);
  PlotOptions plot;
  add_plot(cli, plot);
  GalleryOptions gallery;
  add_gallery(cli, gallery);
  InertiaOptions inertia;
  add_inertia(cli, inertia);
  SweepOptions sweep;
  add_sweep(cli, sweep);
  cli.add_subcommand("info",
                     "Print the EGL vendor, GL renderer and version, FFmpeg versions and encoders");
  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    return report(std::string(e.what()) + " (see bookspin --help)", kExitUsage);
  }
  cap_gl_threads(cli, render.jobs);
  frames_as_override(render.frames, render.overrides);
  frames_as_override(export_options.frames, export_options.overrides);
  const int status = run_guarded([&] {
    if (cli.got_subcommand("simulate")) return simulate_command(simulate);
    if (cli.got_subcommand("render")) return render_command(render);
    if (cli.got_subcommand("export")) return export_command(export_options);
    if (cli.got_subcommand("explore")) return explore_command(explore);
    if (cli.got_subcommand("info")) return info_command();
    if (cli.got_subcommand("accuracy")) return accuracy_command(accuracy);
    if (cli.got_subcommand("plot")) return plot_command(plot);
    if (cli.got_subcommand("gallery")) return gallery_command(gallery);
    if (cli.got_subcommand("inertia")) return inertia_command(inertia);
    if (cli.got_subcommand("sweep")) return sweep_command(sweep);
    return static_cast<int>(kExitOk);
  });
  // A run that stops without its outputs (an interrupt, an error) takes back the folders it
  // made and left empty; their temporaries are gone already.
  if (status != kExitOk) output::remove_empty_made_directories();
  return status;
}

}  // namespace bookspin::cli
