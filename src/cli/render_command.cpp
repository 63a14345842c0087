#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cache/freshness.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/progress.hpp"
#include "cli/subcommand.hpp"
#include "common/errors.hpp"
#include "jobs/lattice_note.hpp"
#include "products/clip.hpp"
#include "scene/scene.hpp"

namespace bookspin::cli {

void remake_note(const std::string& name, const std::string& reason) {
  std::cerr << "bookspin: note: " << name << ": making it again: " << reason << '\n';
}

namespace {

struct RenderArgs {
  std::string scene_path;
  std::vector<std::string> overrides;
  std::string out_dir = "out";
  int frames = 0;  ///< --frames: > 0 is appended to `overrides` as time.frames before the run
  bool no_png = false;
  int jobs = 0;              ///< worker threads; 0 = number of cores
  int png_compression = -1;  ///< deflate level 0–9 for the frames; −1 = render.png_compression
  bool force = false;        ///< render even when OUT/<scene>/manifest.json says up to date
  bool verify = false;       ///< up-to-date check hashes every output (else sizes only)
  /// `--format mp4,webm,gif` as given (overrides render.formats); empty optional: not given.
  std::optional<std::string> formats;
};

/// llvmpipe sizes its rasterizer thread pool by the cores unless told otherwise; `render
/// --jobs` caps it too. Set once, before any GL context exists (GPU drivers ignore it).
void cap_gl_threads(int jobs) {
  if (jobs > 0) setenv("LP_NUM_THREADS", std::to_string(jobs).c_str(), /*overwrite=*/0);
}

/// The video formats of `--format LIST` (comma-separated, blanks around names ignored).
/// Throws InputError "--format: …" for an empty list, an unknown or a repeated name.
std::vector<std::string> parse_format_list(const std::string& list) {
  std::vector<std::string> formats;
  std::size_t start = 0;
  while (!list.empty() && start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    std::string name = list.substr(start, comma - start);
    const auto first = name.find_first_not_of(" \t");
    name = first == std::string::npos
               ? ""
               : name.substr(first, name.find_last_not_of(" \t") + 1 - first);
    formats.push_back(name);
    start = comma + 1;
  }
  if (formats.size() == 1 && formats[0].empty()) formats.clear();
  if (const std::string problem = scene::video_formats_problem(formats); !problem.empty())
    throw InputError("--format: " + problem);
  return formats;
}

/// Renders a scene's clip (products::make_clip: its videos, frames, diagnostics CSVs and
/// manifest). Prints "up to date: <name>" and renders nothing when the manifest matches this
/// run and its outputs are all there.
int render_command(const RenderArgs& args) {
  install_interrupt_handlers();
  std::optional<std::vector<std::string>> formats;
  if (args.formats) formats = parse_format_list(*args.formats);
  products::ClipJob job;
  job.scene = scene::parse_scene(args.scene_path, args.overrides);
  if (formats) job.scene.render.formats = *formats;
  for (const std::string& warning : job.scene.warnings)
    std::cerr << "bookspin: warning: " << warning << '\n';
  if (const std::string note = jobs::lattice_note(job.scene); !note.empty())
    std::cerr << "bookspin: " << note << '\n';
  const std::string name = job.scene.name;
  Progress progress(name, job.scene.frames);
  job.out_dir = args.out_dir;
  job.write_png = !args.no_png;
  job.png_compression = args.png_compression;
  job.jobs = args.jobs;
  job.freshness = {args.force, args.verify, remake_note};
  job.on_progress = [&progress](int done) { progress.update(done); };
  job.stop_signal = stop_poll();
  const products::ClipOutcome done = products::make_clip(job);
  if (done.outcome == cache::Outcome::up_to_date) {
    std::cout << "up to date: " << name << std::endl;
    for (const auto& warning : done.warnings)
      std::cerr << "bookspin: warning: " << warning << " (when it was rendered)\n";
    return kExitOk;
  }
  progress.finish(done.result.frames);
  for (const auto& warning : done.warnings) std::cerr << "bookspin: warning: " << warning << '\n';
  std::cout << "rendered: " << name << " (" << done.result.frames << " frames)" << std::endl;
  return kExitOk;
}

}  // namespace

Subcommand add_render(CLI::App& cli) {
  const auto stored = std::make_shared<RenderArgs>();
  RenderArgs& options = *stored;
  CLI::App* cmd = cli.add_subcommand(
      "render",
      "Render a scene to OUT/<scene>.mp4 (and/or .webm, .gif), OUT/<scene>/frames/ and "
      "OUT/<scene>/diagnostics.csv");
  cmd->add_option("SCENE", options.scene_path, "Scene file (TOML)")->required();
  add_out_option(cmd, options.out_dir, "Output directory");
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
  return {cmd, [stored] {
            cap_gl_threads(stored->jobs);
            frames_as_override(stored->frames, stored->overrides);
            return render_command(*stored);
          }};
}

}  // namespace bookspin::cli
