#include "jobs/page_replay.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "analysis/frame_source.hpp"
#include "output/data_url.hpp"
#include "scene/page_data.hpp"

namespace bookspin::jobs {

std::vector<ReplayedTile> page_replays(const scene::Scene& scene, const StopPoll& stop) {
  std::vector<ReplayedTile> replays;
  for (std::size_t i = 0; i < scene.compare.size(); ++i) {
    const scene::CompareTile& tile = scene.compare[i];
    if (!physics::is_engine(tile.model.kind)) continue;
    const scene::Scene tile_run = scene::tile_scene(scene, tile);
    analysis::FrameSource source(tile_run);
    std::vector<Eigen::Vector4d> q;
    std::vector<Eigen::Vector3d> omega;
    physics::Pose pose;
    for (stop_if_asked(stop, "explore replays"); source.next(pose);
         stop_if_asked(stop, "explore replays")) {
      const physics::Diagnostics& d = pose.diagnostics;
      const Eigen::Quaterniond r(d.orientation);
      Eigen::Vector4d wxyz(r.w(), r.x(), r.y(), r.z());
      wxyz.normalize();
      // q and −q are one orientation: the sign nearest the last sample's, for a smooth series.
      if (q.empty() ? wxyz[0] < 0.0 : wxyz.dot(q.back()) < 0.0) wxyz = -wxyz;
      q.push_back(wxyz);
      omega.push_back(d.orientation * d.omega_body);
    }
    ReplayedTile out;
    out.tile = i;
    out.label = tile.label;
    out.frame_dt = tile_run.dt * tile_run.steps_per_frame;
    out.q.resize(4, static_cast<Eigen::Index>(q.size()));
    out.omega_world.resize(3, static_cast<Eigen::Index>(omega.size()));
    for (std::size_t k = 0; k < q.size(); ++k) {
      out.q.col(static_cast<Eigen::Index>(k)) = q[k];
      out.omega_world.col(static_cast<Eigen::Index>(k)) = omega[k];
    }
    replays.push_back(std::move(out));
  }
  return replays;
}

namespace {

/// `values` (each within ±`scale`) as little-endian 16-bit integers, value·32767/scale rounded,
/// in a data: URL: a replayed motion stored compactly (docs/explorer.md, "Comparison"; the page
/// reads them back in web/src/tile_replay.js).
JsonValue quantised(const double* values, std::size_t count, double scale) {
  std::vector<std::uint8_t> bytes;
  bytes.reserve(2 * count);
  for (std::size_t i = 0; i < count; ++i) {
    const double v = std::clamp(values[i] / scale, -1.0, 1.0);
    const auto q = static_cast<std::uint16_t>(static_cast<std::int16_t>(std::lround(v * 32767)));
    bytes.push_back(static_cast<std::uint8_t>(q & 0xff));
    bytes.push_back(static_cast<std::uint8_t>(q >> 8));
  }
  return {output::data_url("application/octet-stream", bytes)};
}

/// The scene's tiles the page cannot step, as page_replays runs them, the way the page reads
/// them: per tile its index, label, time between samples (`frameDt`), `frames`, `q` (w, x, y, z
/// per frame, ×32767) and `w` (world-frame ω per frame, ×32767/`wScale`), quantised.
JsonArray replays_data(const scene::Scene& scene, const StopPoll& stop) {
  JsonArray out;
  for (const jobs::ReplayedTile& r : jobs::page_replays(scene, stop)) {
    if (r.q.cols() == 0) continue;
    const double scale = std::max(r.omega_world.cwiseAbs().maxCoeff(), 1e-300);
    out.push_back(
        {JsonObject{{"tile", {static_cast<std::int64_t>(r.tile)}},
                    {"label", {r.label}},
                    {"frameDt", {r.frame_dt}},
                    {"frames", {static_cast<std::int64_t>(r.q.cols())}},
                    {"q", quantised(r.q.data(), static_cast<std::size_t>(r.q.size()), 1.0)},
                    {"w", quantised(r.omega_world.data(),
                                    static_cast<std::size_t>(r.omega_world.size()), scale)},
                    {"wScale", {scale}}}});
  }
  return out;
}

}  // namespace

JsonObject explorer_scene_data(const scene::Scene& scene, const StopPoll& stop) {
  JsonObject data = scene::page_data(scene);
  if (JsonArray replays = replays_data(scene, stop); !replays.empty())
    data.push_back({"replays", {std::move(replays)}});
  // A scenario of the conformance kit (scenes/flipcheck/): the ones the page's judge offers.
  if (scene.source.parent_path().filename() == "flipcheck") data.push_back({"kit", {true}});
  return data;
}

}  // namespace bookspin::jobs
