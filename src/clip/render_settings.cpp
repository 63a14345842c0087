#include "clip/render_settings.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "charts/panel.hpp"
#include "charts/poinsot_view.hpp"
#include "charts/sphere_view.hpp"
#include "clip/body_drawing.hpp"
#include "overlay/caption.hpp"

namespace bookspin::clip {

namespace {

/// Moves eye and target along the image's right vector so that the book's centre projects
/// to the middle of the columns [left, share) (fractions of the width) of a width×height image.
void shift_book_left(render::Camera& camera, int width, int height, double share,
                     double left = 0.0) {
  const Eigen::Vector3d forward = camera.target - camera.eye;
  const Eigen::Vector3d right = forward.cross(camera.up);
  if ((share >= 1.0 && left <= 0.0) || right.norm() < 1e-9) return;  // degenerate: reported later
  const double aspect = static_cast<double>(width) / height;
  const double half_width = forward.norm() * std::tan(camera.fov_y_deg * M_PI / 360.0) * aspect;
  const Eigen::Vector3d shift = (1.0 - share - left) * half_width * right.normalized();
  camera.eye += shift;
  camera.target += shift;
}

/// Moves eye and target along the image's up vector so that the book's centre projects to the
/// middle of the rows [top, 1) (fractions of the height, from the top).
void shift_book_down(render::Camera& camera, double top) {
  const Eigen::Vector3d forward = camera.target - camera.eye;
  const Eigen::Vector3d up = forward.cross(camera.up).cross(forward);
  if (top <= 0.0 || up.norm() < 1e-9) return;  // degenerate: reported later
  const double half_height = forward.norm() * std::tan(camera.fov_y_deg * M_PI / 360.0);
  const Eigen::Vector3d shift = top * half_height * up.normalized();
  camera.eye += shift;
  camera.target += shift;
}

/// The share of a single scene's frame height its caption takes at the top (overlay/caption's
/// default box, 0.6 font sizes from the top): the title, the model line, the time, and the
/// twist line where it is shown.
double caption_share(const scene::Scene& scene, int height) {
  const double font = overlay::default_caption_font(height);
  const std::size_t lines = 3 + (scene.render.caption_twist ? 1 : 0);
  return std::min(0.5, (0.6 * font + overlay::caption_height(lines, font)) / height);
}

}  // namespace

render::RenderSettings render_settings_for(const scene::Scene& scene, int width, int height,
                                           double book_share, double book_left, double book_top) {
  const auto& r = scene.render;
  render::RenderSettings s;
  s.width = width;
  s.height = height;
  const int book_width =
      std::max(2, static_cast<int>(std::lround((book_share - book_left) * width)));
  const double radius = 0.5 * scene.body.cage.size.norm();
  s.camera = render::default_camera(radius, book_width, height);
  // The bounding sphere within the rows [book_top, 1) too, with default_camera's margin.
  const double half_rows = std::atan((1.0 - book_top) * std::tan(M_PI / 12.0));
  const double rows_distance = radius / std::sin(half_rows) * 1.1;
  const double framed = std::max((s.camera.eye - s.camera.target).norm(), rows_distance);
  s.camera.fov_y_deg = r.fov_y_deg;
  // Keep the automatic distance for the default field of view, scaled for another one.
  double distance = framed * std::tan(M_PI / 12.0) / std::tan(r.fov_y_deg * M_PI / 360.0);
  if (r.camera_distance > 0.0) distance = r.camera_distance;
  // A direction whose squared norm underflows (render.camera_direction = [1e-300, 0, 0]) is
  // scaled by its largest component first (Eigen's stableNormalized); others as they are.
  const Eigen::Vector3d& direction = r.camera_direction;
  const Eigen::Vector3d unit = direction.squaredNorm() >= std::numeric_limits<double>::min()
                                   ? direction.normalized()
                                   : direction.stableNormalized();
  s.camera.eye = s.camera.target + distance * unit;
  shift_book_left(s.camera, width, height, book_share, book_left);
  shift_book_down(s.camera, book_top);
  s.textures = {r.texture_front, r.texture_back, r.texture_spine, r.texture_pages};
  s.show_angular_momentum = r.show_angular_momentum;
  s.show_body_axes = r.show_body_axes;
  s.max_anisotropy = static_cast<float>(r.anisotropy);
  s.msaa_samples = r.msaa;
  return s;
}

render::RenderSettings render_settings_for(const scene::Scene& scene) {
  const int width = scene.render.width, height = scene.render.height;
  const double share = scene.render.panel ? charts::kBookShare : 1.0;
  // With the momentum sphere the body is framed right of its inset, so that neither hides
  // the other.
  double left = 0.0;
  if (scene.render.sphere) {
    const PixelRect inset = charts::sphere_rect(width, height, share * width);
    left = std::min(share - 0.1, (inset.x + inset.width) / width);
  }
  // Without the panel, Poinsot's construction takes the right edge: the body is framed left
  // of it.
  double right = share;
  if (scene.render.poinsot && !scene.render.panel)
    right = std::max(left + 0.1, charts::poinsot_rect(width, height, nullptr).x / width);
  // Below the caption: the body framed in the rows it leaves.
  return render_settings_for(scene, width, height, right, left, caption_share(scene, height));
}

render::FrameInput frame_input_for(const physics::Pose& pose) {
  render::FrameInput input;
  input.corners = pose.corners;
  input.angular_momentum_direction = pose.diagnostics.L;
  return input;
}

BodyDrawing::BodyDrawing(const physics::Body& body)
    : rest_corners_(body.cage.body_corners()), rest_vertices_(body.vertices) {
  if (body.shape == physics::BodyShape::book) return;
  topology_ = std::make_shared<const render::SurfaceTopology>(
      render::SurfaceTopology{body.triangles, body.face_colours, body.smooth});
}

render::FrameInput BodyDrawing::input_for(const physics::Pose& pose) const {
  render::FrameInput input = frame_input_for(pose);
  if (!topology_) return input;
  input.surface.topology = topology_;
  input.surface.positions = pose.surface.cols() > 0
                                ? pose.surface
                                : trilinear_deform(rest_corners_, pose.corners, rest_vertices_);
  return input;
}

}  // namespace bookspin::clip
