#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <iostream>

#include "app/clip_sinks.hpp"
#include "app/commands.hpp"
#include "app/compare_render.hpp"
#include "app/frame_pipeline.hpp"
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
  s.png_compression = options.png_compression >= 0 ? options.png_compression
                                                   : scene.render.png_compression;
  const int jobs = options.jobs > 0 ? options.jobs : static_cast<int>(std::thread::hardware_concurrency());
  s.png_workers = std::max(1, jobs - 1);
  s.encoder = {scene.render.width, scene.render.height, scene.render.fps, scene.render.codec,
               scene.render.crf, scene.render.preset};
  s.encoder.threads = options.jobs;  // 0: the encoder's own choice for all cores
  return s;
}

/// llvmpipe sizes its rasterizer thread pool by the cores unless told otherwise; --jobs caps
/// it too (before any GL context exists; GPU drivers ignore the variable).
void cap_gl_threads(int jobs) {
  if (jobs > 0) setenv("LP_NUM_THREADS", std::to_string(jobs).c_str(), /*overwrite=*/0);
}

/// Checks early that the output directory exists or can be made and is writable, so a bad
/// -o fails before any work.
void prepare_output_dir(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) video::throw_output_error("cannot create output directory", dir, ec.value());
  if (access(dir.c_str(), W_OK) != 0) video::throw_output_error("cannot write to", dir, errno);
}

}  // namespace

int render_command(const RenderOptions& options) {
  install_interrupt_handlers();
  scene::Scene scene = scene::parse_scene(options.scene_path, options.overrides);
  if (options.frames > 0) scene.frames = options.frames;
  cap_gl_threads(options.jobs);
  if (!scene.compare.empty()) return render_comparison(scene, options);
  prepare_output_dir(options.out_dir);
  render::RenderSettings settings = render_settings_for(scene);
  if (options.trilinear) settings.max_anisotropy = 1.0f;
  render::Renderer renderer(settings);
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
