// The motions the explorer page replays (jobs::page_replays, docs/explorer.md "Comparison"):
// the other engines' tiles alone, each as its model steps from the scene's start, a sample every
// steps_per_frame steps (the model stepped here directly, not through the clip's frame loop).
#include "jobs/page_replay.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <variant>
#include <vector>

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

/// The member `key` of `object`; fails the test where there is none.
const JsonValue& member(const JsonObject& object, const std::string& key) {
  for (const JsonMember& m : object)
    if (m.key == key) return m.value;
  ADD_FAILURE() << "no member " << key;
  static const JsonValue none;
  return none;
}

/// The bytes of a base64 data: URL (RFC 4648 §4), decoded here.
std::vector<std::uint8_t> data_url_bytes(const std::string& url) {
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<std::uint8_t> out;
  unsigned bits = 0, count = 0;
  for (char c : url.substr(url.find(',') + 1)) {
    if (c == '=') break;
    bits = (bits << 6) | static_cast<unsigned>(alphabet.find(c));
    if ((count += 6) >= 8) {
      count -= 8;
      out.push_back(static_cast<std::uint8_t>((bits >> count) & 0xff));
    }
  }
  return out;
}

// The page reads a replay's world ω back from 16-bit integers times wScale/32767
// (web/src/tile_replay.js): every sample within half a step of 16 bits of the motion, for a
// motion whose largest component is negative too (the scale is the largest |ω| component: one
// taken from the largest signed component, 0.02 here, clamps the −0.5 spin to −0.02).
TEST(PageReplays, ThePageReadsEachOmegaBackWithinHalfAStepOfSixteenBits) {
  const scene::Scene scene = scene::parse_scene_text(
      "[initial]\nangular_velocity = [-0.5, 0.01, 0.02]\njiggle = 0.001\n"
      "[time]\ndt = 0.05\nsteps_per_frame = 3\nframes = 40\n"
      "[[compare]]\nlabel = \"exact\"\nmodel.kind = \"exact\"\n"
      "[[compare]]\nlabel = \"m\"\nmodel.kind = \"mujoco\"\n",
      "replay.toml", {});
  const std::vector<ReplayedTile> replays = page_replays(scene);
  ASSERT_EQ(replays.size(), 1u);
  const Eigen::Matrix3Xd& w = replays[0].omega_world;
  const JsonObject data = explorer_scene_data(scene);
  const auto& list = std::get<JsonArray>(member(data, "replays").value);
  ASSERT_EQ(list.size(), 1u);
  const auto& replay = std::get<JsonObject>(list[0].value);
  const double scale = std::get<double>(member(replay, "wScale").value);
  const std::vector<std::uint8_t> bytes =
      data_url_bytes(std::get<std::string>(member(replay, "w").value));
  ASSERT_EQ(bytes.size(), 2u * static_cast<std::size_t>(w.size()));
  for (Eigen::Index i = 0; i < w.size(); ++i) {
    const auto raw = static_cast<std::int16_t>(bytes[2 * i] | (bytes[2 * i + 1] << 8));
    const double read = raw * scale / 32767;
    EXPECT_LE(std::abs(read - w.data()[i]), 0.5 * w.cwiseAbs().maxCoeff() / 32767 * (1 + 1e-9))
        << "component " << i << ": " << w.data()[i] << " read back as " << read;
  }
}

}  // namespace
}  // namespace bookspin::jobs
