#pragma once
// The clip loop: scene → simulator → pose → renderer → overlays → sinks, one frame after
// another, written once for every clip. A clip is tiles: a single scene is one tile that fills
// the frame, a comparison one tile per [[compare]] entry. Each frame, every tile's simulation
// moves on and its picture is submitted to one renderer; the pictures are read back one or two
// behind, while the frame before is composed and decorated (composer.hpp: a single scene by
// charts::FrameDecorator, a comparison with its header strip, shared sphere and panel, and a
// caption per tile); the sinks encode and compress on their own threads and write one CSV row
// per tile.
#include "clip/clip_request.hpp"

namespace bookspin::clip {

/// Renders `request.scene` (a single scene or a comparison) into its videos, PNG frames and
/// diagnostics CSV(s) at request.paths (and a comparison's request.tile_csvs). Each frame of a
/// single scene is pixel for pixel what render_frame() (frame.hpp) makes of it. After a
/// divergence the last finite pose is held with a "diverged at t = …" caption (a comparison:
/// in that tile), so the clip keeps its length. Throws Interrupted, leaving nothing unfinished
/// behind and nothing put in place, when request.stop_signal answers a signal; OutputError (an
/// output cannot be written), video::EncoderError, render::RenderError (no usable EGL/GL).
ClipResult render_clip(const ClipRequest& request);

}  // namespace bookspin::clip
