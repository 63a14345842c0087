#pragma once
// Inside the clip loop (clip.cpp): a clip is a row of tiles, one for a single scene, one per
// [[compare]] entry for a comparison, each simulated and drawn alike; a Composer, chosen once
// per clip, makes each video frame of the tiles' pictures and decorates it.
#include <memory>
#include <optional>
#include <vector>

#include "analysis/frame_source.hpp"
#include "charts/diagnostics_history.hpp"
#include "clip/frame.hpp"
#include "clip/render_settings.hpp"
#include "common/rgba_image.hpp"
#include "physics/simulator.hpp"
#include "render/renderer.hpp"
#include "scene/scene.hpp"

namespace bookspin::clip {

/// A tile as the frame being composed shows it. The simulation runs up to the renderer's
/// pipeline depth ahead, so this is kept apart from the simulation's SimulatedFrame; the tile's
/// one diagnostics history is here, grown as its frames are shown.
struct TileShown {
  double t = 0.0;  ///< the frame's time (SimulatedFrame::t)
  std::optional<double> diverged_at;
  physics::Diagnostics diagnostics;    ///< the shown pose's (held after a divergence)
  charts::DiagnosticsHistory history;  ///< every frame up to this one: the panel's curves

  /// The frame's row of the diagnostics CSV: the shown pose's diagnostics at time t.
  physics::Diagnostics row() const {
    physics::Diagnostics r = diagnostics;
    r.t = t;
    return r;
  }
};

/// One tile's run. Not movable: the FrameSource keeps a reference to `scene`.
struct TileRun {
  explicit TileRun(scene::Scene s) : scene(std::move(s)), source(scene), drawing(scene.body) {}
  /// A tile whose simulator the caller made (ClipRequest::tile_models), captioned with
  /// `line` for its model.
  TileRun(scene::Scene s, std::unique_ptr<physics::Simulator> simulator, std::string line)
      : scene(std::move(s)),
        model_line(std::move(line)),
        source(scene, std::move(simulator)),
        drawing(scene.body) {}
  scene::Scene scene;  ///< a single clip's scene, or the comparison's with this tile's model
  /// The caption's words for the model; empty: scene::model_line(scene).
  std::string model_line;
  analysis::FrameSource source;
  BodyDrawing drawing;
  SimulatedFrame frame;  ///< the simulation side: the frame last handed to the renderer
  TileShown shown;       ///< the display side: the frame last composed
};
using Tiles = std::vector<std::unique_ptr<TileRun>>;

/// How the tiles' pictures become one video frame.
class Composer {
 public:
  virtual ~Composer() = default;
  /// The renderer of the tiles' pictures (all of one size; the camera framed on the first
  /// tile's body, `first_tile` being its scene).
  virtual render::RenderSettings picture_settings(const scene::Scene& first_tile) const = 0;
  /// The decorated frame of `pictures` (one per tile, in tile order, taken or left as the
  /// composer likes) showing `tiles` as TileRun::shown holds them.
  virtual RgbaImage compose(std::vector<RgbaImage>& pictures, const Tiles& tiles) = 0;
};

/// A single scene (`scene` must outlive it): its one tile fills the frame, decorated by
/// charts::FrameDecorator (caption, panel, sphere or Poinsot inset, divergence banner).
std::unique_ptr<Composer> single_composer(const scene::Scene& scene);

/// A comparison scene (`scene` must outlive it; comparison.cpp): the tiles laid out by
/// compare_layout(), under the header strip (title, t), with the shared momentum sphere and
/// plot panel (one curve per tile) and a caption per tile (its label, model line, t).
std::unique_ptr<Composer> comparison_composer(const scene::Scene& scene);

}  // namespace bookspin::clip
