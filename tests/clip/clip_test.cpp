// The clip loop's single-scene composer (clip.cpp), without a GL context: its pictures are
// framed as render_settings_for(scene) frames them, and each frame is decorated exactly as
// charts::decorate_frame decorates a still (frame.hpp's promise that a clip's frame is pixel
// for pixel render_frame()'s). render_clip itself draws with GL: the clips are tested through
// the program (tests/cli/render_command_test.cpp, tests/cli/compare_test.cpp) and their
// frames against the goldens (tests/picture/).
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "charts/decoration.hpp"
#include "clip/composer.hpp"
#include "support/test_images.hpp"

namespace bookspin::clip {
namespace {

scene::Scene small_scene(std::vector<std::string> more = {}) {
  more.insert(more.end(), {"render.width=320", "render.height=240", "time.frames=4"});
  return scene::parse_scene_text("[scene]\ntitle = \"A test\"\n", "clip_test.toml", more);
}

TEST(Clip, ASingleScenesPictureIsFramedAsItsStill) {
  const scene::Scene scene = small_scene({"render.panel=true"});
  const auto composer = single_composer(scene);
  const render::RenderSettings picture = composer->picture_settings(scene);
  const render::RenderSettings still = render_settings_for(scene);
  EXPECT_EQ(picture.width, 320);
  EXPECT_EQ(picture.height, 240);
  EXPECT_EQ(picture.camera.eye, still.camera.eye);
  EXPECT_EQ(picture.camera.target, still.camera.target);
}

// The composed frame is the picture with decorate_frame's decoration, and no other change:
// for a plain scene (caption only) and one with the panel, the sphere and Poinsot's inset.
TEST(Clip, ASingleScenesFrameIsThePictureDecoratedAsAStill) {
  for (const auto& overrides : std::vector<std::vector<std::string>>{
           {}, {"render.panel=true", "render.sphere=true", "render.poinsot=true"}}) {
    const scene::Scene scene = small_scene(overrides);
    Tiles tiles;
    tiles.push_back(std::make_unique<TileRun>(scene));
    tiles.front()->shown.t = 2.5;
    std::vector<RgbaImage> pictures{test::gradient_frame(320, 240)};
    const auto composer = single_composer(scene);
    const RgbaImage frame = composer->compose(pictures, tiles);

    RgbaImage expected = test::gradient_frame(320, 240);
    charts::decorate_frame(expected, scene, 2.5, std::nullopt, charts::DiagnosticsHistory{});
    EXPECT_EQ(frame.width, 320);
    EXPECT_EQ(frame.height, 240);
    EXPECT_TRUE(frame.pixels == expected.pixels);
    // And the decoration is there: the frame is not the bare picture.
    EXPECT_FALSE(frame.pixels == test::gradient_frame(320, 240).pixels);
  }
}

}  // namespace
}  // namespace bookspin::clip
