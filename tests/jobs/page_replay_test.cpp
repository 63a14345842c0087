// The motions the explorer page replays (jobs::page_replays, docs/explorer.md "Comparison"):
// the other engines' tiles alone, each as its model steps from the scene's start, a sample every
// steps_per_frame steps (the model stepped here directly, not through the clip's frame loop).
#include "jobs/page_replay.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <memory>

#include "engines/models.hpp"

namespace bookspin::jobs {
namespace {

TEST(PageReplays, TheEnginesTilesEachAFrameFromTheStart) {
  const scene::Scene scene = scene::parse_scene_text(
      "[initial]\nangular_velocity = [0.5, 0.01, 0.02]\njiggle = 0.001\n"
      "[time]\ndt = 0.05\nsteps_per_frame = 3\nframes = 40\n"
      "[[compare]]\nlabel = \"exact\"\nmodel.kind = \"exact\"\n"
      "[[compare]]\nlabel = \"m\"\nmodel.kind = \"mujoco\"\n"
      "[[compare]]\nlabel = \"q\"\nmodel.kind = \"rigid-quaternion\"\n"
      "[[compare]]\nlabel = \"b\"\nmodel.kind = \"bullet\"\nmodel.integrator = \"none\"\n",
      "replay.toml", {});
  const std::vector<ReplayedTile> replays = page_replays(scene);
  ASSERT_EQ(replays.size(), 2u);
  EXPECT_EQ(replays[0].tile, 1u);
  EXPECT_EQ(replays[0].label, "m");
  EXPECT_EQ(replays[1].tile, 3u);
  EXPECT_EQ(replays[1].label, "b");
  for (const ReplayedTile& r : replays) {
    EXPECT_DOUBLE_EQ(r.frame_dt, 0.15);
    ASSERT_EQ(r.q.cols(), 40);
    ASSERT_EQ(r.omega_world.cols(), 40);
    const scene::CompareTile& tile = scene.compare[r.tile];
    const std::unique_ptr<physics::Simulator> sim = engines::make_model(scene.body, tile.model);
    sim->reset(scene.initial);
    for (Eigen::Index k = 0; k < r.q.cols(); ++k) {
      if (k > 0)
        for (int s = 0; s < 3; ++s) sim->step(0.05);
      const Eigen::Matrix3d R = sim->orientation();
      const Eigen::Vector4d q = r.q.col(k);
      EXPECT_NEAR(q.norm(), 1.0, 1e-12);
      if (k == 0) {
        EXPECT_GT(q[0], 0.0);
      }
      if (k > 0) {
        EXPECT_GE(q.dot(r.q.col(k - 1)), 0.0) << "frame " << k;
      }
      const Eigen::Matrix3d Rq = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).toRotationMatrix();
      EXPECT_LT((Rq - R).norm(), 1e-12) << "frame " << k;
      const Eigen::Vector3d w = R * sim->diagnostics().omega_body;
      EXPECT_LT((r.omega_world.col(k) - w).norm(), 1e-12 * w.norm()) << "frame " << k;
    }
  }
  EXPECT_TRUE(page_replays(scene::parse_scene_text("[model]\nkind = \"mujoco\"\n", "one.toml", {}))
                  .empty());
}

}  // namespace
}  // namespace bookspin::jobs
