#pragma once
// What a caller asks of the pipeline for one clip, and what it gets back. No command-line
// types: the clip product (products/clip.hpp), the bench and tests build a ClipRequest and
// call render_clip().
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "clip/clip_sinks.hpp"
#include "common/stop.hpp"
#include "scene/scene.hpp"

namespace bookspin::clip {

/// A tile's simulator made by the caller rather than from its scene's model (a motion given,
/// not simulated: physics::ReplayModel), and the caption's words for it.
struct TileModel {
  std::function<std::unique_ptr<physics::Simulator>()> make;  ///< called once, at the start
  std::string model_line;  ///< replaces scene::model_line() in the tile's caption
};

struct ClipRequest {
  scene::Scene scene;  ///< validated; scene.frames is the clip's length
  /// Where the videos, frames and the diagnostics CSV (a comparison's first tile's) go: the
  /// clip product's layout (products/clip.hpp).
  ClipPaths paths;
  /// A comparison: the diagnostics CSVs of its tiles after the first, in tile order.
  std::vector<std::filesystem::path> tile_csvs;
  /// One per tile (a single scene: one), in tile order, or empty: every tile simulates its
  /// scene's model (engines::make_model).
  std::vector<TileModel> tile_models;
  bool write_png = true;     ///< false: MP4 and CSV only
  int png_compression = -1;  ///< deflate level 0–9 for the frames; −1: render.png_compression
  int jobs = 0;              ///< worker threads (PNG, encoder); 0: every core
  /// Called after each frame is queued, with the number of frames done so far.
  std::function<void(int done)> on_progress;
  /// Polled before each frame ("render frames") and while the encoders finish (see
  /// SinkOptions::stop): the signal asking the clip to stop (SIGINT, SIGTERM), or 0.
  StopPoll stop_signal;
};

/// A tile of a comparison whose simulation diverged (its tile holds the last finite frame).
struct TileDivergence {
  std::string label;
  double t = 0.0;  ///< time units
};

struct ClipResult {
  int frames = 0;                     ///< frames handed to the sinks
  std::optional<double> diverged_at;  ///< single scene: when its simulation diverged
  std::string divergence_reason;      ///< single scene: the simulator's reason, if it gave one
  std::vector<TileDivergence> diverged_tiles;  ///< comparison scene: every diverged tile
  /// The H.264 encoder that made the MP4 ("libx264", "h264_nvenc"): render.codec's, or libx264
  /// when that one is missing or did not open. Empty without an MP4.
  std::string mp4_encoder;
  /// Why libx264 made the MP4 rather than render.codec's encoder, in one line ("encoder
  /// \"h264_nvenc\" failed to open: …; using libx264"); empty when it did not fall back.
  std::string encoder_fallback;
};

/// The encoder settings of a render of `scene` (render.width, height, fps, codec, crf,
/// preset) with `jobs` threads (0: the encoder's own choice for all cores).
video::EncoderSettings encoder_settings(const scene::Scene& scene, int jobs);

/// Sink settings from the scene's render.* keys and the request's options.
SinkOptions sink_options(const ClipRequest& request);

/// The end of a clip: unless request.stop_signal() asks to stop (Interrupted is thrown and
/// nothing is put in place), puts every complete output of the run in place together
/// (`outputs.commit()`: all or none). Throws OutputError from the commit.
void commit_unless_stopped(const ClipRequest& request, output::OutputSet& outputs);

}  // namespace bookspin::clip
