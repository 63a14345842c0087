#include "pipeline/decoration.hpp"

#include <cstdio>

#include "pipeline/panel.hpp"
#include "pipeline/sphere_view.hpp"

namespace bookspin::pipeline {

namespace {

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

}  // namespace

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

std::string divergence_text(double t) { return format("diverged at t = %.2f", t); }

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

void decorate_frame(RgbaImage& image, const scene::Scene& scene, double t,
                    std::optional<double> diverged_at, const DiagnosticsHistory& history) {
  overlay::CaptionLayout caption;
  double centre_x = 0.5 * image.width;
  if (scene.render.panel) {
    const PixelRect rect = panel_rect(image.width, image.height);
    draw_panel(image, rect, panel_plots(single_run(scene, history), clip_end_time(scene), t));
    caption.max_width = rect.x - 0.03 * image.height;  // keep clear of the panel
    centre_x = 0.5 * rect.x;
  }
  if (scene.render.sphere) {
    const double book_width = scene.render.panel ? panel_rect(image.width, image.height).x
                                                 : static_cast<double>(image.width);
    overlay::draw_sphere(
        image, sphere_rect(image.width, image.height, book_width),
        sphere_spec(sphere_moments(scene), {SphereRun{&history, palette_colour(0)}}));
  }
  overlay::draw_caption(image, caption_for(scene, t, diverged_at), caption);
  if (diverged_at) overlay::draw_banner(image, divergence_text(*diverged_at), centre_x);
}

}  // namespace bookspin::pipeline
