// Every figure scene, rendered exactly as `bookspin render` renders it (at 256×256), must
// match its goldens: the first, middle and last frame. This pins faces, orientation,
// physics (a changed simulator moves the book) and the caption and banner overlays.
#include <gtest/gtest.h>

#include "clip/frame.hpp"
#include "golden_store.hpp"
#include "picture_scenes.hpp"

namespace bookspin::picture {
namespace {

class FigureGoldens : public ::testing::TestWithParam<std::string> {};

TEST_P(FigureGoldens, FirstMiddleAndLastFramesMatch) {
  const scene::Scene scene = figure_scene(GetParam());
  expect_pinned_frames_match(scene);
}

INSTANTIATE_TEST_SUITE_P(Scenes, FigureGoldens, ::testing::ValuesIn(figure_scene_names()),
                         [](const auto& info) { return test_name(info.param); });

// These figures show a simulation blowing up (README, "The figures"); their last frame must
// hold the last finite pose under the "diverged at" banner, so its golden pins that too.
TEST(FigureGoldens, DivergingFiguresEndOnTheDivergenceBanner) {
  for (const char* name : {"fig07-particle-no-normalization", "fig08-particle-neither",
                           "fig10-matrix-no-normalization"}) {
    const scene::Scene scene = figure_scene(name);
    EXPECT_TRUE(clip::simulate_to(scene, pinned_frames(scene.frames).back()).diverged_at) << name;
  }
}

}  // namespace
}  // namespace bookspin::picture
