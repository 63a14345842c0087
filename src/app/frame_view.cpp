#include "app/frame_view.hpp"

#include <cmath>
#include <cstdio>

namespace bookspin::app {

namespace {

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

std::string model_line(const scene::Scene& scene) {
  const auto& m = scene.model;
  std::string line = std::string(physics::to_string(m.kind));
  if (m.kind != physics::ModelKind::exact) {
    line += ", " + std::string(physics::to_string(m.integrator));
    line += format(", dt = %.4g", scene.dt);
    line += m.normalize ? ", normalized" : ", not normalized";
  }
  if (m.kind == physics::ModelKind::particle) {
    line += m.damping ? ", damped" : ", undamped";
    line += format(", k = %g", m.spring_constant);
  }
  return line;
}

}  // namespace

std::string divergence_text(double t) { return format("diverged at t = %.2f", t); }

render::RenderSettings render_settings_for(const scene::Scene& scene) {
  const auto& r = scene.render;
  render::RenderSettings s;
  s.width = r.width;
  s.height = r.height;
  s.camera = render::default_camera(0.5 * scene.book.size.norm(), r.width, r.height);
  s.camera.fov_y_deg = r.fov_y_deg;
  // Keep the automatic distance for the default field of view, scaled for another one.
  double distance = (s.camera.eye - s.camera.target).norm() *
                    std::tan(M_PI / 12.0) / std::tan(r.fov_y_deg * M_PI / 360.0);
  if (r.camera_distance > 0.0) distance = r.camera_distance;
  s.camera.eye = s.camera.target + distance * r.camera_direction.normalized();
  s.textures = {r.texture_front, r.texture_back, r.texture_spine, r.texture_pages};
  s.show_angular_momentum = r.show_angular_momentum;
  s.show_body_axes = r.show_body_axes;
  return s;
}

render::FrameInput frame_input_for(const physics::BookPose& pose) {
  render::FrameInput input;
  input.corners = pose.corners;
  input.angular_momentum_direction = pose.diagnostics.L;
  return input;
}

std::vector<overlay::CaptionLine> caption_for(const scene::Scene& scene, double t,
                                              std::optional<double> diverged_at) {
  std::vector<overlay::CaptionLine> lines;
  lines.push_back({scene.title, overlay::CaptionStyle::normal, true});
  lines.push_back({model_line(scene)});
  lines.push_back({format("t = %.1f", t)});
  if (diverged_at) {
    lines.push_back({divergence_text(*diverged_at), overlay::CaptionStyle::warning, true});
  }
  return lines;
}

}  // namespace bookspin::app
