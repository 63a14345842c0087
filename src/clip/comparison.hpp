#pragma once
// A comparison scene ([[compare]] tiles side by side in one clip).
#include "clip/clip_request.hpp"

namespace bookspin::clip {

/// Renders a comparison scene: every tile's simulator starts from the scene's initial state
/// and steps in lockstep; one renderer at tile size draws each tile's book, each tile is
/// labelled (label, model line, t), and the composited frame goes to OUT/<scene>.mp4 and
/// OUT/<scene>/frames/. Each tile's diagnostics go to OUT/<scene>/diagnostics-<tile
/// name>.csv (the diagnostics CSV's columns). Called by render_clip(); same errors.
ClipResult render_comparison(const ClipRequest& request);

}  // namespace bookspin::clip
