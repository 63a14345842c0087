#include "charts/panel.hpp"

#include <algorithm>
#include <iterator>

#include "common/colour.hpp"
#include "overlay/cairo_canvas.hpp"

namespace bookspin::charts {

namespace {

// ω components in the colours of the rendered body axes (x red, y green, z blue).
constexpr Rgb kRed{0.85, 0.15, 0.10}, kGreen{0.10, 0.60, 0.20}, kBlue{0.15, 0.35, 0.90};
constexpr Rgb kPurple{0.50, 0.20, 0.60}, kOrange{0.90, 0.55, 0.00}, kTeal{0.00, 0.55, 0.60},
    kPink{0.80, 0.30, 0.55};

// Smallest y spans: a quantity that is constant up to round-off draws flat.
constexpr double kOmegaSpan = 0.02, kDriftSpan = 1e-3, kShapeSpan = 1e-3;

overlay::Series series(std::string label, const std::vector<double>& t,
                       const std::vector<double>& y, Rgb c, bool dashed = false) {
  overlay::Series s;
  s.label = std::move(label);
  s.x = t;
  s.y = y;
  s.r = c.r, s.g = c.g, s.b = c.b;
  s.dashed = dashed;
  return s;
}

overlay::PlotSpec axes(std::string title, std::string y_label, double min_span, double t_end,
                       std::optional<double> cursor) {
  overlay::PlotSpec spec;
  spec.title = std::move(title);
  spec.x_label = "t (time units)";
  spec.y_label = std::move(y_label);
  spec.legend_placement = overlay::LegendPlacement::top;
  if (t_end > 0) spec.x_range = std::pair{0.0, t_end};
  spec.min_y_span = min_span;
  spec.cursor_x = cursor;
  return spec;
}

std::vector<overlay::PlotSpec> single_plots(const PanelRun& run, double t_end,
                                            std::optional<double> cursor) {
  const DiagnosticsHistory& h = *run.history;
  auto omega =
      axes("angular velocity ω, body frame", "ω (rad / time unit)", kOmegaSpan, t_end, cursor);
  omega.series = {series("ω_x", h.t, h.omega_x, kRed), series("ω_y", h.t, h.omega_y, kGreen),
                  series("ω_z", h.t, h.omega_z, kBlue)};
  auto drift = axes("relative energy drift", "E/E₀ − 1", kDriftSpan, t_end, cursor);
  drift.series = {series("E/E₀ − 1", h.t, h.energy_drift, kPurple)};
  drift.legend = false;
  auto shape = axes("shape error", "dimensionless", kShapeSpan, t_end, cursor);
  shape.series = {series("max strain |ℓ/ℓ₀ − 1|", h.t, h.strain_max, kOrange)};
  if (run.kind == physics::ModelKind::rigid_matrix) {
    shape.series.push_back(series("‖RᵀR − I‖", h.t, h.orthogonality_error, kTeal, true));
  } else if (run.kind == physics::ModelKind::rigid_quaternion) {
    shape.series.push_back(series("|q| − 1", h.t, h.quaternion_deviation, kPink, true));
  }
  return {omega, drift, shape};
}

/// One curve per run; odd runs dashed, so curves that coincide (runs in lockstep) still
/// show both colours.
std::vector<overlay::PlotSpec> comparison_plots(const std::vector<PanelRun>& runs, double t_end,
                                                std::optional<double> cursor) {
  static const char* const kAxis[3] = {"x", "y", "z"};
  const int axis = runs.front().flip_axis;
  const std::string name = std::string("ω_") + kAxis[axis];
  auto omega = axes(name + ", body frame (the flips)", name + " (rad / time unit)", kOmegaSpan,
                    t_end, cursor);
  auto drift = axes("relative energy drift", "E/E₀ − 1", kDriftSpan, t_end, cursor);
  auto shape =
      axes("shape error: max strain |ℓ/ℓ₀ − 1|", "dimensionless", kShapeSpan, t_end, cursor);
  drift.legend = shape.legend = false;  // the same colours as the ω_x legend
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const DiagnosticsHistory& h = *runs[i].history;
    const Rgb c = palette_colour(i);  // runs of a comparison
    const bool dashed = i % 2 == 1;
    const std::vector<double>& w = axis == 0 ? h.omega_x : axis == 1 ? h.omega_y : h.omega_z;
    omega.series.push_back(series(runs[i].label, h.t, w, c, dashed));
    drift.series.push_back(series(runs[i].label, h.t, h.energy_drift, c, dashed));
    shape.series.push_back(series(runs[i].label, h.t, h.strain_max, c, dashed));
  }
  return {omega, drift, shape};
}

}  // namespace

std::vector<overlay::PlotSpec> panel_plots(const std::vector<PanelRun>& runs, double t_end,
                                           std::optional<double> cursor) {
  if (runs.empty()) return {};
  if (runs.size() == 1) return single_plots(runs.front(), t_end, cursor);
  return comparison_plots(runs, t_end, cursor);
}

PixelRect panel_rect(int width, int height) {
  const double margin = 0.012 * std::min(width, height);
  const double left = kBookShare * width;
  return {left, margin, width - left - margin, height - 2 * margin};
}

void draw_panel(RgbaImage& image, const PixelRect& rect,
                const std::vector<overlay::PlotSpec>& plots) {
  // Below about 100 px a plot has no room for its ticks and labels: better none than a smudge.
  if (plots.empty() || rect.width < 100 || rect.height < 100) return;
  // Only the panel's pixels: its cost per frame is its own area, not the frame's.
  overlay::CairoCanvas canvas(image.width, image.height,
                              overlay::region_around(rect.x, rect.y, rect.width, rect.height, 2.0,
                                                     image.width, image.height));
  cairo_t* cr = canvas.cr();
  cairo_rectangle(cr, rect.x, rect.y, rect.width, rect.height);
  cairo_set_source_rgba(cr, 0.98, 0.98, 0.97, 0.9);
  cairo_fill(cr);
  const double inset = 0.01 * rect.height;
  const double each = (rect.height - 2 * inset) / plots.size();
  std::vector<overlay::PlotSpec> aligned = plots;
  overlay::align_left_margins(cr, each, aligned);
  for (std::size_t i = 0; i < aligned.size(); ++i) {
    overlay::draw_plot(cr, rect.x + inset, rect.y + inset + i * each, rect.width - 2 * inset, each,
                       aligned[i]);
  }
  canvas.composite_onto(image);
}

std::vector<PanelRun> single_run(const scene::Scene& scene, const DiagnosticsHistory& history) {
  return {PanelRun(scene, history)};
}

double clip_end_time(const scene::Scene& scene) {
  return static_cast<double>(scene.frames - 1) * scene.steps_per_frame * scene.dt;
}

double draw_sheet_header(cairo_t* cr, const std::vector<std::string>& header, double font) {
  double y = 0.4 * font;
  for (std::size_t i = 0; i < header.size(); ++i) {
    overlay::select_overlay_font(cr, i == 0, i == 0 ? font : 0.8 * font);
    y += 1.35 * (i == 0 ? font : 0.8 * font);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_move_to(cr, font, y);
    cairo_show_text(cr, header[i].c_str());
  }
  return y;
}

RgbaImage plot_sheet(const std::vector<std::string>& header,
                     const std::vector<overlay::PlotSpec>& plots, int width, int height) {
  RgbaImage image(width, height);
  std::fill(image.pixels.begin(), image.pixels.end(), 255);
  overlay::CairoCanvas canvas(width, height);
  cairo_t* cr = canvas.cr();
  const double font = std::max(10.0, 0.024 * height);
  double y = draw_sheet_header(cr, header, font);
  y += 0.6 * font;
  const double each = plots.empty() ? 0 : (height - y) / plots.size();
  std::vector<overlay::PlotSpec> aligned = plots;
  overlay::align_left_margins(cr, each, aligned);
  for (std::size_t i = 0; i < aligned.size(); ++i)
    overlay::draw_plot(cr, 0, y + i * each, width, each, aligned[i]);
  canvas.composite_onto(image);
  return image;
}

}  // namespace bookspin::charts
