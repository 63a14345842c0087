#pragma once
// The render command's frame loop, pipelined (issue 7): the simulation and GL run on the
// calling thread one frame ahead of the read-back, the caption and panel are drawn on the
// frame whose pixels have arrived, and the sinks encode and compress on their own threads.
#include <optional>

#include "app/clip_sinks.hpp"
#include "app/progress.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace bookspin::app {

struct LoopResult {
  int frames = 0;  ///< frames handed to the sinks
  std::optional<double> diverged_at;
  int signal = 0;  ///< the interrupting signal, 0 if none
};

/// Simulates, renders, decorates and queues every frame of `scene` in order. Each frame is
/// pixel for pixel what render_frame() (still.hpp) makes of it. After a divergence the last
/// finite pose is held with a "diverged at t = …" caption, so the clip keeps its length.
/// Stops early, with `signal` set, on SIGINT or SIGTERM.
LoopResult render_frames(const scene::Scene& scene, render::Renderer& renderer, ClipSinks& sinks,
                         Progress& progress);

}  // namespace bookspin::app
