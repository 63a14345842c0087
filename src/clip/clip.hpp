#pragma once
// The clip loop: scene → simulator → pose → renderer → overlays → sinks, one frame after
// another. The simulation and GL run on the calling thread one frame ahead of the
// read-back; the caption and panel are drawn on the frame whose pixels have arrived; the
// sinks encode and compress on their own threads.
#include "clip/clip_request.hpp"

namespace bookspin::clip {

/// Renders `request.scene` (a single scene or a comparison) into its MP4, PNG frames and
/// diagnostics CSV(s) under request.out_dir. Each frame is pixel for pixel what
/// render_frame() (frame.hpp) makes of it. After a divergence the last finite pose is held
/// with a "diverged at t = …" caption, so the clip keeps its length. Stops early, leaving
/// nothing unfinished behind, when request.stop_signal answers a signal.
/// Throws OutputError (an output cannot be written), output::EncoderError,
/// render::RenderError (no usable EGL/GL).
ClipResult render_clip(const ClipRequest& request);

}  // namespace bookspin::clip
