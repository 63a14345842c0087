// Stills that pin the face mapping (docs/physics.md §1): the book at rest at identity seen along
// each body axis must show the front cover (+z), back cover (−z), spine (+x) and page
// edges (−x), upright and unmirrored; plus a figure frame with both 3-D overlays on.
#include <gtest/gtest.h>

#include "clip/frame.hpp"
#include "golden_store.hpp"
#include "picture_scenes.hpp"

namespace bookspin::picture {
namespace {

struct View {
  const char* name;       ///< golden: face-<name>
  const char* direction;  ///< render.camera_direction (TOML)
};

void PrintTo(const View& view, std::ostream* out) { *out << view.name; }  // for failure messages

class FaceMapping : public ::testing::TestWithParam<View> {};

TEST_P(FaceMapping, BookAtIdentityShowsTheRightFace) {
  const scene::Scene scene = book_at_rest(GetParam().name, GetParam().direction);
  EXPECT_TRUE(matches_golden(std::string("face-") + GetParam().name,
                             clip::render_still(scene, renderer_for(scene), 0)));
}

INSTANTIATE_TEST_SUITE_P(Views, FaceMapping,
                         ::testing::Values(View{"front-from-plus-z", "[0.0, 0.0, 1.0]"},
                                           View{"back-from-minus-z", "[0.0, 0.0, -1.0]"},
                                           View{"spine-from-plus-x", "[1.0, 0.0, 0.0]"},
                                           View{"pages-from-minus-x", "[-1.0, 0.0, 0.0]"}),
                         [](const auto& info) { return test_name(info.param.name); });

TEST(Overlays, AngularMomentumAndBodyAxesMatch) {
  const scene::Scene scene =
      figure_scene("fig09-matrix-unstable-x",
                   {"render.show_angular_momentum=true", "render.show_body_axes=true"});
  const int index = pinned_frames(scene.frames)[1];
  EXPECT_TRUE(matches_golden(golden_name("overlays-" + scene.name, index),
                             clip::render_still(scene, renderer_for(scene), index)));
}

}  // namespace
}  // namespace bookspin::picture
