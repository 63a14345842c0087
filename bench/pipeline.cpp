// Bench sections that time whole renders: the pipeline against the encoder floor, and
// resolution scaling. Renders go through clip::render_clip, in this process, so they
// measure exactly what `bookspin render` does.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "analysis/frame_source.hpp"
#include "bench/clip_runs.hpp"
#include "bench/clock.hpp"
#include "bench/sections.hpp"
#include "bench/zlib_png.hpp"
#include "charts/decoration.hpp"
#include "clip/clip.hpp"
#include "clip/clip_request.hpp"
#include "clip/frame.hpp"
#include "clip/render_settings.hpp"
#include "output/png_writer.hpp"
#include "products/clip.hpp"
#include "scene/scene.hpp"
#include "video/video.hpp"

namespace bookspin::bench {

namespace {

std::vector<std::string> size_overrides(int width, int height) {
  return {"render.width=" + std::to_string(width), "render.height=" + std::to_string(height)};
}

}  // namespace

clip::ClipRequest clip_request(const BenchContext& c, const std::string& name, int width,
                               int height, int frames, bool png, std::vector<std::string> extra) {
  std::vector<std::string> overrides = size_overrides(width, height);
  overrides.insert(overrides.end(), extra.begin(), extra.end());
  products::ClipJob job;
  job.scene = scene::parse_scene(c.options.scene_path, overrides);
  job.scene.frames = frames;
  job.out_dir = c.scratch / name;
  job.write_png = png;
  job.jobs = c.options.jobs;
  return products::clip_request(job);
}

Timing timed_render(const clip::ClipRequest& request) {
  const Stopwatch stopwatch;
  clip::render_clip(request);
  const Timing timing = stopwatch.elapsed();
  // Leave the disk as the next run found it (the clip's folder under the scratch folder).
  std::filesystem::remove_all(request.paths.mp4.parent_path());
  return timing;
}

namespace {

scene::Scene pipeline_scene(const BenchContext& c, int width, int height, int frames) {
  scene::Scene scene = scene::parse_scene(c.options.scene_path, size_overrides(width, height));
  scene.frames = frames;
  return scene;
}

/// Every frame exactly as the render command makes it, held in memory.
std::vector<RgbaImage> prerender(const scene::Scene& scene) {
  render::Renderer renderer(clip::render_settings_for(scene));
  analysis::FrameSource source(scene);
  clip::ShownFrame frame;
  std::vector<RgbaImage> frames;
  frames.reserve(static_cast<std::size_t>(scene.frames));
  for (int index = 0; index < scene.frames; ++index) {
    clip::advance(source, index, scene, frame);
    frames.push_back(clip::render_frame(scene, renderer, frame));
  }
  return frames;
}

/// The floor: the same encoder with the same settings as the render command, fed frames
/// that are already rendered. Opening the encoder and finishing the file are included, as
/// they are in the render's time.
Timing timed_encoding(const scene::Scene& scene, const std::vector<RgbaImage>& frames,
                      const std::filesystem::path& file, int jobs, double* conversion) {
  const Stopwatch stopwatch;
  video::Mp4Encoder encoder(file, clip::encoder_settings(scene, jobs));
  for (const RgbaImage& frame : frames) encoder.add_frame(frame);
  encoder.finish();
  const Timing timing = stopwatch.elapsed();
  if (conversion) *conversion = encoder.conversion_seconds();
  std::filesystem::remove(file);
  return timing;
}

/// CPU seconds of each part of the render's work, summed over a clip's frames.
struct Split {
  double simulation = 1e300, draw = 1e300, read_back = 1e300, png = 1e300, png_zlib = 1e300;
  double png_bytes = 0, png_zlib_bytes = 0;  ///< file sizes summed over the frames
  charts::OverlayTimes overlays{1e300, 1e300, 1e300};
  /// Keeps, part by part, the smaller time of this and `run`.
  void keep_best(const Split& run) {
    simulation = std::min(simulation, run.simulation);
    draw = std::min(draw, run.draw);
    read_back = std::min(read_back, run.read_back);
    png = std::min(png, run.png);
    png_zlib = std::min(png_zlib, run.png_zlib);
    png_bytes = run.png_bytes;  // the same frames every round
    png_zlib_bytes = run.png_zlib_bytes;
    overlays.panel = std::min(overlays.panel, run.overlays.panel);
    overlays.sphere = std::min(overlays.sphere, run.overlays.sphere);
    overlays.caption = std::min(overlays.caption, run.overlays.caption);
  }
};

/// The render's parts one after another on this thread, each timed with the CPU time of the
/// whole process (llvmpipe rasterizes on threads of its own), nothing else running: the
/// frames of `scene` as the render command makes them, without the encoder.
Split timed_parts(const scene::Scene& scene, const std::filesystem::path& png_file) {
  render::Renderer renderer(clip::render_settings_for(scene));
  analysis::FrameSource source(scene);
  charts::FrameDecorator decorator(scene);
  const clip::BodyDrawing drawing(scene.body);
  clip::ShownFrame frame;
  Split split{0, 0, 0, 0, 0, 0, 0, {}};
  for (int index = 0; index < scene.frames; ++index) {
    double start = process_cpu_seconds();
    const auto lap = [&start] {
      const double now = process_cpu_seconds(), elapsed = now - start;
      start = now;
      return elapsed;
    };
    clip::advance(source, index, scene, frame);
    split.simulation += lap();
    renderer.draw(drawing.input_for(frame.pose));
    split.draw += lap();
    RgbaImage image = renderer.read_back();
    split.read_back += lap();
    decorator.decorate(image, frame.t, frame.diverged_at, frame.history, &split.overlays);
    lap();
    output::write_png(png_file, image, scene.render.png_compression);
    split.png += lap();
    split.png_bytes += static_cast<double>(std::filesystem::file_size(png_file));
    lap();
    // The yardstick: the same frame through libpng and zlib at the same level.
    write_png_with_zlib(png_file, image, scene.render.png_compression);
    split.png_zlib += lap();
    split.png_zlib_bytes += static_cast<double>(std::filesystem::file_size(png_file));
    lap();
  }
  std::filesystem::remove(png_file);
  return split;
}

constexpr int kPipelineWidth = 1280, kPipelineHeight = 720;

/// MemAvailable from /proc/meminfo in bytes; 0 where it cannot be read.
double available_memory_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kib = 0.0;
  while (meminfo >> key >> kib) {
    if (key == "MemAvailable:") return kib * 1024.0;
    meminfo.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  return 0.0;
}

std::string gib_text(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f GiB", bytes / (1024.0 * 1024.0 * 1024.0));
  return text;
}

std::string frames_text(int frames, int width, int height) {
  return std::to_string(frames) + " frames " + std::to_string(width) + "x" + std::to_string(height);
}

}  // namespace

// The floor must encode frames that already exist, so they are held in memory: reading
// them from disk would slow the floor down and flatter the ratios. A run whose frames do
// not fit (at most 80% of what is available, leaving room for the encoder and the renders)
// is refused up front instead of being killed for memory half-way.
void check_pipeline_memory(const BenchOptions& options) {
  const double needed = 4.0 * kPipelineWidth * kPipelineHeight * options.frames;
  const double available = available_memory_bytes();
  if (available > 0.0 && needed > 0.8 * available) {
    throw BenchLimitError(
        "bench: --frames " + std::to_string(options.frames) + " holds " + gib_text(needed) +
        " of pre-rendered " + std::to_string(kPipelineWidth) + "x" +
        std::to_string(kPipelineHeight) + " frames for the encoder floor, more than 80% of the " +
        gib_text(available) + " available; use fewer --frames (or --only other sections)");
  }
}

namespace {

/// The pipeline's timings, each the best over the rounds.
struct PipelineTimes {
  Timing floor, no_png, png, anisotropic, no_msaa, start_up;
  double conversion = 0;  ///< CPU seconds of the floor's RGBA → yuv420p conversion
};

std::string cores_busy(const Timing& t) {
  char text[64];
  std::snprintf(text, sizeof text, "all threads; %.2f cores busy on average", t.cpu / t.wall);
  return text;
}

/// The wall times and their ratios to the floor.
void report_wall(BenchReport& report, const PipelineTimes& best, const scene::Scene& scene,
                 const std::string& what, int rounds) {
  const std::string of = ", best of " + std::to_string(rounds) + " alternated runs";
  const auto row = [&](const std::string& metric, const Timing& t, const std::string& note) {
    report.add({"pipeline", metric + ", " + what, t.wall, "s", note + of});
  };
  const auto ratio = [&](const std::string& metric, const Timing& t, const std::string& note) {
    report.add({"pipeline", metric + " / floor", t.wall / best.floor.wall, "x", note});
  };
  const scene::RenderOptions& r = scene.render;
  row("encoder alone (the floor)", best.floor,
      r.codec + " crf " + std::to_string(r.crf) + " preset " + r.preset +
          ", frames rendered beforehand");
  row("render --no-png", best.no_png, "in-process render_clip");
  row("render with PNGs", best.png, "PNG level " + std::to_string(r.png_compression));
  row("render --no-png, 4x anisotropic filtering", best.anisotropic,
      "forced; on a software rasterizer the default is trilinear");
  row("render --no-png, render.msaa = 1", best.no_msaa, "forced; no anti-aliasing");
  ratio("render --no-png", best.no_png, "the pipeline's wall time over the encoder's alone");
  ratio("render with PNGs", best.png, "the same with PNG frames");
  ratio("render --no-png, 4x anisotropic", best.anisotropic,
        "for comparison: what anisotropic filtering costs on this GL");
  ratio("render --no-png, render.msaa = 1", best.no_msaa,
        "for comparison: what 4x MSAA costs on this GL");
}

/// Where the time goes: with the cores busy in both runs, the wall ratio follows the CPU
/// ratio, so these rows say how much work the render adds, whatever the machine's load.
void report_cpu(BenchReport& report, const PipelineTimes& best, const std::string& what) {
  const auto row = [&](const std::string& metric, const Timing& t, const std::string& note) {
    report.add({"pipeline", metric, t.cpu, "s", note + cores_busy(t)});
  };
  const auto ratio = [&](const std::string& metric, const Timing& t) {
    report.add({"pipeline", metric + " / floor, CPU time", t.cpu / best.floor.cpu, "x",
                "for comparison: the work the render adds to the encoder's"});
  };
  row("encoder alone (the floor), CPU time, " + what, best.floor, "");
  row("render --no-png, CPU time, " + what, best.no_png, "");
  row("render with PNGs, CPU time, " + what, best.png, "");
  row("render --no-png start-up (2 frames), CPU time", best.start_up,
      "EGL, textures, shader compilation, encoder set-up; ");
  ratio("render --no-png", best.no_png);
  ratio("render with PNGs", best.png);
}

/// Per frame: the CPU time the render adds to the encoder's, and its parts.
void report_split(BenchReport& report, const PipelineTimes& best, const Split& split,
                  const scene::Scene& scene, int frames) {
  const auto row = [&](const std::string& metric, double seconds, const std::string& note) {
    report.add({"pipeline split", metric + ", per frame", 1e3 * seconds / frames, "ms", note});
  };
  const std::string parts =
      "CPU time of the part alone, all parts of a frame in turn on one thread, best of the "
      "rounds part by part";
  row("render --no-png minus the floor, CPU time", best.no_png.cpu - best.floor.cpu,
      "what the render adds to the encoder's work (the best runs above)");
  row("render with PNGs minus the floor, CPU time", best.png.cpu - best.floor.cpu,
      "the same with PNG frames");
  row("simulation", split.simulation, parts);
  row("GL draw + MSAA resolve", split.draw, parts + "; glFinish after the draw");
  row("read-back", split.read_back, parts + "; glReadPixels and the row flip");
  row("overlay: panel plots", split.overlays.panel, parts);
  row("overlay: momentum sphere inset", split.overlays.sphere, parts);
  row("overlay: caption", split.overlays.caption, parts);
  const std::string level = std::to_string(scene.render.png_compression);
  row("PNG (libdeflate, as render writes it)", split.png,
      parts + "; level " + level + " as the scene's, one thread");
  row("PNG through libpng and zlib (the former writer)", split.png_zlib,
      parts + "; zlib level " + level + ", the same frames, one thread");
  report.add({"pipeline split", "PNG libdeflate / libpng+zlib, CPU time",
              split.png / split.png_zlib, "x", "the two rows above"});
  report.add({"pipeline split", "PNG file (libdeflate), per frame", split.png_bytes / frames / 1e3,
              "kB", "mean size of the frames' files"});
  report.add({"pipeline split", "PNG file (libpng+zlib), per frame",
              split.png_zlib_bytes / frames / 1e3, "kB", "mean size of the same frames' files"});
  row("conversion RGBA to yuv420p", best.conversion,
      "swscale inside the encoder; part of the floor, not added by the render");
}

}  // namespace

// The runs are alternated round by round and each keeps its best (shortest) time: on a
// shared 2-core machine one run can be slowed by a neighbour by half; the best of
// alternated runs compares them under the same conditions.
void bench_pipeline(const BenchContext& c) {
  const int frames = c.options.frames, rounds = std::max(1, c.options.rounds);
  const int w = kPipelineWidth, h = kPipelineHeight;
  const scene::Scene scene = pipeline_scene(c, w, h, frames);
  const std::vector<RgbaImage> rendered = prerender(scene);
  const auto anisotropic =
      clip_request(c, "anisotropic", w, h, frames, false, {"render.anisotropy=4"});
  const auto no_msaa = clip_request(c, "no-msaa", w, h, frames, false, {"render.msaa=1"});
  PipelineTimes best;
  Split split;
  for (int round = 0; round < rounds; ++round) {
    double conversion = 0;
    const Timing floor =
        timed_encoding(scene, rendered, c.scratch / "floor.mp4", c.options.jobs, &conversion);
    if (floor.wall < best.floor.wall) best.conversion = conversion;
    best.floor.keep_best(floor);
    best.no_png.keep_best(timed_render(clip_request(c, "no-png", w, h, frames, false)));
    best.png.keep_best(timed_render(clip_request(c, "png", w, h, frames, true)));
    best.anisotropic.keep_best(timed_render(anisotropic));
    best.no_msaa.keep_best(timed_render(no_msaa));
    best.start_up.keep_best(timed_render(clip_request(c, "start-up", w, h, 2, false)));
    split.keep_best(timed_parts(scene, c.scratch / "split.png"));
  }
  const std::string what = frames_text(frames, w, h);
  report_wall(*c.report, best, scene, what, rounds);
  report_cpu(*c.report, best, what);
  report_split(*c.report, best, split, scene, frames);
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
        timed_render(clip_request(c, "resolution", s.width, s.height, s.frames, false)).wall;
    c.report->add({"resolution", "render --no-png, " + frames_text(s.frames, s.width, s.height),
                   s.frames / seconds, "frames/s", "whole command, start-up included"});
  }
}

}  // namespace bookspin::bench
