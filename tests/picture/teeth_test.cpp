// Negative tests: the comparison must have teeth. Each renders a golden's frame with one
// plausible bug — front and back textures swapped, the picture mirrored, the book turned by
// 3°, the clock one frame ahead — and asserts that the comparison fails, by far, for that
// reason (first checking that the unchanged frame passes, so the failure is the bug's).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "clip/frame.hpp"
#include "golden_store.hpp"
#include "output/png_writer.hpp"
#include "picture_scenes.hpp"
#include "render/face_images.hpp"
#include "support/scratch.hpp"

namespace bookspin::picture {
namespace {

constexpr const char* kScene = "fig09-matrix-unstable-x";

/// "Fails by far": the share of differing pixels is at least this many times the allowed
/// one, so that the bug is no borderline case (the subtlest, the 3° turn, is at ~3.7×).
constexpr double kMargin = 3.0;

class Teeth : public ::testing::Test {
 protected:
  void SetUp() override {
    if (update_mode()) GTEST_SKIP() << "goldens are being rewritten";
  }

  /// Compares a buggy frame with the golden, leaves the images for a look, and returns
  /// the comparison after checking that it failed by far.
  Comparison expect_caught(const std::string& golden, const RgbaImage& buggy,
                           const std::string& bug) {
    const Tolerance tolerance;
    const RgbaImage expected = read_golden(golden);
    const Comparison c = compare_images(buggy, expected, tolerance);
    const std::string images =
        write_failure_images(test::fresh_dir("picture/teeth-" + bug), buggy, expected, tolerance);
    std::cout << bug << ": " << c.summary(tolerance) << images << '\n';
    EXPECT_TRUE(c.same_size) << bug;
    EXPECT_FALSE(c.passed) << bug << " was not caught: " << c.summary(tolerance);
    EXPECT_GT(c.differing_fraction, kMargin * tolerance.max_differing_fraction)
        << bug << " is caught only narrowly: " << c.summary(tolerance);
    return c;
  }

  /// The golden's frame rendered correctly must pass, or the teeth prove nothing.
  void expect_unchanged_frame_passes(const scene::Scene& scene, int index) {
    ASSERT_TRUE(matches_golden(golden_name(scene.name, index),
                               clip::render_still(scene, renderer_for(scene), index)));
  }
};

/// Writes the generated default image of a face to a PNG, for render.texture_* keys.
std::string exported_face(render::FaceImage which, const std::string& file) {
  const auto path = test::fresh_dir("picture/teeth-textures-" + file) / (file + ".png");
  output::write_png(path, render::generate_face_image(which));
  return path.string();
}

TEST_F(Teeth, SwappedFrontAndBackTexturesAreCaught) {
  const std::string front = exported_face(render::FaceImage::front, "front");
  const std::string back = exported_face(render::FaceImage::back, "back");
  const scene::Scene scene = figure_scene(
      kScene, {"render.texture_front=\"" + back + "\"", "render.texture_back=\"" + front + "\""});
  expect_unchanged_frame_passes(figure_scene(kScene), 0);
  expect_caught(golden_name(kScene, 0), clip::render_still(scene, renderer_for(scene), 0),
                "swapped-textures");
}

// A renderer that flips a texture's u (the cover reads right to left) moves no edge of the
// book; only the artwork inside the cover changes.
TEST_F(Teeth, MirroredCoverArtIsCaught) {
  const auto path = test::fresh_dir("picture/teeth-textures-mirrored-front") / "front.png";
  output::write_png(path, mirrored(render::generate_face_image(render::FaceImage::front)));
  const scene::Scene scene = book_at_rest("front-from-plus-z", "[0.0, 0.0, 1.0]",
                                          {"render.texture_front=\"" + path.string() + "\""});
  expect_caught("face-front-from-plus-z", clip::render_still(scene, renderer_for(scene), 0),
                "mirrored-cover");
}

TEST_F(Teeth, MirroredFrameIsCaught) {
  const scene::Scene scene = figure_scene(kScene);
  expect_unchanged_frame_passes(scene, 0);
  const Comparison c =
      expect_caught(golden_name(kScene, 0),
                    mirrored(clip::render_still(scene, renderer_for(scene), 0)), "mirrored");
  // Not noise: whole regions change colour, so the PSNR is far below that of sub-pixel
  // rasterization differences (≥ 36 dB even for a half-pixel shift, see tolerance_test.cpp)
  // and some pixels change by most of the range.
  EXPECT_LT(c.psnr_db, 25.0);
  EXPECT_GT(c.max_channel_difference, 128);
}

// Mid-clip the book is mid-flip and tilted towards the camera, so a turn about y moves its
// outline and cover; at frame 0 it faces the camera and a 3° turn barely shows at 256².
TEST_F(Teeth, BookTurnedByThreeDegreesIsCaught) {
  const scene::Scene scene = figure_scene(kScene);
  const int index = pinned_frames(scene.frames)[1];
  expect_unchanged_frame_passes(scene, index);
  clip::ShownFrame frame = clip::simulate_to(scene, index);
  const Eigen::Matrix3d turn =
      Eigen::AngleAxisd(3.0 * M_PI / 180.0, Eigen::Vector3d::UnitY()).toRotationMatrix();
  frame.pose.corners = turn * frame.pose.corners;
  expect_caught(golden_name(kScene, index), clip::render_frame(scene, renderer_for(scene), frame),
                "turned-3deg");
}

TEST_F(Teeth, NextFrameIsCaught) {
  const scene::Scene scene = figure_scene(kScene);
  const int index = pinned_frames(scene.frames)[1];
  expect_unchanged_frame_passes(scene, index);
  expect_caught(golden_name(kScene, index),
                clip::render_still(scene, renderer_for(scene), index + 1), "next-frame");
}

}  // namespace
}  // namespace bookspin::picture
