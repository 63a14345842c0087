#include "charts/decoration.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>

#include "charts/panel.hpp"
#include "charts/poinsot_view.hpp"
#include "charts/sphere_view.hpp"
#include "scene/model_line.hpp"

namespace bookspin::charts {

namespace {

std::string format(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

/// CPU time of this thread between laps (the overlays are drawn on one thread).
class CpuTimer {
 public:
  explicit CpuTimer(bool on) : on_(on), last_(on ? now() : 0.0) {}
  double lap() {
    if (!on_) return 0.0;
    const double t = now(), elapsed = t - last_;
    last_ = t;
    return elapsed;
  }

 private:
  static double now() {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  }
  bool on_;
  double last_;
};

}  // namespace

std::string divergence_text(double t) { return format("diverged at t = %.2f", t); }

std::string twist_line(const analysis::TwistMeasure& twist) {
  auto angle = [](const std::optional<double>& value) -> std::string {
    if (!value || !std::isfinite(*value)) return "none";
    const std::string digits = format("%.3f rad", std::abs(*value));
    // The sign of what is printed: a value that rounds to zero is shown as 0.000.
    return *value < 0.0 && digits != "0.000 rad" ? "\u2212" + digits : digits;
  };
  return "twist per period: measured " + angle(twist.measured) + ", closed form " +
         angle(twist.closed_form);
}

std::vector<overlay::CaptionLine> caption_for(const scene::Scene& scene, double t,
                                              std::optional<double> diverged_at,
                                              const std::optional<std::string>& twist) {
  std::vector<overlay::CaptionLine> lines;
  lines.push_back({scene.title, overlay::CaptionStyle::normal, true});
  lines.push_back({scene::model_line(scene)});
  if (twist) lines.push_back({*twist});
  lines.push_back({format("t = %.1f", t)});
  if (diverged_at) {
    lines.push_back({divergence_text(*diverged_at), overlay::CaptionStyle::warning, true});
  }
  return lines;
}

void decorate_frame(RgbaImage& image, const scene::Scene& scene, double t,
                    std::optional<double> diverged_at, const DiagnosticsHistory& history) {
  FrameDecorator(scene).decorate(image, t, diverged_at, history);
}

FrameDecorator::FrameDecorator(const scene::Scene& scene) : scene_(scene) {
  if (scene.render.caption_twist) twist_line_ = twist_line(analysis::measure_twist(scene));
}
FrameDecorator::~FrameDecorator() = default;

void FrameDecorator::decorate(RgbaImage& image, double t, std::optional<double> diverged_at,
                              const DiagnosticsHistory& history, OverlayTimes* times) {
  const scene::Scene& scene = scene_;
  CpuTimer timer(times != nullptr);
  overlay::CaptionLayout caption;
  double centre_x = 0.5 * image.width;
  if (scene.render.panel) {
    const PixelRect rect = panel_rect(image.width, image.height);
    // With Poinsot's construction on top of the column, the plots below it.
    const PixelRect plots = scene.render.poinsot ? split_for_sphere(rect).second : rect;
    auto specs = panel_plots(single_run(scene, history), clip_end_time(scene), t);
    // A run that blew up keeps the range before it, as the plot sheet does: the growth the
    // figure is about, not 1e13 flattening it (▲ ▼ mark where a curve leaves the range).
    // The clip cannot know the end: it does so once the run has diverged, or once its energy
    // is ten times off (an explosion), not for a slow growth past double (fig10's).
    const auto blown = blow_up_time(history);
    const bool exploded = std::any_of(history.energy_drift.begin(), history.energy_drift.end(),
                                      [](double d) { return !(std::abs(d) < 10.0); });
    if (blown && (diverged_at || exploded))
      clip_to_range_before(specs, [&](const overlay::Series&) { return *blown; });
    draw_panel(image, plots, specs);
    caption.max_width = rect.x - 0.03 * image.height;  // keep clear of the panel
    centre_x = 0.5 * rect.x;
    if (times) times->panel += timer.lap();
  }
  if (scene.render.sphere) {
    if (!sphere_ || !sphere_->fits(image)) {
      const double book_width = scene.render.panel ? panel_rect(image.width, image.height).x
                                                   : static_cast<double>(image.width);
      sphere_ = std::make_unique<overlay::SphereInset>(
          image.width, image.height,
          sphere_rect(image.width, image.height, book_width, twist_line_ ? 4 : 3),
          sphere_spec(sphere_moments(scene), {}));
    }
    sphere_->draw(image, sphere_trails({SphereRun{&history, palette_colour(0)}}));
    if (times) times->sphere += timer.lap();
  }
  if (scene.render.poinsot && !history.orientation.empty()) {
    const PixelRect column = panel_rect(image.width, image.height);
    overlay::draw_poinsot(
        image, poinsot_rect(image.width, image.height, scene.render.panel ? &column : nullptr),
        poinsot_spec(sphere_moments(scene), history));
    if (times) times->sphere += timer.lap();
  }
  caption_.draw(image, caption_for(scene, t, diverged_at, twist_line_), caption);
  if (diverged_at) overlay::draw_banner(image, divergence_text(*diverged_at), centre_x);
  if (times) times->caption += timer.lap();
}

}  // namespace bookspin::charts
