#include "clip/clip.hpp"

#include <deque>

#include "charts/decoration.hpp"
#include "clip/comparison.hpp"
#include "clip/frame.hpp"
#include "clip/render_settings.hpp"
#include "output/output_dir.hpp"

namespace bookspin::clip {

namespace {

/// A frame between Renderer::submit() and its collection: what its decoration and its CSV
/// row need, since the simulation has moved on by then.
struct InFlight {
  int index = 0;
  double t = 0.0;
  std::optional<double> diverged_at;
  physics::Diagnostics diagnostics;
  physics::Corners corners;  ///< for the orientation (Poinsot's construction)
  bool fresh = false;        ///< a newly simulated pose (else the held last finite one)
};

/// The display side of the loop: finishes frames in the order they were submitted.
class FrameFinisher {
 public:
  FrameFinisher(const ClipRequest& request, output::ClipSinks& sinks, ClipResult& result)
      : request_(request), sinks_(sinks), result_(result), decorator_(request.scene) {}

  void expect(InFlight frame) { in_flight_.push_back(std::move(frame)); }

  /// Decorates the oldest frame in flight with the panel curves as they were at its time,
  /// then queues it and its CSV row.
  void finish(RgbaImage image) {
    InFlight frame = std::move(in_flight_.front());
    in_flight_.pop_front();
    if (frame.fresh) history_.add(frame.diagnostics, &frame.corners);
    decorator_.decorate(image, frame.t, frame.diverged_at, history_);
    physics::Diagnostics row = frame.diagnostics;
    row.t = frame.t;
    sinks_.add(frame.index, std::move(image), row);
    result_.frames = frame.index + 1;
    if (request_.on_progress) request_.on_progress(result_.frames);
  }

 private:
  const ClipRequest& request_;
  output::ClipSinks& sinks_;
  ClipResult& result_;
  std::deque<InFlight> in_flight_;
  charts::DiagnosticsHistory history_;  ///< every frame finished so far, like ShownFrame::history
  charts::FrameDecorator decorator_;
};

ClipResult render_single(const ClipRequest& request) {
  const scene::Scene& scene = request.scene;
  render::Renderer renderer(render_settings_for(scene));
  output::ClipSinks sinks(request.paths, sink_options(request));
  if (request.on_note && !sinks.encoder_message().empty()) request.on_note(sinks.encoder_message());

  ClipResult result;
  analysis::FrameSource source(scene);
  const BodyDrawing drawing(scene.body);
  ShownFrame frame;  // the simulation side, a frame or two ahead of the display side
  FrameFinisher finisher(request, sinks, result);
  for (int index = 0; index < scene.frames; ++index) {
    if ((result.signal = stop_signal(request.stop_signal, "render frames")) != 0)
      return result;  // sinks clean up
    const std::size_t samples = frame.history.size();
    advance(source, index, scene, frame);
    result.diverged_at = frame.diverged_at;
    renderer.submit(drawing.input_for(frame.pose));
    finisher.expect({index, frame.t, frame.diverged_at, frame.pose.diagnostics, frame.pose.corners,
                     frame.history.size() > samples});
    // While this frame is drawn and read back, the previous one is decorated and queued.
    if (auto spare = sinks.spare_frame()) renderer.recycle(std::move(*spare));
    if (auto image = renderer.collect()) finisher.finish(std::move(*image));
  }
  while (auto image = renderer.flush()) finisher.finish(std::move(*image));
  result.divergence_reason = source.divergence_reason();
  output::OutputSet outputs;
  sinks.finish(outputs);
  result.signal = commit_unless_stopped(request, outputs);
  return result;
}

}  // namespace

ClipResult render_clip(const ClipRequest& request) {
  output::prepare_output_dir(request.paths.mp4.parent_path());
  if (!request.scene.compare.empty()) return render_comparison(request);
  return render_single(request);
}

}  // namespace bookspin::clip
