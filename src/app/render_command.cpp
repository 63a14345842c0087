#include <unistd.h>

#include <cerrno>
#include <iostream>

#include "app/clip_sinks.hpp"
#include "app/commands.hpp"
#include "app/compare_render.hpp"
#include "app/frame_source.hpp"
#include "app/frame_view.hpp"
#include "app/interrupt.hpp"
#include "app/progress.hpp"
#include "app/still.hpp"

namespace bookspin::app {

namespace {

ClipPaths clip_paths(const std::filesystem::path& out_dir, const std::string& name) {
  return {out_dir / (name + ".mp4"), out_dir / name / "frames", out_dir / name / "diagnostics.csv"};
}

SinkOptions sink_options(const scene::Scene& scene, const RenderOptions& options) {
  SinkOptions s;
  s.write_png = !options.no_png;
  s.png_compression = scene.render.png_compression;
  const int jobs = options.jobs > 0 ? options.jobs : static_cast<int>(std::thread::hardware_concurrency());
  s.png_workers = std::max(1, jobs - 1);
  s.encoder = {scene.render.width, scene.render.height, scene.render.fps, scene.render.codec,
               scene.render.crf, scene.render.preset};
  return s;
}

/// Checks early that the output directory exists or can be made and is writable, so a bad
/// -o fails before any work.
void prepare_output_dir(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) video::throw_output_error("cannot create output directory", dir, ec.value());
  if (access(dir.c_str(), W_OK) != 0) video::throw_output_error("cannot write to", dir, errno);
}

struct LoopResult {
  int frames = 0;
  std::optional<double> diverged_at;
  int signal = 0;
};

/// Simulates, renders and queues every frame. After a divergence the last finite pose is
/// held with a "diverged at t = …" caption, so the clip keeps its length.
LoopResult render_frames(const scene::Scene& scene, render::Renderer& renderer, ClipSinks& sinks,
                         Progress& progress) {
  LoopResult result;
  FrameSource source(scene);
  ShownFrame frame;
  for (int index = 0; index < scene.frames; ++index) {
    if ((result.signal = interrupt_signal()) != 0) return result;
    advance(source, index, scene, frame);
    result.diverged_at = frame.diverged_at;
    RgbaImage image = render_frame(scene, renderer, frame);
    physics::Diagnostics row = frame.pose.diagnostics;
    row.t = frame.t;
    sinks.add(index, std::move(image), row);
    result.frames = index + 1;
    progress.update(result.frames);
  }
  return result;
}

}  // namespace

int render_command(const RenderOptions& options) {
  install_interrupt_handlers();
  scene::Scene scene = scene::parse_scene(options.scene_path, options.overrides);
  if (options.frames > 0) scene.frames = options.frames;
  if (!scene.compare.empty()) return render_comparison(scene, options);
  prepare_output_dir(options.out_dir);
  render::Renderer renderer(render_settings_for(scene));
  ClipSinks sinks(clip_paths(options.out_dir, scene.name), sink_options(scene, options));
  if (!sinks.encoder_message().empty()) std::cerr << "bookspin: note: " << sinks.encoder_message() << '\n';
  Progress progress(scene.name, scene.frames);
  const LoopResult result = render_frames(scene, renderer, sinks, progress);
  if (result.signal != 0) {
    std::cerr << "\nbookspin: interrupted; removed the unfinished outputs of " << scene.name << '\n';
    return 128 + result.signal;  // the sinks' destructor removes every temporary
  }
  sinks.finish();
  progress.finish(result.frames);
  if (result.diverged_at) {
    std::cerr << "bookspin: warning: " << scene.name << ": simulation diverged at t = "
              << *result.diverged_at << "; the clip holds the last finite frame\n";
  }
  return kExitOk;
}

}  // namespace bookspin::app
