// `bookspin plot`: the panel's curves over a whole run, as a PNG for papers and slides.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cache/freshness.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/subcommand.hpp"
#include "products/plot.hpp"
#include "scene/scene.hpp"

namespace bookspin::cli {
namespace {

struct PlotOptions {
  std::string scene_path;
  std::vector<std::string> overrides;
  std::string out_dir = "out";
  int width = 1280;     ///< pixels
  int height = 800;     ///< pixels
  bool force = false;   ///< plot even when OUT/<scene>/plot-manifest.json says up to date
  bool verify = false;  ///< up-to-date check hashes the PNG (else its size only)
};

/// Simulates a scene (every panel of a comparison) over its whole run and writes
/// OUT/<scene>-plot.png: the plot panel's curves (body-frame ω, E/E0 − 1, shape error)
/// against time, without the cursor.
int plot_command(const PlotOptions& options) {
  products::PlotJob job;
  job.scene = scene::parse_scene(options.scene_path, options.overrides);
  job.out_dir = options.out_dir;
  job.width = options.width;
  job.height = options.height;
  job.freshness = {options.force, options.verify, remake_note};
  job.stop = stop_poll();
  const std::string name = job.scene.name + "-plot";
  const cache::Outcome outcome = products::make_plot(job);
  if (outcome == cache::Outcome::up_to_date) std::cout << "up to date: " << name << std::endl;
  if (outcome == cache::Outcome::made)
    std::cout << "wrote " << products::plot_layout(job.out_dir, job.scene).png.string() << '\n';
  return kExitOk;
}

}  // namespace

Subcommand add_plot(CLI::App& cli) {
  const auto stored = std::make_shared<PlotOptions>();
  PlotOptions& options = *stored;
  CLI::App* cmd = cli.add_subcommand(
      "plot",
      "Simulate a scene and plot its diagnostics over the whole run into OUT/<scene>-plot.png");
  cmd->add_option("SCENE", options.scene_path,
                  "Scene file (TOML); a comparison scene plots every panel")
      ->required();
  cmd->add_option("--set", options.overrides, kSetHelp)->take_all()->allow_extra_args(false);
  add_out_option(cmd, options.out_dir, "Output directory");
  cmd->add_option("--width", options.width, "Image width in pixels")
      ->check(CLI::Range(320, scene::kMaxDimension))
      ->capture_default_str();
  cmd->add_option("--height", options.height, "Image height in pixels")
      ->check(CLI::Range(240, scene::kMaxDimension))
      ->capture_default_str();
  add_freshness_flags(cmd, options.force, options.verify, "OUT/<scene>/plot-manifest.json");
  return {cmd, [stored] { return plot_command(*stored); }};
}

}  // namespace bookspin::cli
