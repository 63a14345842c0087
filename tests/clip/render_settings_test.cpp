// The scene → renderer translation: the render.* keys carried over, the camera framed on the
// body's bounding sphere (render/camera.hpp's rule: distance = 1.1 · r / sin(fov/2)) or at
// render.camera_distance, the book moved into the left 60% with the panel; a pose's corners
// and L as the renderer's input, and a body's surface carried by its corners.
#include "clip/render_settings.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "charts/decoration.hpp"
#include "overlay/caption.hpp"
#include "render/marker_mesh.hpp"

namespace bookspin::clip {
namespace {

scene::Scene scene_with(const std::vector<std::string>& overrides) {
  return scene::parse_scene_text("[scene]\ntitle = \"A test\"\n", "render_settings_test.toml",
                                 overrides);
}

/// Where the world point `p` lands in normalized device x (−1 left edge … 1 right edge) of a
/// width×height image seen by `camera` (a symmetric perspective about eye → target).
double ndc_x(const render::Camera& camera, const Eigen::Vector3d& p, int width, int height) {
  const Eigen::Vector3d forward = (camera.target - camera.eye).normalized();
  const Eigen::Vector3d right = forward.cross(camera.up).normalized();
  const Eigen::Vector3d v = p - camera.eye;
  const double aspect = static_cast<double>(width) / height;
  return v.dot(right) / (v.dot(forward) * std::tan(camera.fov_y_deg * M_PI / 360.0) * aspect);
}

// The default book, 1.878 × 2.9085 × 0.5 (scenes/README.md): its bounding sphere.
const double kBookRadius = 0.5 * std::sqrt(1.878 * 1.878 + 2.9085 * 2.9085 + 0.5 * 0.5);

TEST(RenderSettings, TheScenesRenderKeysAreTheRenderersSettings) {
  const render::RenderSettings s = render_settings_for(
      scene_with({"render.width=640", "render.height=480", "render.fov_y=40.0",
                  "render.show_angular_momentum=true", "render.anisotropy=8", "render.msaa=2"}));
  EXPECT_EQ(s.width, 640);
  EXPECT_EQ(s.height, 480);
  EXPECT_DOUBLE_EQ(s.camera.fov_y_deg, 40.0);
  EXPECT_TRUE(s.show_angular_momentum);
  EXPECT_FALSE(s.show_body_axes);
  EXPECT_FLOAT_EQ(s.max_anisotropy, 8.0f);
  EXPECT_EQ(s.msaa_samples, 2);
  EXPECT_TRUE(s.textures.front.empty());  // no texture: the generated covers
  const render::RenderSettings axes =
      render_settings_for(scene_with({"render.show_body_axes=true"}));
  EXPECT_FALSE(axes.show_angular_momentum);
  EXPECT_TRUE(axes.show_body_axes);
  EXPECT_EQ(axes.msaa_samples, 4);
  EXPECT_FLOAT_EQ(axes.max_anisotropy, 0.0f);  // automatic
}

TEST(RenderSettings, TheCameraFramesTheBooksBoundingSphereFromTheSceneDirection) {
  // Columns and rows [0, 1) of a 1280×720 image (no caption to leave room for): the vertical
  // field of view (30°) is the narrower one.
  const render::RenderSettings s = render_settings_for(scene_with({}), 1280, 720, 1.0);
  EXPECT_NEAR(s.camera.target.norm(), 0.0, 1e-12);
  const Eigen::Vector3d eye = s.camera.eye;
  EXPECT_NEAR(eye.norm(), 1.1 * kBookRadius / std::sin(15.0 * M_PI / 180.0), 1e-9);
  EXPECT_NEAR(eye.normalized().dot(Eigen::Vector3d(0.9, 0.6, 3.2).normalized()), 1.0, 1e-12);
  // Another field of view: the same picture height of the book, tan(15°) / tan(30°) closer.
  const render::RenderSettings wide =
      render_settings_for(scene_with({"render.fov_y=60.0"}), 1280, 720, 1.0);
  EXPECT_NEAR(wide.camera.eye.norm(),
              eye.norm() * std::tan(15.0 * M_PI / 180.0) / std::tan(30.0 * M_PI / 180.0), 1e-9);
  // Rows [0.2, 1): the sphere fits 80% of the height, tan(15°) · 0.8 its half angle.
  const render::RenderSettings low = render_settings_for(scene_with({}), 1280, 720, 1.0, 0.0, 0.2);
  EXPECT_NEAR((low.camera.eye - low.camera.target).norm(),
              1.1 * kBookRadius / std::sin(std::atan(0.8 * std::tan(15.0 * M_PI / 180.0))), 1e-9);
}

TEST(RenderSettings, AGivenCameraDistanceAndDirectionPlaceTheEye) {
  const render::RenderSettings s = render_settings_for(
      scene_with({"render.camera_distance=10.0", "render.camera_direction=[0.0, 0.0, 2.0]"}));
  // The eye 10 along the direction from the target, which is moved up along the image's
  // vertical only (the body framed below the caption).
  EXPECT_NEAR((s.camera.eye - s.camera.target - Eigen::Vector3d(0, 0, 10)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(s.camera.target.z(), 0.0, 1e-12);
  // Any nonzero direction, also one whose squared norm underflows (1e-600 → 0) or is subnormal.
  for (const char* tiny : {"[0.0, 0.0, 1e-300]", "[0.0, 0.0, 1e-160]"}) {
    const render::RenderSettings t = render_settings_for(scene_with(
        {"render.camera_distance=10.0", std::string("render.camera_direction=") + tiny}));
    EXPECT_NEAR((t.camera.eye - t.camera.target - Eigen::Vector3d(0, 0, 10)).norm(), 0.0, 1e-12)
        << tiny;
  }
}

// With the panel the book's centre is seen in the middle of the left 60% of the frame: at
// 30% of the width, NDC x = −0.4; the eye moves sideways, so its distance stays.
TEST(RenderSettings, WithThePanelTheBookIsFramedInTheLeftSixtyPercent) {
  const render::RenderSettings s = render_settings_for(scene_with({"render.panel=true"}));
  EXPECT_NEAR(ndc_x(s.camera, Eigen::Vector3d::Zero(), 1280, 720), -0.4, 1e-9);
  const render::RenderSettings alone = render_settings_for(scene_with({}));
  EXPECT_NEAR((s.camera.eye - s.camera.target).norm(),
              (alone.camera.eye - alone.camera.target).norm(), 1e-9);
  EXPECT_NEAR(ndc_x(alone.camera, Eigen::Vector3d::Zero(), 1280, 720), 0.0, 1e-12);
  // Columns [0.25, 0.75) of a 400×400 image: the centre at 50%, NDC 0.
  const render::RenderSettings middle = render_settings_for(scene_with({}), 400, 400, 0.75, 0.25);
  EXPECT_NEAR(ndc_x(middle.camera, Eigen::Vector3d::Zero(), 400, 400), 0.0, 1e-12);
  // Columns [0, 0.5): the centre at 25%, NDC −0.5.
  const render::RenderSettings half = render_settings_for(scene_with({}), 400, 400, 0.5);
  EXPECT_NEAR(ndc_x(half.camera, Eigen::Vector3d::Zero(), 400, 400), -0.5, 1e-9);
}

/// The image row (0 at the top) where the world point `p` is seen by `camera` in a
/// width×height image.
double image_row(const render::Camera& camera, const Eigen::Vector3d& p, int height) {
  const Eigen::Vector3d forward = (camera.target - camera.eye).normalized();
  const Eigen::Vector3d right = forward.cross(camera.up).normalized();
  const Eigen::Vector3d up = right.cross(forward);
  const Eigen::Vector3d v = p - camera.eye;
  const double ndc = v.dot(up) / (v.dot(forward) * std::tan(camera.fov_y_deg * M_PI / 360.0));
  return (1.0 - ndc) / 2.0 * height;
}

/// The image column (0 at the left) where `p` is seen, likewise.
double image_column(const render::Camera& camera, const Eigen::Vector3d& p, int width, int height) {
  const Eigen::Vector3d forward = (camera.target - camera.eye).normalized();
  const Eigen::Vector3d right = forward.cross(camera.up).normalized();
  const Eigen::Vector3d v = p - camera.eye;
  const double aspect = static_cast<double>(width) / height;
  const double ndc =
      v.dot(right) / (v.dot(forward) * std::tan(camera.fov_y_deg * M_PI / 360.0) * aspect);
  return (1.0 + ndc) / 2.0 * width;
}

// No caption covers the body: in every single scene of the gallery, whatever its orientation,
// the body's bounding sphere, and its markers' where it shows them (the L arrow, the body
// axes), is seen below the lowest row the caption paints (the caption drawn here, with a
// twist line where the scene shows one), above the frame's bottom and within its sides.
TEST(RenderSettings, TheBodyIsFramedBelowItsCaption) {
  const std::filesystem::path scenes = std::filesystem::path(BOOKSPIN_SOURCE_DIR) / "scenes";
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(scenes)) {
    if (entry.path().extension() != ".toml") continue;
    const scene::Scene scene = scene::parse_scene(entry.path());
    if (!scene.compare.empty()) continue;  // a comparison's tiles carry their own captions
    const int w = scene.render.width, h = scene.render.height;
    RgbaImage caption(w, h);  // white: the caption's box darkens what it covers
    std::fill(caption.pixels.begin(), caption.pixels.end(), 255);
    const std::optional<std::string> twist =
        scene.render.caption_twist
            ? std::optional<std::string>("twist per period: measured 1.234 rad, closed form 1.234")
            : std::nullopt;
    overlay::draw_caption(caption, charts::caption_for(scene, 123.4, std::nullopt, twist));
    int bottom = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (caption.row(y)[4 * x] != 255) bottom = y + 1;
    ASSERT_GT(bottom, 0) << entry.path();
    const render::RenderSettings s = render_settings_for(scene);
    const Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double radius = 0.5 * scene.body.cage.size.norm();
    if (scene.render.show_angular_momentum || scene.render.show_body_axes) {
      // The markers as drawn (their mesh, for L along each axis and diagonal): what they
      // reach, not what the framing assumes they do.
      const Eigen::Matrix<double, 3, 8> corners = scene.body.cage.body_corners();
      for (const Eigen::Vector3d& l :
           {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1),
            Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(-1, 2, 0.5)}) {
        for (const render::MarkerVertex& v : render::build_markers(
                 corners, l, scene.render.show_angular_momentum, scene.render.show_body_axes))
          radius =
              std::max(radius, Eigen::Vector3d(v.position[0], v.position[1], v.position[2]).norm());
      }
    }
    double top = h, lowest = 0, left = w, rightmost = 0;
    for (int i = 0; i < 400; ++i) {  // points over the sphere, by a Fibonacci spiral
      const double z = 1.0 - (i + 0.5) / 200.0, r = std::sqrt(std::max(0.0, 1.0 - z * z));
      const double phi = i * M_PI * (3.0 - std::sqrt(5.0));
      const Eigen::Vector3d p =
          centre + radius * Eigen::Vector3d(r * std::cos(phi), r * std::sin(phi), z);
      top = std::min(top, image_row(s.camera, p, h));
      lowest = std::max(lowest, image_row(s.camera, p, h));
      left = std::min(left, image_column(s.camera, p, w, h));
      rightmost = std::max(rightmost, image_column(s.camera, p, w, h));
    }
    EXPECT_GE(top, bottom) << entry.path().filename() << ": the body reaches row " << top
                           << ", the caption row " << bottom;
    EXPECT_LE(lowest, h) << entry.path().filename();
    EXPECT_GE(left, 0) << entry.path().filename();
    EXPECT_LE(rightmost, w) << entry.path().filename();
    ++checked;
  }
  EXPECT_GE(checked, 10);
}

TEST(RenderSettings, APoseIsItsCornersAndL) {
  physics::Pose pose;
  for (int p = 0; p < 8; ++p) pose.corners.col(p) = Eigen::Vector3d(p, 2.0 * p, -p);
  pose.diagnostics.L = Eigen::Vector3d(0.5, -1.0, 2.0);
  const render::FrameInput input = frame_input_for(pose);
  EXPECT_EQ(input.corners, pose.corners);
  EXPECT_EQ(input.angular_momentum_direction, Eigen::Vector3d(0.5, -1.0, 2.0));
  EXPECT_EQ(input.surface.topology, nullptr);
}

TEST(RenderSettings, ABodysSurfaceIsCarriedByItsCornersAndTheBookHasNone) {
  const scene::Scene book = scene_with({});
  const scene::Scene handle = scene_with({"body.shape=\"t-handle\""});
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.8, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d b(0.5, -2.0, 1.0);
  physics::Pose pose;
  pose.corners = (R * handle.body.cage.body_corners()).colwise() + b;
  EXPECT_EQ(BodyDrawing(book.body).input_for(pose).surface.topology, nullptr);

  const render::FrameInput input = BodyDrawing(handle.body).input_for(pose);
  ASSERT_NE(input.surface.topology, nullptr);
  EXPECT_EQ(input.surface.topology->triangles, handle.body.triangles);
  EXPECT_EQ(input.surface.topology->face_colours, handle.body.face_colours);
  const Eigen::Matrix3Xd expected = (R * handle.body.vertices).colwise() + b;
  ASSERT_EQ(input.surface.positions.cols(), expected.cols());
  EXPECT_LT((input.surface.positions - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(input.corners, pose.corners);

  // A deforming body's own surface (the lattice) is drawn as the pose gives it.
  pose.surface = expected.array() + 1.0;
  EXPECT_EQ(BodyDrawing(handle.body).input_for(pose).surface.positions, pose.surface);
}

}  // namespace
}  // namespace bookspin::clip
