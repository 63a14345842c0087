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
/// submitted and, once a frame's are all there, composes it and hands it to the sinks.
class FrameFinisher {
 public:
  FrameFinisher(const ClipRequest& request, Composer& composer, Tiles& tiles, ClipSinks& sinks,
                ClipResult& result)
      : request_(request), composer_(composer), tiles_(tiles), sinks_(sinks), result_(result) {}

  void expect(InFlight picture) { in_flight_.push_back(std::move(picture)); }

  /// Moves the oldest picture's tile on to the pose it shows, with the panel curves as they
  /// were at its time; after the frame's last tile, composes the frame and queues it and its
  /// CSV rows.
  void take(RgbaImage picture) {
    InFlight shown = std::move(in_flight_.front());
    in_flight_.pop_front();
    TileShown& tile = tiles_[shown.tile]->shown;
    if (shown.fresh) tile.history.add(shown.diagnostics, &shown.corners);
    tile.t = shown.t;
    tile.diverged_at = shown.diverged_at;
    tile.diagnostics = shown.diagnostics;
    pictures_.push_back(std::move(picture));
    if (pictures_.size() < tiles_.size()) return;
    rows_.clear();
    for (const auto& run : tiles_) rows_.push_back(run->shown.row());
    RgbaImage frame = composer_.compose(pictures_, tiles_);
    pictures_.clear();
    sinks_.add(shown.index, std::move(frame), rows_);
    result_.frames = shown.index + 1;
    if (request_.on_progress) request_.on_progress(result_.frames);
  }

  /// After the last frame: a single scene's divergence (time and the simulator's reason), or
  /// every diverged tile of a comparison, into the result.
  void record_divergence() {
    if (request_.scene.compare.empty()) {
      result_.diverged_at = tiles_.front()->frame.diverged_at;
      result_.divergence_reason = tiles_.front()->source.divergence_reason();
      return;
    }
    for (const auto& tile : tiles_) {
      if (tile->frame.diverged_at)
        result_.diverged_tiles.push_back({tile->scene.title, *tile->frame.diverged_at});
    }
  }

 private:
  const ClipRequest& request_;
  Composer& composer_;
  Tiles& tiles_;
  ClipSinks& sinks_;
  ClipResult& result_;
  std::deque<InFlight> in_flight_;
  std::vector<RgbaImage> pictures_;  ///< the frame's pictures taken so far, in tile order
  std::vector<physics::Diagnostics> rows_;
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

ClipResult render_clip(const ClipRequest& request) {
  const scene::Scene& scene = request.scene;
  const SinkOptions options = sink_options(request);
  Tiles tiles = tiles_of(scene, request.tile_models);
  BOOKSPIN_ASSERT(request.tile_csvs.size() + 1 == tiles.size());
  const std::unique_ptr<Composer> composer =
      scene.compare.empty() ? single_composer(scene) : comparison_composer(scene);
  render::Renderer renderer(composer->picture_settings(tiles.front()->scene));
  ClipSinks sinks(request.paths, options, request.tile_csvs);

  ClipResult result;
  result.mp4_encoder = sinks.mp4_encoder();
  result.encoder_fallback = sinks.encoder_message();
  FrameFinisher finisher(request, *composer, tiles, sinks, result);
  for (int index = 0; index < scene.frames; ++index) {
    stop_if_asked(request.stop_signal, "render frames");  // the sinks remove their temporaries
    for (std::size_t i = 0; i < tiles.size(); ++i) {
      TileRun& tile = *tiles[i];
      const bool fresh = advance(tile.source, index, tile.scene, tile.frame);
      renderer.submit(tile.drawing.input_for(tile.frame.pose));
      finisher.expect({index, i, tile.frame.t, tile.frame.diverged_at, tile.frame.pose.diagnostics,
                       tile.frame.pose.corners, fresh});
      // While this picture is drawn and read back, the previous one is composed and queued.
      if (auto spare = sinks.spare_frame()) renderer.recycle(std::move(*spare));
      if (auto picture = renderer.collect()) finisher.take(std::move(*picture));
    }
  }
  while (auto picture = renderer.flush()) finisher.take(std::move(*picture));
  finisher.record_divergence();
  output::OutputSet outputs;
  sinks.finish(outputs);
  commit_unless_stopped(request, outputs);
  return result;
}

}  // namespace bookspin::clip
