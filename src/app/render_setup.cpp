#include "app/render_setup.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <thread>

#include "video/atomic_output.hpp"

namespace bookspin::app {

video::EncoderSettings encoder_settings(const scene::Scene& scene, int jobs) {
  const scene::RenderOptions& r = scene.render;
  video::EncoderSettings settings{r.width, r.height, r.fps, r.codec, r.crf, r.preset};
  settings.threads = jobs;
  return settings;
}

SinkOptions sink_options(const scene::Scene& scene, const RenderOptions& options) {
  SinkOptions s;
  s.write_png = !options.no_png;
  s.png_compression =
      options.png_compression >= 0 ? options.png_compression : scene.render.png_compression;
  const int jobs =
      options.jobs > 0 ? options.jobs : static_cast<int>(std::thread::hardware_concurrency());
  s.png_workers = std::max(1, jobs - 1);
  s.encoder = encoder_settings(scene, options.jobs);
  return s;
}

void prepare_output_dir(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) video::throw_output_error("cannot create output directory", dir, ec.value());
  if (access(dir.c_str(), W_OK) != 0) video::throw_output_error("cannot write to", dir, errno);
}

}  // namespace bookspin::app
