#include "app/frame_pipeline.hpp"

#include <deque>

#include "app/diagnostics_history.hpp"
#include "app/frame_source.hpp"
#include "app/frame_view.hpp"
#include "app/interrupt.hpp"
#include "app/still.hpp"

namespace bookspin::app {

namespace {

/// A frame between Renderer::submit() and its collection: what its decoration and its CSV
/// row need, since the simulation has moved on by then.
struct InFlight {
  int index = 0;
  double t = 0.0;
  std::optional<double> diverged_at;
  physics::Diagnostics diagnostics;
  bool fresh = false;  ///< a newly simulated pose (else the held last finite one)
};

/// The display side of the loop: finishes frames in the order they were submitted.
class FrameFinisher {
 public:
  FrameFinisher(const scene::Scene& scene, ClipSinks& sinks, Progress& progress, LoopResult& result)
      : scene_(scene), sinks_(sinks), progress_(progress), result_(result) {}

  void expect(InFlight frame) { in_flight_.push_back(std::move(frame)); }

  /// Decorates the oldest frame in flight with the panel curves as they were at its time,
  /// then queues it and its CSV row.
  void finish(RgbaImage image) {
    InFlight frame = std::move(in_flight_.front());
    in_flight_.pop_front();
    if (frame.fresh) history_.add(frame.diagnostics);
    decorate_frame(image, scene_, frame.t, frame.diverged_at, history_);
    physics::Diagnostics row = frame.diagnostics;
    row.t = frame.t;
    sinks_.add(frame.index, std::move(image), row);
    result_.frames = frame.index + 1;
    progress_.update(result_.frames);
  }

 private:
  const scene::Scene& scene_;
  ClipSinks& sinks_;
  Progress& progress_;
  LoopResult& result_;
  std::deque<InFlight> in_flight_;
  DiagnosticsHistory history_;  ///< every frame finished so far, like ShownFrame::history
};

}  // namespace

LoopResult render_frames(const scene::Scene& scene, render::Renderer& renderer, ClipSinks& sinks,
                         Progress& progress) {
  LoopResult result;
  FrameSource source(scene);
  ShownFrame frame;  // the simulation side, a frame or two ahead of the display side
  FrameFinisher finisher(scene, sinks, progress, result);
  for (int index = 0; index < scene.frames; ++index) {
    if ((result.signal = interrupt_signal()) != 0) return result;
    const std::size_t samples = frame.history.size();
    advance(source, index, scene, frame);
    result.diverged_at = frame.diverged_at;
    renderer.submit(frame_input_for(frame.pose));
    finisher.expect({index, frame.t, frame.diverged_at, frame.pose.diagnostics,
                     frame.history.size() > samples});
    // While this frame is drawn and read back, the previous one is decorated and queued.
    if (auto spare = sinks.spare_frame()) renderer.recycle(std::move(*spare));
    if (auto image = renderer.collect()) finisher.finish(std::move(*image));
  }
  while (auto image = renderer.flush()) finisher.finish(std::move(*image));
  return result;
}

}  // namespace bookspin::app
