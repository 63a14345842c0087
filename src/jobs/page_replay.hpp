#pragma once
// Physics only: the motions the explorer page replays (docs/explorer.md, "Comparison"): the
// [[compare]] tiles of a scene that the page cannot step itself (the other engines' models,
// MuJoCo, Bullet and ODE: docs/engines.md) run as the clip runs them, one sample a frame, as a
// value that the explorer product embeds in the page, and the page's data of a scene with them.
#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "common/json_writer.hpp"
#include "common/stop.hpp"
#include "scene/scene.hpp"

namespace bookspin::jobs {

/// One tile's motion as the clip computes it (analysis::FrameSource on scene::tile_scene), a
/// sample at each frame from frame 0 to the scene's last or the tile's divergence.
struct ReplayedTile {
  std::size_t tile = 0;          ///< its index among the scene's [[compare]] tiles
  std::string label;             ///< the tile's label, as the clip captions it
  double frame_dt = 0.0;         ///< time units between samples: dt · steps_per_frame
  Eigen::Matrix4Xd q;            ///< each frame's orientation, body → world, (w, x, y, z), unit
  Eigen::Matrix3Xd omega_world;  ///< each frame's ω in the world frame (rad per time unit)
};

/// The scene's [[compare]] tiles whose model is another engine's (physics::is_engine), in tile
/// order, each run from the scene's start as the clip runs it; none for a scene without such
/// tiles. The quaternion's sign is kept continuous from frame to frame (w of frame 0 positive).
/// `stop` is polled before every frame ("explore replays"): a signal throws Interrupted.
std::vector<ReplayedTile> page_replays(const scene::Scene& scene, const StopPoll& stop = {});

/// The value the explorer page reads for one scene: scene::page_data(), and where the scene has
/// tiles the page cannot step, `replays`: per tile its index, label, time between samples
/// (`frameDt`), `frames`, `q` (w, x, y, z per frame, ×32767) and `w` (world-frame ω per frame,
/// ×32767/`wScale`), each little-endian 16-bit integers in a data: URL (docs/explorer.md,
/// "Comparison"; web/src/tile_replay.js reads them). Throws Interrupted as page_replays().
JsonObject explorer_scene_data(const scene::Scene& scene, const StopPoll& stop = {});

}  // namespace bookspin::jobs
