// The bodies other than the book (docs/physics.md §12, §13) are pictures too: each body scene's
// first, middle and last frames are pinned at 512×288 with its panel and momentum sphere, and
// the lattice comparison at its first flip. Their physics is pinned by hashes of the first
// frames' diagnostics, as the figures' are.
#include <gtest/gtest.h>

#include <cstdlib>

#include "golden_store.hpp"
#include "output/png_writer.hpp"
#include "picture_scenes.hpp"

namespace bookspin::picture {
namespace {

// The Poinsot inset is pinned by poinsot_goldens_test.cpp; these pin the bodies and the sphere.
const std::vector<std::string> kBodySize{"render.width=512", "render.height=288",
                                         "render.sphere=true", "render.poinsot=false"};

class BodyGoldens : public ::testing::TestWithParam<std::string> {};

TEST_P(BodyGoldens, FirstMiddleAndLastFramesMatch) {
  const scene::Scene scene = figure_scene(GetParam(), kBodySize);
  ASSERT_NE(scene.body.shape, physics::BodyShape::book);
  expect_pinned_frames_match(scene);
}

INSTANTIATE_TEST_SUITE_P(Scenes, BodyGoldens,
                         ::testing::Values("t-handle-dzhanibekov", "tennis-racket", "phone-flip"),
                         [](const auto& info) { return test_name(info.param); });

// The lattice, the rigid body and the exact motion side by side, through `bookspin render`
// (one simulator per tile), at frame 45 (t = 4.5): just after the first flip, with the three
// T-handles turned over together.
TEST(BodyGoldens, LatticeComparisonFlipsWithTheRigidBodyAndTheExactMotion) {
  const RgbaImage frame =
      rendered_frame("compare-t-handle-models", 45, 512, 288, {}, "body-compare");
  EXPECT_TRUE(matches_golden("compare-t-handle-models-f0045", frame));
}

}  // namespace
}  // namespace bookspin::picture
