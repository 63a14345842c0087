// Poinsot's construction inset (render.poinsot; docs/physics.md §16) is part of the picture:
// the first, middle and last frames of exact-unstable-x (the book) and of t-handle-dzhanibekov
// are pinned with the plot panel at 640×360. The geometry itself is tested against closed
// forms in tests/physics/poinsot_test.cpp; these pin what the inset draws of it.
#include <gtest/gtest.h>

#include "picture_scenes.hpp"

namespace bookspin::picture {
namespace {

const std::vector<std::string> kPoinsotOn{"render.width=640", "render.height=360",
                                          "render.panel=true", "render.poinsot=true"};

class PoinsotGoldens : public ::testing::TestWithParam<std::string> {};

TEST_P(PoinsotGoldens, FirstMiddleAndLastFramesMatch) {
  const scene::Scene scene = figure_scene(GetParam(), kPoinsotOn);
  ASSERT_TRUE(scene.render.poinsot);
  expect_pinned_frames_match(scene, "poinsot-");
}

INSTANTIATE_TEST_SUITE_P(Scenes, PoinsotGoldens,
                         ::testing::Values("exact-unstable-x", "t-handle-dzhanibekov"),
                         [](const auto& info) { return test_name(info.param); });

}  // namespace
}  // namespace bookspin::picture
