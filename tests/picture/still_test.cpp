// The goldens are only worth something if clip::render_still draws what `bookspin render`
// writes: compare the two byte for byte on the same machine.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>

#include "clip/frame.hpp"
#include "golden_store.hpp"
#include "output/png_writer.hpp"
#include "picture_scenes.hpp"
#include "support/scratch.hpp"

namespace bookspin::picture {
namespace {

std::string frame_file(int index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", index);
  return name;
}

TEST(RenderStill, IsWhatBookspinRenderWrites) {
  const char* scene_name = "fig09-matrix-unstable-x";
  const std::vector<std::string> overrides{"time.frames=3", "render.show_angular_momentum=true",
                                           "render.sphere=true"};
  const auto dir = test::fresh_dir("picture/render-still");
  std::string command = std::string(BOOKSPIN_EXE) + " render " + BOOKSPIN_SOURCE_DIR + "/scenes/" +
                        scene_name + ".toml -o " + dir.string() +
                        " --set render.width=" + std::to_string(kGoldenSize) +
                        " --set render.height=" + std::to_string(kGoldenSize);
  for (const auto& o : overrides) command += " --set " + o;
  ASSERT_EQ(std::system((command + " > /dev/null 2>&1").c_str()), 0) << command;
  const scene::Scene scene = figure_scene(scene_name, overrides);
  for (int index = 0; index < scene.frames; ++index) {
    const RgbaImage written = output::read_png(dir / scene.name / "frames" / frame_file(index));
    const RgbaImage still = clip::render_still(scene, renderer_for(scene), index);
    EXPECT_TRUE(written.width == still.width && written.pixels == still.pixels)
        << "frame " << index;
  }
  if (!::testing::Test::HasFailure()) std::filesystem::remove_all(dir);  // else keep for a look
}

}  // namespace
}  // namespace bookspin::picture
