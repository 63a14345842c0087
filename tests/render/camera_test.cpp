#include "render/camera.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render/render_error.hpp"

namespace bookspin::render {
namespace {

Eigen::Vector3d to_ndc(const Camera& camera, double aspect, const Eigen::Vector3d& world) {
  const Eigen::Vector4d clip =
      projection_matrix(camera, aspect) * view_matrix(camera) * world.homogeneous();
  return clip.head<3>() / clip.w();
}

TEST(Camera, DefaultDistanceFollowsTheFormula) {
  const Camera camera = default_camera(1.75, 1280, 720);
  const double expected = 1.75 / std::sin(15.0 * std::numbers::pi / 180.0) * 1.1;
  EXPECT_NEAR(camera.eye.norm(), expected, 1e-9);
  EXPECT_TRUE(camera.eye.normalized().isApprox(Eigen::Vector3d(0.9, 0.6, 3.2).normalized()));
  EXPECT_EQ(camera.target, Eigen::Vector3d::Zero());
  EXPECT_EQ(camera.up, Eigen::Vector3d::UnitY());
  EXPECT_DOUBLE_EQ(camera.fov_y_deg, 30.0);
}

TEST(Camera, PortraitImagesMoveTheCameraBack) {
  EXPECT_GT(default_camera(1.75, 720, 1280).eye.norm(), default_camera(1.75, 1280, 720).eye.norm());
}

// Every point of the bounding sphere projects inside the image, in both orientations.
TEST(Camera, DefaultKeepsTheBoundingSphereInView) {
  for (const auto& [w, h] : {std::pair{1280, 720}, std::pair{720, 1280}, std::pair{256, 256}}) {
    const Camera camera = default_camera(1.75, w, h);
    const double aspect = double(w) / h;
    for (int i = 0; i < 2000; ++i) {
      // Fibonacci sphere directions.
      const double z = 1.0 - 2.0 * (i + 0.5) / 2000;
      const double phi = i * std::numbers::pi * (3.0 - std::sqrt(5.0));
      const Eigen::Vector3d p = 1.75 * Eigen::Vector3d(std::sqrt(1 - z * z) * std::cos(phi),
                                                       std::sqrt(1 - z * z) * std::sin(phi), z);
      const Eigen::Vector3d ndc = to_ndc(camera, aspect, p);
      EXPECT_LT(ndc.head<2>().cwiseAbs().maxCoeff(), 1.0) << w << "x" << h;
      EXPECT_LT(std::abs(ndc.z()), 1.0);
    }
  }
}

TEST(Camera, ViewMatrixPutsTheEyeAtTheOriginLookingDownMinusZ) {
  Camera camera;
  camera.eye = {3, 2, 5};
  camera.target = {1, 0, -1};
  const Eigen::Matrix4d view = view_matrix(camera);
  EXPECT_TRUE((view * camera.eye.homogeneous()).head<3>().isZero(1e-12));
  const Eigen::Vector3d target = (view * camera.target.homogeneous()).head<3>();
  EXPECT_NEAR(target.x(), 0, 1e-12);
  EXPECT_NEAR(target.y(), 0, 1e-12);
  EXPECT_NEAR(target.z(), -(camera.target - camera.eye).norm(), 1e-12);
}

TEST(Camera, DegenerateCamerasThrow) {
  Camera camera;
  camera.eye = camera.target;
  EXPECT_THROW(view_matrix(camera), RenderError);
  camera = Camera{};
  camera.up = camera.eye;
  EXPECT_THROW(validate_camera(camera), RenderError);
  camera = Camera{};
  camera.fov_y_deg = 0;
  EXPECT_THROW(validate_camera(camera), RenderError);
  camera = Camera{};
  camera.eye.x() = std::nan("");
  EXPECT_THROW(validate_camera(camera), RenderError);
  EXPECT_THROW(default_camera(0.0, 100, 100), RenderError);
  EXPECT_THROW(default_camera(1.0, 0, 100), RenderError);
}

}  // namespace
}  // namespace bookspin::render
