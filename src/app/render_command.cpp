#include <cstdlib>
#include <iostream>

#include "app/clip_sinks.hpp"
#include "app/commands.hpp"
#include "app/compare_render.hpp"
#include "app/frame_pipeline.hpp"
#include "app/frame_view.hpp"
#include "app/interrupt.hpp"
#include "app/progress.hpp"
#include "app/render_setup.hpp"

namespace bookspin::app {

namespace {

ClipPaths clip_paths(const std::filesystem::path& out_dir, const std::string& name) {
  return {out_dir / (name + ".mp4"), out_dir / name / "frames", out_dir / name / "diagnostics.csv"};
}

/// llvmpipe sizes its rasterizer thread pool by the cores unless told otherwise; --jobs caps
/// it too (before any GL context exists; GPU drivers ignore the variable).
void cap_gl_threads(int jobs) {
  if (jobs > 0) setenv("LP_NUM_THREADS", std::to_string(jobs).c_str(), /*overwrite=*/0);
}

}  // namespace

int render_command(const RenderOptions& options) {
  install_interrupt_handlers();
  scene::Scene scene = scene::parse_scene(options.scene_path, options.overrides);
  if (options.frames > 0) scene.frames = options.frames;
  cap_gl_threads(options.jobs);
  if (!scene.compare.empty()) return render_comparison(scene, options);
  prepare_output_dir(options.out_dir);
  render::Renderer renderer(render_settings_for(scene));
  ClipSinks sinks(clip_paths(options.out_dir, scene.name), sink_options(scene, options));
  if (!sinks.encoder_message().empty())
    std::cerr << "bookspin: note: " << sinks.encoder_message() << '\n';
  Progress progress(scene.name, scene.frames);
  const LoopResult result = render_frames(scene, renderer, sinks, progress);
  if (result.signal != 0) {
    std::cerr << "\nbookspin: interrupted; removed the unfinished outputs of " << scene.name
              << '\n';
    return 128 + result.signal;  // the sinks' destructor removes every temporary
  }
  sinks.finish();
  progress.finish(result.frames);
  if (result.diverged_at) {
    std::cerr << "bookspin: warning: " << scene.name
              << ": simulation diverged at t = " << *result.diverged_at
              << "; the clip holds the last finite frame\n";
  }
  return kExitOk;
}

}  // namespace bookspin::app
