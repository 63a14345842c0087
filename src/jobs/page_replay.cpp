#include "jobs/page_replay.hpp"

#include <Eigen/Geometry>

#include "analysis/frame_source.hpp"

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

}  // namespace bookspin::jobs
