// The keys that sweeps over the step and the normalization interval need: model.normalize_every
// (docs/physics.md §18) and time.duration (scenes/README.md).
#include <gtest/gtest.h>

#include "scene/scene.hpp"
#include "scene_text.hpp"

namespace bookspin::scene {
namespace {

using testing::error_of;
using testing::parse;

TEST(NormalizeEveryKey, NeedsNormalizeAndReachesEveryTile) {
  EXPECT_EQ(parse("[model]\nnormalize = true\n").model.normalize_every, 1);
  EXPECT_EQ(parse("[model]\nnormalize = true\nnormalize_every = 40\n").model.normalize_every, 40);
  EXPECT_NE(error_of("[model]\nnormalize_every = 40\n")
                .find("model.normalize_every: needs model.normalize = true"),
            std::string::npos);
  // A comparison tile inherits the interval; one that turns normalization off ignores it.
  const Scene s = parse(
      "[model]\nkind = \"rigid-matrix\"\nnormalize = true\nnormalize_every = 5\n"
      "[[compare]]\nlabel = \"every 5\"\n[[compare]]\nlabel = \"never\"\nmodel.normalize = "
      "false\n");
  EXPECT_EQ(s.compare[0].model.normalize_every, 5);
  EXPECT_FALSE(s.compare[1].model.normalize);
}

TEST(DurationKey, GivesTheFramesThatCoverIt) {
  // 2209.46 time units at dt = 1/8, 10 steps a frame: 1767.568 frames of time after frame 0.
  const Scene s = parse("[time]\ndt = 0.125\nsteps_per_frame = 10\nduration = 2209.46\n");
  EXPECT_EQ(s.frames, 1 + 1768);
  // An exact multiple needs no extra frame.
  EXPECT_EQ(parse("[time]\ndt = 0.5\nsteps_per_frame = 2\nduration = 30\n").frames, 31);
  EXPECT_NE(error_of("[time]\nframes = 10\nduration = 30\n")
                .find("time.duration: give either time.frames or time.duration"),
            std::string::npos);
  EXPECT_NE(error_of("[time]\ndt = 0.001\nsteps_per_frame = 1\nduration = 1000\n")
                .find("time.duration: needs 1000001 frames"),
            std::string::npos);
}

}  // namespace
}  // namespace bookspin::scene
