#include "render/camera.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "render/render_error.hpp"

namespace bookspin::render {

namespace {

constexpr double deg_to_rad = std::numbers::pi / 180.0;

double half_fov_y_rad(const Camera& camera) { return 0.5 * camera.fov_y_deg * deg_to_rad; }

bool is_finite(const Eigen::Vector3d& v) { return v.allFinite(); }

}  // namespace

void validate_camera(const Camera& camera) {
  if (!(camera.fov_y_deg > 0.0 && camera.fov_y_deg < 180.0))
    throw RenderError("camera: fov_y_deg must be in (0, 180), got " +
                      std::to_string(camera.fov_y_deg));
  if (!is_finite(camera.eye) || !is_finite(camera.target) || !is_finite(camera.up))
    throw RenderError("camera: eye, target and up must be finite");
  const Eigen::Vector3d forward = camera.target - camera.eye;
  if (forward.norm() <= 1e-12) throw RenderError("camera: eye and target coincide");
  if (camera.up.norm() <= 1e-12) throw RenderError("camera: up vector is zero");
  // A small sine of the angle between up and the view direction makes the roll undefined.
  if (forward.normalized().cross(camera.up.normalized()).norm() < 1e-6)
    throw RenderError("camera: up vector is parallel to the view direction");
}

Camera default_camera(double bounding_radius, int width, int height) {
  if (!(std::isfinite(bounding_radius) && bounding_radius > 0.0))
    throw RenderError("default_camera: bounding radius must be finite and > 0, got " +
                      std::to_string(bounding_radius));
  if (width <= 0 || height <= 0)
    throw RenderError("default_camera: image size must be positive, got " + std::to_string(width) +
                      "x" + std::to_string(height));
  Camera camera;
  const double half_y = half_fov_y_rad(camera);
  const double aspect = static_cast<double>(width) / height;
  // In a portrait image the horizontal field of view is the narrower one.
  const double half_x = std::atan(std::tan(half_y) * aspect);
  const double half_min = std::min(half_y, half_x);
  const double distance = bounding_radius / std::sin(half_min) * 1.1;
  camera.eye = Eigen::Vector3d(0.9, 0.6, 3.2).normalized() * distance;
  return camera;
}

double bounding_radius(const Eigen::Matrix3Xd& points) {
  if (points.cols() == 0) throw RenderError("bounding_radius: no points");
  if (!points.allFinite()) throw RenderError("bounding_radius: a point is not finite");
  const double radius = points.colwise().norm().maxCoeff();
  if (!(radius > 0.0) || !std::isfinite(radius))
    throw RenderError("bounding_radius: the points span no sphere about the origin");
  return radius;
}

Eigen::Matrix4d view_matrix(const Camera& camera) {
  validate_camera(camera);
  const Eigen::Vector3d f = (camera.target - camera.eye).normalized();
  const Eigen::Vector3d s = f.cross(camera.up).normalized();
  const Eigen::Vector3d u = s.cross(f);
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.block<1, 3>(0, 0) = s.transpose();
  view.block<1, 3>(1, 0) = u.transpose();
  view.block<1, 3>(2, 0) = -f.transpose();
  view(0, 3) = -s.dot(camera.eye);
  view(1, 3) = -u.dot(camera.eye);
  view(2, 3) = f.dot(camera.eye);
  return view;
}

Eigen::Matrix4d projection_matrix(const Camera& camera, double aspect) {
  validate_camera(camera);
  const double distance = (camera.target - camera.eye).norm();
  // Depth range around the target; a diverged book beyond it is clipped, not a crash.
  const double near = distance / 50.0;
  const double far = distance * 50.0;
  const double f = 1.0 / std::tan(half_fov_y_rad(camera));
  Eigen::Matrix4d proj = Eigen::Matrix4d::Zero();
  proj(0, 0) = f / aspect;
  proj(1, 1) = f;
  proj(2, 2) = (far + near) / (near - far);
  proj(2, 3) = 2.0 * far * near / (near - far);
  proj(3, 2) = -1.0;
  return proj;
}

}  // namespace bookspin::render
