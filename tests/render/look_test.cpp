// Writes 1280×720 "look" images for a human to inspect (front, back, spine, pages, a 3/4
// view with markers, a stretched book). Runs only when BOOKSPIN_RENDER_LOOK_DIR names an
// output folder, e.g. BOOKSPIN_RENDER_LOOK_DIR=/tmp/render_look ./render_tests.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "output/png_writer.hpp"
#include "render/renderer.hpp"
#include "render_test_util.hpp"

namespace bookspin::render {
namespace {

struct View {
  const char* name;
  Eigen::Vector3d eye;
  bool markers;
};

TEST(RenderLook, WritesLookImages) {
  const char* dir = std::getenv("BOOKSPIN_RENDER_LOOK_DIR");
  if (dir == nullptr || *dir == '\0')
    GTEST_SKIP() << "set BOOKSPIN_RENDER_LOOK_DIR to write images";
  std::filesystem::create_directories(dir);
  const double d = default_camera(default_bounding_radius, 1280, 720).eye.norm();
  const View views[] = {
      {"default", default_camera(default_bounding_radius, 1280, 720).eye, false},
      {"front_+z", {0, 0, d}, false},
      {"back_-z", {0, 0, -d}, false},
      {"spine_+x", {d, 0, 0}, false},
      {"pages_-x", {-d, 0, 0}, false},
      {"top_+y", {0, d, 0.001}, false},
      {"three_quarter_markers", Eigen::Vector3d(0.9, 0.6, 3.2).normalized() * d, true},
      {"back_three_quarter", Eigen::Vector3d(-1.4, -0.5, -2.6).normalized() * d, true},
  };
  for (const View& view : views) {
    RenderSettings settings;
    settings.camera.eye = view.eye;
    settings.show_angular_momentum = view.markers;
    settings.show_body_axes = view.markers;
    Renderer renderer(settings);
    FrameInput frame;
    const Eigen::Matrix3d tilt =
        view.markers
            ? Eigen::AngleAxisd(0.5, Eigen::Vector3d(1, 1, 0.3).normalized()).toRotationMatrix()
            : Eigen::Matrix3d::Identity();
    frame.corners = testing::default_book(tilt);
    frame.angular_momentum_direction = tilt * Eigen::Vector3d(1, 0.15, 0.05);
    output::write_png(std::string(dir) + "/" + view.name + ".png", renderer.render(frame), 1);
  }
  // A stretched, sheared book (what an unnormalized rotation matrix produces).
  RenderSettings settings;
  settings.show_body_axes = true;
  Renderer renderer(settings);
  Eigen::Matrix3d stretch;
  stretch << 1.3, 0.4, 0.0, -0.2, 0.8, 0.1, 0.3, 0.0, 1.4;
  FrameInput frame;
  frame.corners = testing::default_book(stretch);
  output::write_png(std::string(dir) + "/stretched.png", renderer.render(frame), 1);
}

}  // namespace
}  // namespace bookspin::render
