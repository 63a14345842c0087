#include <iostream>

#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "cli/progress.hpp"
#include "pipeline/clip.hpp"
#include "pipeline/lattice_note.hpp"

namespace bookspin::cli {

namespace {

pipeline::ClipRequest clip_request(const RenderArgs& args, scene::Scene scene, Progress& progress) {
  pipeline::ClipRequest request;
  request.scene = std::move(scene);
  request.out_dir = args.out_dir;
  request.write_png = !args.no_png;
  request.png_compression = args.png_compression;
  request.jobs = args.jobs;
  request.on_note = [](const std::string& note) {
    std::cerr << "bookspin: note: " << note << '\n';
  };
  request.on_progress = [&progress](int done) { progress.update(done); };
  request.stop_signal = interrupt_signal;
  return request;
}

void warn_divergence(const std::string& name, const pipeline::ClipResult& result) {
  if (result.diverged_at) {
    std::cerr << "bookspin: warning: " << name
              << ": simulation diverged at t = " << *result.diverged_at
              << divergence_because(result.divergence_reason)
              << "; the clip holds the last finite frame\n";
  }
  for (const auto& tile : result.diverged_tiles) {
    std::cerr << "bookspin: warning: " << name << ": panel '" << tile.label
              << "' diverged at t = " << tile.t << "; its tile holds the last finite frame\n";
  }
}

}  // namespace

std::string divergence_because(const std::string& reason) {
  return reason.empty() ? "" : "; " + reason;
}

int render_command(const RenderArgs& args) {
  install_interrupt_handlers();
  scene::Scene scene = scene::parse_scene(args.scene_path, args.overrides);
  for (const std::string& warning : scene.warnings)
    std::cerr << "bookspin: warning: " << warning << '\n';
  if (const std::string note = pipeline::lattice_note(scene); !note.empty())
    std::cerr << "bookspin: " << note << '\n';
  if (args.frames > 0) scene.frames = args.frames;
  Progress progress(scene.name, scene.frames);
  const pipeline::ClipRequest request = clip_request(args, std::move(scene), progress);
  const pipeline::ClipResult result = pipeline::render_clip(request);
  if (result.signal != 0) {
    std::cerr << "\nbookspin: interrupted; removed the unfinished outputs of " << request.scene.name
              << '\n';
    return 128 + result.signal;
  }
  progress.finish(result.frames);
  warn_divergence(request.scene.name, result);
  return kExitOk;
}

}  // namespace bookspin::cli
