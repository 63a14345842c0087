// The tolerance must let through what legitimately differs between GL implementations
// (image_compare.hpp). Only llvmpipe is at hand, so we emulate the worst of it: the whole
// picture rasterized and sampled a quarter pixel off (conformant implementations share the
// pixel-centre convention and the standard 4× sample pattern, so they differ by less).
#include <gtest/gtest.h>

#include <cmath>

#include "charts/decoration.hpp"
#include "clip/frame.hpp"
#include "clip/render_settings.hpp"
#include "golden_store.hpp"
#include "picture_scenes.hpp"

namespace bookspin::picture {
namespace {

/// `settings` with the camera (eye and target) moved sideways by `pixels` image pixels.
render::RenderSettings shifted(render::RenderSettings settings, double pixels) {
  render::Camera& camera = settings.camera;
  const Eigen::Vector3d forward = camera.target - camera.eye;
  const Eigen::Vector3d right = forward.cross(camera.up).normalized();
  const double pixel =
      2 * forward.norm() * std::tan(camera.fov_y_deg * M_PI / 360) / settings.height;
  camera.eye += pixels * pixel * right;
  camera.target += pixels * pixel * right;
  return settings;
}

class Tolerance : public ::testing::TestWithParam<std::string> {};

TEST_P(Tolerance, QuarterPixelShiftStillMatches) {
  if (update_mode()) GTEST_SKIP() << "goldens are being rewritten";
  const scene::Scene scene = figure_scene(GetParam());
  render::Renderer renderer(shifted(clip::render_settings_for(scene), 0.25));
  for (const int index : pinned_frames(scene.frames)) {
    const std::string name = golden_name(scene.name, index);
    const Comparison c =
        compare_images(clip::render_still(scene, renderer, index), read_golden(name));
    std::cout << name << " a quarter pixel off: " << c.summary({}) << '\n';
    EXPECT_TRUE(c.passed) << name << ": " << c.summary({});
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, Tolerance,
                         ::testing::Values("fig03-particle-stable-z", "fig09-matrix-unstable-x"),
                         [](const auto& info) { return test_name(info.param); });

}  // namespace
}  // namespace bookspin::picture
