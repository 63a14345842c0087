// What a video frame shows, without drawing it (render_frame and render_still need a GL
// context: the goldens of tests/picture/ pin those): the pose of frame k at its time
// k · steps_per_frame · dt, and after a divergence the last finite pose held while the time
// runs on.
#include "clip/frame.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace bookspin::clip {
namespace {

// The exact model spun about the book's largest axis (z, its thickness) alone: a steady
// rotation, so at time t the corners are the rest corners turned by angle ω t about z.
TEST(Frame, FrameKShowsTheSteadySpinAtItsTime) {
  const scene::Scene scene =
      scene::parse_scene_text("[scene]\ntitle = \"A test\"\n", "frame_test.toml",
                              {"model.kind=\"exact\"", "initial.angular_velocity=[0.0, 0.0, 0.5]",
                               "time.dt=0.01", "time.steps_per_frame=10", "time.frames=40"});
  const ShownFrame frame = simulate_to(scene, 30);
  EXPECT_NEAR(frame.t, 3.0, 1e-12);  // 30 frames × 10 steps × 0.01
  EXPECT_FALSE(frame.diverged_at.has_value());
  const Eigen::Matrix3d turned =
      Eigen::AngleAxisd(0.5 * 3.0, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const physics::Corners expected = turned * scene.body.cage.body_corners();
  EXPECT_LT((frame.pose.corners - expected).cwiseAbs().maxCoeff(), 1e-9) << frame.pose.corners;

  const ShownFrame first = simulate_to(scene, 0);
  EXPECT_DOUBLE_EQ(first.t, 0.0);
  EXPECT_LT((first.pose.corners - scene.body.cage.body_corners()).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(Frame, AFrameOutsideTheClipIsOutOfRange) {
  const scene::Scene scene = scene::parse_scene_text(
      "[scene]\ntitle = \"A test\"\n", "frame_test.toml", {"time.frames=5", "scene.name=\"five\""});
  EXPECT_NO_THROW(simulate_to(scene, 4));
  EXPECT_THROW(simulate_to(scene, 5), std::out_of_range);
  EXPECT_THROW(simulate_to(scene, -1), std::out_of_range);
  try {
    simulate_to(scene, 7);
  } catch (const std::out_of_range& e) {
    EXPECT_EQ(std::string(e.what()), "frame 7 is outside five (5 frames)");
  }
}

// fig07 (the particle book without normalization) blows up within its clip (the goldens show
// its "diverged at" banner on the last frame): that frame holds a finite pose, and its time
// is still frame × steps_per_frame × dt.
TEST(Frame, AfterADivergenceTheLastFinitePoseIsHeldAndTheTimeRunsOn) {
  const scene::Scene scene = scene::parse_scene(std::filesystem::path(BOOKSPIN_SOURCE_DIR) /
                                                "scenes" / "fig07-particle-no-normalization.toml");
  const int last = scene.frames - 1;
  const ShownFrame frame = simulate_to(scene, last);
  ASSERT_TRUE(frame.diverged_at.has_value());
  EXPECT_NEAR(frame.t, last * 32 * 0.04, 1e-9);  // time.steps_per_frame = 32, time.dt = 0.04
  EXPECT_LT(*frame.diverged_at, frame.t);
  EXPECT_TRUE(frame.pose.corners.allFinite());
  // The pose held is the one of the last frame before the divergence.
  const int before = static_cast<int>(std::floor(*frame.diverged_at / (32 * 0.04)));
  const ShownFrame held = simulate_to(scene, before);
  EXPECT_FALSE(held.diverged_at.has_value());
  EXPECT_EQ(frame.pose.corners, held.pose.corners);
}

// fig08's particle book explodes from t ≈ 14 and diverges at 31.35: its last finite pose is
// the book blown far past the view, which the clip's last 4.5 s showed as an empty frame. The
// picture holds the last pose before the blow-up instead (its energy within a factor of two
// of the start's), a book of about its own size; the CSV's pose stays the last finite one.
TEST(Frame, AfterABlowUpThePictureHoldsTheLastPoseBeforeIt) {
  const scene::Scene scene = scene::parse_scene(std::filesystem::path(BOOKSPIN_SOURCE_DIR) /
                                                "scenes" / "fig08-particle-neither.toml");
  const ShownFrame frame = simulate_to(scene, scene.frames - 1);
  ASSERT_TRUE(frame.diverged_at.has_value());
  const auto span = [](const physics::Corners& c) {
    return (c.rowwise().maxCoeff() - c.rowwise().minCoeff()).maxCoeff();
  };
  const ShownFrame start = simulate_to(scene, 0);
  const double size = span(start.pose.corners);
  EXPECT_GT(span(frame.pose.corners), 10 * size);  // the last finite pose: exploded
  EXPECT_LT(span(frame.picture().corners), 2 * size) << frame.picture().corners;
  EXPECT_LT(std::abs(frame.picture().diagnostics.energy_total / frame.energy0 - 1.0), 1.0);
  // Before the divergence the picture is the pose itself.
  const ShownFrame early = simulate_to(scene, 10);
  EXPECT_EQ(early.picture().corners, early.pose.corners);
}

}  // namespace
}  // namespace bookspin::clip
