#include "clip/clip_request.hpp"

#include <algorithm>
#include <thread>

namespace bookspin::clip {

video::EncoderSettings encoder_settings(const scene::Scene& scene, int jobs) {
  const scene::RenderOptions& r = scene.render;
  video::EncoderSettings settings{r.width, r.height, r.fps, r.codec, r.crf, r.preset};
  settings.threads = jobs;
  return settings;
}

SinkOptions sink_options(const ClipRequest& request) {
  SinkOptions s;
  s.write_png = request.write_png;
  s.png_compression =
      request.png_compression >= 0 ? request.png_compression : request.scene.render.png_compression;
  const int jobs =
      request.jobs > 0 ? request.jobs : static_cast<int>(std::thread::hardware_concurrency());
  s.png_workers = std::max(1, jobs - 1);
  s.encoder = encoder_settings(request.scene, request.jobs);
  const scene::RenderOptions& r = request.scene.render;
  s.formats = r.formats;
  s.webm_crf = r.webm_crf;
  s.gif_width = r.gif_width;
  s.gif_fps = r.gif_fps;
  s.stop = request.stop_signal;
  return s;
}

void commit_unless_stopped(const ClipRequest& request, output::OutputSet& outputs) {
  // Asked to stop while the videos were finalized: abandon the run. Nothing is in place yet,
  // and the outputs' owners remove their temporaries.
  stop_if_asked(request.stop_signal, "commit outputs");
  outputs.commit();  // every output of the run, or none
}

}  // namespace bookspin::clip
