#pragma once
// One video frame exactly as `bookspin render` makes it: the simulated pose (held after a
// divergence), rendered and decorated with the caption and the divergence banner. Shared by
// the render loop and the golden-image tests, so the goldens pin what the clips show.
#include <optional>

#include "analysis/frame_source.hpp"
#include "charts/diagnostics_history.hpp"
#include "clip/render_settings.hpp"
#include "common/rgba_image.hpp"
#include "physics/simulator.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace bookspin::clip {

/// The simulation's side of one video frame: the pose, its time and whether the simulation
/// has diverged.
struct SimulatedFrame {
  physics::Pose pose;  ///< after a divergence: the last finite pose
  double t = 0.0;      ///< frame time; after a divergence index × frame time, so it runs on
  std::optional<double> diverged_at;
  /// The last pose before the run blew up: its energy within a factor of two of frame 0's,
  /// |E/E₀ − 1| < 1 (the plot sheet's blow-up, charts/plot_sheet.cpp). A run that blew up
  /// ends far past the view (fig08's exploded book), so once it has diverged the picture
  /// holds this pose instead of the last finite one.
  physics::Pose before_blow_up;
  double energy0 = 0.0;  ///< frame 0's total energy
  /// The pose the picture shows: `pose`, or after a divergence `before_blow_up`.
  const physics::Pose& picture() const { return diverged_at ? before_blow_up : pose; }
};

/// What one video frame shows: the simulated frame and the panel's curves up to it.
struct ShownFrame : SimulatedFrame {
  charts::DiagnosticsHistory history;  ///< every simulated frame so far: the panel's curves
};

/// Moves `frame` to video frame `index` (call with 0, 1, 2, … in turn). After a divergence
/// the last finite pose stays in `frame`, so the clip keeps its length (its picture the last
/// pose before the blow-up, SimulatedFrame::picture()). Returns whether the
/// pose is newly simulated (false: the last finite one, held), that is whether the frame adds
/// a sample to the panel's curves.
bool advance(analysis::FrameSource& source, int index, const scene::Scene& scene,
             SimulatedFrame& frame);

/// The same, and the new pose's sample added to `frame.history`.
void advance(analysis::FrameSource& source, int index, const scene::Scene& scene,
             ShownFrame& frame);

/// Simulates from the start to video frame `index` (0 ≤ index < scene.frames, else
/// std::out_of_range).
ShownFrame simulate_to(const scene::Scene& scene, int index);

/// Renders `frame` with `renderer` (made from render_settings_for(scene)) and draws the
/// caption, plus the "diverged at" banner once the simulation has diverged.
RgbaImage render_frame(const scene::Scene& scene, render::Renderer& renderer,
                       const ShownFrame& frame);

/// Video frame `index` of `scene`, pixel for pixel what `bookspin render` writes for it.
RgbaImage render_still(const scene::Scene& scene, render::Renderer& renderer, int index);

/// Same with a renderer of its own (creating one costs a few tenths of a second; reuse one
/// for many frames with the overload above).
RgbaImage render_still(const scene::Scene& scene, int index);

}  // namespace bookspin::clip
