#pragma once
// The clip loop: scene → simulator → pose → renderer → overlays → sinks, one frame after
// another, written once for every clip. A clip is tiles: a single scene is one tile that fills
// the frame, a comparison one tile per [[compare]] entry. Each frame, every tile's simulation
// moves on and its picture is submitted to one renderer; the pictures are read back one or two
// behind, while the frame before is composed and decorated (composer.hpp: a single scene by
// charts::FrameDecorator, a comparison with its header strip, shared sphere and panel, and a
// caption per tile). FrameLoop hands the composed frames out one at a time; render_clip() gives
// each to the sinks, which encode and compress on their own threads and write one CSV row per
// tile, and a caller that wants the frames themselves (the Python module's bookspin.frames)
// pulls them from a FrameLoop of its own.
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "clip/clip_request.hpp"
#include "common/rgba_image.hpp"
#include "common/stop.hpp"
#include "physics/simulator.hpp"
#include "scene/scene.hpp"

namespace bookspin::clip {

/// One video frame of a clip, composed and decorated: what the sinks encode and write.
struct ClipFrame {
  int index = 0;    ///< the video frame, from 0
  double t = 0.0;   ///< its time, time units (the diagnostics CSV's t; runs on after a divergence)
  RgbaImage image;  ///< render.width × render.height, opaque, top row first
  std::vector<physics::Diagnostics> rows;  ///< its diagnostics CSV rows, one per tile
};

/// A source of frame buffers the caller is done with (ClipSinks::spare_frame), for the
/// renderer to read pictures back into rather than allocate; std::nullopt when none is free.
using SpareFrames = std::function<std::optional<RgbaImage>()>;

/// The frame loop of a clip, pulled one frame at a time: each next() simulates, draws and
/// composes until the next frame is finished. render_clip() is this loop feeding the sinks.
/// Holds a GL context: use it from the thread that made it. Writes nothing.
class FrameLoop {
 public:
  /// The loop of `scene` (a single scene or a comparison), each tile simulating its scene's
  /// model or, given `tile_models` (one per tile), the caller's (ClipRequest::tile_models).
  /// Throws render::RenderError (no usable EGL/GL, a texture missing).
  explicit FrameLoop(scene::Scene scene, const std::vector<TileModel>& tile_models = {});
  ~FrameLoop();
  FrameLoop(const FrameLoop&) = delete;
  FrameLoop& operator=(const FrameLoop&) = delete;

  /// The clip's frames (scene.frames) and tiles (1 for a single scene).
  int frames() const;
  std::size_t tiles() const;

  /// The next frame, in order from 0, or std::nullopt after the last. Asks `stop` before
  /// simulating each frame ("render frames") and throws Interrupted when it answers a signal;
  /// `spare` is asked once per tile picture.
  std::optional<ClipFrame> next(const StopPoll& stop = {}, const SpareFrames& spare = {});

  /// After the last frame: a single scene's divergence (time and the simulator's reason), or
  /// every diverged tile of a comparison, into `result`.
  void record_divergence(ClipResult& result) const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// Renders `request.scene` (a single scene or a comparison) into its videos, PNG frames and
/// diagnostics CSV(s) at request.paths (and a comparison's request.tile_csvs): FrameLoop's
/// frames, each handed to the ClipSinks. Each frame of a single scene is pixel for pixel what
/// render_frame() (frame.hpp) makes of it. After a divergence the last pose before the blow-up
/// is held (SimulatedFrame::picture()) with a "diverged at t = …" caption (a comparison: in that
/// tile), so the clip keeps its length.
/// Throws Interrupted, leaving nothing unfinished behind and nothing put in place, when
/// request.stop_signal answers a signal; OutputError (an output cannot be written),
/// video::EncoderError, render::RenderError (no usable EGL/GL).
ClipResult render_clip(const ClipRequest& request);

}  // namespace bookspin::clip
