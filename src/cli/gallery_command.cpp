// `bookspin gallery`: OUT/index.html over the clips, frames and plots already under OUT.
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cache/freshness.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/subcommand.hpp"
#include "products/gallery.hpp"

namespace bookspin::cli {
namespace {

struct GalleryOptions {
  std::string out_dir = "out";
  std::vector<std::string> scene_paths;
  bool force = false;  ///< write the page even when OUT/gallery-manifest.json says up to date
};

/// Writes OUT/index.html: for each scene its title, description, poster frame, clip
/// (<video>), static plot and diagnostics CSVs, each only where the file exists under OUT.
int gallery_command(const GalleryOptions& options) {
  products::GalleryJob job;
  job.out_dir = options.out_dir;
  job.scene_paths = options.scene_paths;
  job.freshness = {options.force, false, remake_note};
  job.stop_signal = stop_poll();
  const products::GalleryOutcome done = products::make_gallery(job);
  const std::string page = products::gallery_layout(job.out_dir).page.string();
  if (done.outcome == cache::Outcome::up_to_date) {
    std::cout << "up to date: " << std::filesystem::path(page).filename().string() << std::endl;
    return kExitOk;
  }
  std::cout << "wrote " << page << " (" << done.entries << " clips)\n";
  return kExitOk;
}

}  // namespace

Subcommand add_gallery(CLI::App& cli) {
  const auto stored = std::make_shared<GalleryOptions>();
  GalleryOptions& options = *stored;
  CLI::App* cmd = cli.add_subcommand(
      "gallery", "Write OUT_DIR/index.html listing each scene's clip, poster frame and plot");
  cmd->add_option("OUT_DIR", options.out_dir,
                  "Folder holding the rendered clips; the page goes there")
      ->required()
      ->check(no_empty_output("a directory", "give . for the current folder"));
  cmd->add_option(
         "SCENES", options.scene_paths,
         "Scene files (TOML); the page orders them (paper figures first, see docs/outputs.md)")
      ->required();
  cmd->add_flag("--force", options.force,
                "Write the page even when OUT_DIR/gallery-manifest.json says it is up to date");
  return {cmd, [stored] { return gallery_command(*stored); }};
}

}  // namespace bookspin::cli
