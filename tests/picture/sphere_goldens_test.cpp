// The momentum sphere inset (render.sphere; docs/physics.md §15) is part of the picture: the
// first, middle and last frames of fig09 (Euler: the trail drifts off its polhode) and of
// exact-unstable-x (the trail stays on it) are pinned, with the plot panel, at 640×360 —
// large enough for the inset's labels to be read in the goldens; and one comparison frame.
#include <gtest/gtest.h>

#include <cstdlib>

#include "golden_store.hpp"
#include "output/png_writer.hpp"
#include "picture_scenes.hpp"

namespace bookspin::picture {
namespace {

// The Poinsot inset is pinned by poinsot_goldens_test.cpp.
const std::vector<std::string> kSphereOn{"render.width=640", "render.height=360",
                                         "render.sphere=true", "render.poinsot=false"};

class SphereGoldens : public ::testing::TestWithParam<std::string> {};

TEST_P(SphereGoldens, FirstMiddleAndLastFramesMatch) {
  const scene::Scene scene = figure_scene(GetParam(), kSphereOn);
  ASSERT_TRUE(scene.render.sphere);
  expect_pinned_frames_match(scene, "sphere-");
}

INSTANTIATE_TEST_SUITE_P(Scenes, SphereGoldens,
                         ::testing::Values("fig09-matrix-unstable-x", "exact-unstable-x",
                                           "fig10-matrix-no-normalization"),
                         [](const auto& info) { return test_name(info.param); });

// A comparison draws one trail per tile, in the tile's plot colour, atop the plot column. By
// frame 299 the particle model's trail has turned back towards +x while the rigid and exact
// ones (in lockstep, drawn narrower on top of each other) have not.
TEST(SphereGoldens, ComparisonDrawsOneTrailPerTile) {
  const RgbaImage frame =
      rendered_frame("compare-methods-x", 299, 640, 360, {"render.sphere=true"}, "sphere-compare");
  EXPECT_TRUE(matches_golden("sphere-compare-methods-x-f0299", frame));
}

}  // namespace
}  // namespace bookspin::picture
