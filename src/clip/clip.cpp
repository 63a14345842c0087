#include "clip/clip.hpp"

#include <deque>

#include "charts/decoration.hpp"
#include "clip/composer.hpp"
#include "common/errors.hpp"

namespace bookspin::clip {

namespace {

/// A single scene: the one picture is the frame, decorated as render_frame() does (frame.hpp).
class SingleComposer final : public Composer {
 public:
  explicit SingleComposer(const scene::Scene& scene) : decorator_(scene) {}
  render::RenderSettings picture_settings(const scene::Scene& first_tile) const override {
    return render_settings_for(first_tile);
  }
  RgbaImage compose(std::vector<RgbaImage>& pictures, const Tiles& tiles) override {
    RgbaImage frame = std::move(pictures.front());
    const TileShown& shown = tiles.front()->shown;
    decorator_.decorate(frame, shown.t, shown.diverged_at, shown.history);
    return frame;
  }

 private:
  charts::FrameDecorator decorator_;
};

/// A tile's picture between Renderer::submit() and its collection: what the frame's
/// decoration and CSV rows need, since the simulation has moved on by then.
struct InFlight {
  int index = 0;         ///< the video frame
  std::size_t tile = 0;  ///< its tile
  double t = 0.0;
  std::optional<double> diverged_at;
  physics::Diagnostics diagnostics;
  physics::Corners corners;  ///< for the orientation (Poinsot's construction)
  bool fresh = false;        ///< a newly simulated pose (else the held last finite one)
};

/// The display side of the loop: takes the tiles' pictures in the order they were
/// submitted and, once a frame's are all there, composes it.
class FrameFinisher {
 public:
  FrameFinisher(Composer& composer, Tiles& tiles) : composer_(composer), tiles_(tiles) {}

  void expect(InFlight picture) { in_flight_.push_back(std::move(picture)); }

  /// Moves the oldest picture's tile on to the pose it shows, with the panel curves as they
  /// were at its time; after the frame's last tile, the composed frame with its CSV rows.
  std::optional<ClipFrame> take(RgbaImage picture) {
    InFlight shown = std::move(in_flight_.front());
    in_flight_.pop_front();
    TileShown& tile = tiles_[shown.tile]->shown;
    if (shown.fresh) tile.history.add(shown.diagnostics, &shown.corners);
    tile.t = shown.t;
    tile.diverged_at = shown.diverged_at;
    tile.diagnostics = shown.diagnostics;
    pictures_.push_back(std::move(picture));
    if (pictures_.size() < tiles_.size()) return std::nullopt;
    ClipFrame frame;
    frame.index = shown.index;
    frame.t = tiles_.front()->shown.t;
    for (const auto& run : tiles_) frame.rows.push_back(run->shown.row());
    frame.image = composer_.compose(pictures_, tiles_);
    pictures_.clear();
    return frame;
  }

 private:
  Composer& composer_;
  Tiles& tiles_;
  std::deque<InFlight> in_flight_;
  std::vector<RgbaImage> pictures_;  ///< the frame's pictures taken so far, in tile order
};

/// The tiles of `scene`: itself, or one per [[compare]] entry (scene::tile_scene), each
/// simulating its scene's model or, given `models`, the caller's.
Tiles tiles_of(const scene::Scene& scene, const std::vector<TileModel>& models) {
  std::vector<scene::Scene> scenes;
  if (scene.compare.empty()) scenes.push_back(scene);
  for (const auto& tile : scene.compare) scenes.push_back(tile_scene(scene, tile));
  BOOKSPIN_ASSERT(models.empty() || models.size() == scenes.size());
  Tiles tiles;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    if (models.empty())
      tiles.push_back(std::make_unique<TileRun>(std::move(scenes[i])));
    else
      tiles.push_back(
          std::make_unique<TileRun>(std::move(scenes[i]), models[i].make(), models[i].model_line));
  }
  return tiles;
}

}  // namespace

std::unique_ptr<Composer> single_composer(const scene::Scene& scene) {
  return std::make_unique<SingleComposer>(scene);
}

/// The loop's state, in the order it is made: the tiles' scenes outlive the composer, which
/// the renderer's settings come from.
struct FrameLoop::State {
  State(scene::Scene s, const std::vector<TileModel>& models)
      : scene(std::move(s)),
        tiles(tiles_of(scene, models)),
        composer(scene.compare.empty() ? single_composer(scene) : comparison_composer(scene)),
        renderer(composer->picture_settings(tiles.front()->scene)),
        finisher(*composer, tiles) {}
  scene::Scene scene;
  Tiles tiles;
  std::unique_ptr<Composer> composer;
  render::Renderer renderer;
  FrameFinisher finisher;
  int index = 0;         ///< the frame whose tiles are being submitted
  std::size_t tile = 0;  ///< the next tile of it to submit
};

FrameLoop::FrameLoop(scene::Scene scene, const std::vector<TileModel>& tile_models)
    : state_(std::make_unique<State>(std::move(scene), tile_models)) {}

FrameLoop::~FrameLoop() = default;

int FrameLoop::frames() const { return state_->scene.frames; }

std::size_t FrameLoop::tiles() const { return state_->tiles.size(); }

std::optional<ClipFrame> FrameLoop::next(const StopPoll& stop, const SpareFrames& spare) {
  State& s = *state_;
  while (s.index < s.scene.frames) {
    if (s.tile == 0) stop_if_asked(stop, "render frames");  // the sinks remove their temporaries
    TileRun& tile = *s.tiles[s.tile];
    const bool fresh = advance(tile.source, s.index, tile.scene, tile.frame);
    s.renderer.submit(tile.drawing.input_for(tile.frame.picture()));
    s.finisher.expect({s.index, s.tile, tile.frame.t, tile.frame.diverged_at,
                       tile.frame.pose.diagnostics, tile.frame.pose.corners, fresh});
    if (++s.tile == s.tiles.size()) {
      s.tile = 0;
      ++s.index;
    }
    // While this picture is drawn and read back, the previous one is composed.
    if (spare) {
      if (auto buffer = spare()) s.renderer.recycle(std::move(*buffer));
    }
    if (auto picture = s.renderer.collect()) {
      if (auto frame = s.finisher.take(std::move(*picture))) return frame;
    }
  }
  while (auto picture = s.renderer.flush()) {
    if (auto frame = s.finisher.take(std::move(*picture))) return frame;
  }
  return std::nullopt;
}

void FrameLoop::record_divergence(ClipResult& result) const {
  const Tiles& tiles = state_->tiles;
  if (state_->scene.compare.empty()) {
    result.diverged_at = tiles.front()->frame.diverged_at;
    result.divergence_reason = tiles.front()->source.divergence_reason();
    return;
  }
  for (const auto& tile : tiles) {
    if (tile->frame.diverged_at)
      result.diverged_tiles.push_back({tile->scene.title, *tile->frame.diverged_at});
  }
}

ClipResult render_clip(const ClipRequest& request) {
  const SinkOptions options = sink_options(request);
  FrameLoop loop(request.scene, request.tile_models);
  BOOKSPIN_ASSERT(request.tile_csvs.size() + 1 == loop.tiles());
  ClipSinks sinks(request.paths, options, request.tile_csvs);

  ClipResult result;
  result.mp4_encoder = sinks.mp4_encoder();
  result.encoder_fallback = sinks.encoder_message();
  const SpareFrames spare = [&sinks] { return sinks.spare_frame(); };
  while (auto frame = loop.next(request.stop_signal, spare)) {
    sinks.add(frame->index, std::move(frame->image), frame->rows);
    result.frames = frame->index + 1;
    if (request.on_progress) request.on_progress(result.frames);
  }
  loop.record_divergence(result);
  output::OutputSet outputs;
  sinks.finish(outputs);
  commit_unless_stopped(request, outputs);
  return result;
}

}  // namespace bookspin::clip
