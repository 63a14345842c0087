// Bench sections that time whole renders: the pipeline against the encoder floor, and
// resolution scaling. Renders go through render_command itself, in this process, so they
// measure exactly what `bookspin render` does.
#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/bench_sections.hpp"
#include "app/frame_source.hpp"
#include "app/frame_view.hpp"
#include "app/still.hpp"
#include "scene/scene.hpp"
#include "video/mp4_encoder.hpp"

namespace bookspin::app {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::vector<std::string> size_overrides(int width, int height) {
  return {"render.width=" + std::to_string(width), "render.height=" + std::to_string(height)};
}

/// render SCENE --set render.width=W --set render.height=H --frames N -o SCRATCH/NAME.
RenderOptions render_options(const BenchContext& c, const std::string& name, int width, int height,
                             int frames, bool png) {
  RenderOptions o;
  o.scene_path = c.options.scene_path;
  o.overrides = size_overrides(width, height);
  o.out_dir = (c.scratch / name).string();
  o.frames = frames;
  o.no_png = !png;
  o.jobs = c.options.jobs;
  return o;
}

/// Wall time of a whole render command (start-up, every frame, finishing the files).
double timed_render(const RenderOptions& options) {
  const auto start = Clock::now();
  const int status = render_command(options);
  const double seconds = seconds_since(start);
  if (status != kExitOk)
    throw std::runtime_error("bench: the render failed (status " + std::to_string(status) + ")");
  std::filesystem::remove_all(options.out_dir);  // leave the disk as the next run found it
  return seconds;
}

scene::Scene pipeline_scene(const BenchContext& c, int width, int height, int frames) {
  scene::Scene scene = scene::parse_scene(c.options.scene_path, size_overrides(width, height));
  scene.frames = frames;
  return scene;
}

/// Every frame exactly as the render command makes it, held in memory.
std::vector<RgbaImage> prerender(const scene::Scene& scene) {
  render::Renderer renderer(render_settings_for(scene));
  FrameSource source(scene);
  ShownFrame frame;
  std::vector<RgbaImage> frames;
  frames.reserve(static_cast<std::size_t>(scene.frames));
  for (int index = 0; index < scene.frames; ++index) {
    advance(source, index, scene, frame);
    frames.push_back(render_frame(scene, renderer, frame));
  }
  return frames;
}

/// The floor: the same encoder with the same settings as the render command, fed frames
/// that are already rendered. Opening the encoder and finishing the file are included, as
/// they are in the render's time.
double timed_encoding(const scene::Scene& scene, const std::vector<RgbaImage>& frames,
                      const std::filesystem::path& file, int jobs) {
  const auto& r = scene.render;
  video::EncoderSettings settings{r.width, r.height, r.fps, r.codec, r.crf, r.preset};
  settings.threads = jobs;
  const auto start = Clock::now();
  video::Mp4Encoder encoder(file, settings);
  for (const RgbaImage& frame : frames) encoder.add_frame(frame);
  encoder.finish();
  const double seconds = seconds_since(start);
  std::filesystem::remove(file);
  return seconds;
}

std::string frames_text(int frames, int width, int height) {
  return std::to_string(frames) + " frames " + std::to_string(width) + "x" + std::to_string(height);
}

}  // namespace

/// The pipeline's four timings, each the best over the rounds.
struct PipelineTimes {
  double floor = 1e300, no_png = 1e300, png = 1e300, anisotropic = 1e300, no_msaa = 1e300;
};

// The four are alternated round by round and each keeps its best (shortest) time: on a
// shared 2-core machine one run can be slowed by a neighbour by half; the best of
// alternated runs compares the four under the same conditions.
void bench_pipeline(const BenchContext& c) {
  BenchReport& report = *c.report;
  const int frames = c.options.frames, rounds = std::max(1, c.options.rounds);
  const scene::Scene scene = pipeline_scene(c, 1280, 720, frames);
  const std::string what = frames_text(frames, 1280, 720);
  const std::vector<RgbaImage> rendered = prerender(scene);
  RenderOptions anisotropic = render_options(c, "anisotropic", 1280, 720, frames, false);
  anisotropic.overrides.push_back("render.anisotropy=4");
  RenderOptions no_msaa = render_options(c, "no-msaa", 1280, 720, frames, false);
  no_msaa.overrides.push_back("render.msaa=1");
  PipelineTimes best;
  for (int round = 0; round < rounds; ++round) {
    best.floor = std::min(best.floor,
                          timed_encoding(scene, rendered, c.scratch / "floor.mp4", c.options.jobs));
    best.no_png =
        std::min(best.no_png, timed_render(render_options(c, "no-png", 1280, 720, frames, false)));
    best.png = std::min(best.png, timed_render(render_options(c, "png", 1280, 720, frames, true)));
    best.anisotropic = std::min(best.anisotropic, timed_render(anisotropic));
    best.no_msaa = std::min(best.no_msaa, timed_render(no_msaa));
  }
  const std::string of = ", best of " + std::to_string(rounds) + " alternated runs";
  report.add({"pipeline", "encoder alone (the floor), " + what, best.floor, "s",
              scene.render.codec + " crf " + std::to_string(scene.render.crf) + " preset " +
                  scene.render.preset + ", frames rendered beforehand" + of});
  report.add(
      {"pipeline", "render --no-png, " + what, best.no_png, "s", "in-process render command" + of});
  report.add({"pipeline", "render with PNGs, " + what, best.png, "s",
              "PNG zlib level " + std::to_string(scene.render.png_compression) + of});
  report.add({"pipeline", "render --no-png, 4x anisotropic filtering, " + what, best.anisotropic,
              "s", "forced; on a software rasterizer the default is trilinear" + of});
  report.add({"pipeline", "render --no-png, render.msaa = 1, " + what, best.no_msaa, "s",
              "forced; no anti-aliasing" + of});
  report.add({"pipeline", "render --no-png / floor", best.no_png / best.floor, "x",
              at_most(best.no_png / best.floor, 1.15)});
  report.add({"pipeline", "render with PNGs / floor", best.png / best.floor, "x",
              at_most(best.png / best.floor, 1.5)});
  report.add({"pipeline", "render --no-png, 4x anisotropic / floor", best.anisotropic / best.floor,
              "x", "for comparison: what anisotropic filtering costs on this GL"});
  report.add({"pipeline", "render --no-png, render.msaa = 1 / floor", best.no_msaa / best.floor,
              "x", "for comparison: what 4x MSAA costs on this GL"});
}

void bench_resolution(const BenchContext& c) {
  struct Size {
    int width, height, frames;
  };
  // Fewer frames where each costs more, so every size takes seconds, not minutes.
  const int n = c.options.frames;
  const Size sizes[] = {{640, 360, n},
                        {1280, 720, n},
                        {1920, 1080, std::max(2, n / 3)},
                        {3840, 2160, std::max(2, n / 10)}};
  for (const Size& s : sizes) {
    const double seconds =
        timed_render(render_options(c, "resolution", s.width, s.height, s.frames, false));
    c.report->add({"resolution", "render --no-png, " + frames_text(s.frames, s.width, s.height),
                   s.frames / seconds, "frames/s", "whole command, start-up included"});
  }
}

}  // namespace bookspin::app
