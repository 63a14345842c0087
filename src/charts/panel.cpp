#include "charts/panel.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

#include "common/colour.hpp"
#include "overlay/cairo_canvas.hpp"
#include "overlay/caption.hpp"

namespace bookspin::charts {

namespace {

// ω components in the colours of the rendered body axes (common/colour.hpp).
constexpr Rgb kRed = kComponentColours[0], kGreen = kComponentColours[1],
              kBlue = kComponentColours[2];
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

/// "t (s)" or "t (time units)"; "rad/s" or "rad / time unit".
std::string time_label(const std::string& unit) {
  return unit.empty() ? "t (time units)" : "t (" + unit + ")";
}
std::string rate_unit(const std::string& unit) {
  return unit.empty() ? "rad / time unit" : "rad/" + unit;
}

overlay::PlotSpec axes(std::string title, std::string y_label, double min_span, double t_end,
                       std::optional<double> cursor, const std::string& unit) {
  overlay::PlotSpec spec;
  spec.title = std::move(title);
  spec.x_label = time_label(unit);
  spec.y_label = std::move(y_label);
  spec.legend_placement = overlay::LegendPlacement::top;
  if (t_end > 0) spec.x_range = std::pair{0.0, t_end};
  spec.min_y_span = min_span;
  spec.cursor_x = cursor;
  return spec;
}

/// The measured samples up to `t_until` (the run's last frame): component `c` as dots.
overlay::Series measured_dots(const scene::MeasuredOmega& m, int c, double t_until, Rgb colour,
                              std::string label) {
  overlay::Series s;
  s.label = std::move(label);
  for (std::size_t i = 0; i < m.t.size() && m.t[i] <= t_until; ++i) {
    s.x.push_back(m.t[i]);
    s.y.push_back(m.omega(c, static_cast<Eigen::Index>(i)));
  }
  s.r = colour.r, s.g = colour.g, s.b = colour.b;
  s.dots = true;
  return s;
}

/// |ω_run(t_i) − ω_measured(t_i)| at each measured sample within the run so far, the run's ω
/// taken linear between its frames.
overlay::Series measured_residual(const DiagnosticsHistory& h, const scene::MeasuredOmega& m,
                                  std::string label, Rgb colour) {
  overlay::Series s;
  s.label = std::move(label);
  std::size_t j = 0;
  for (std::size_t i = 0; i < m.t.size(); ++i) {
    const double t = m.t[i];
    if (h.t.empty() || t < h.t.front() || t > h.t.back()) continue;
    while (j + 1 < h.t.size() && h.t[j + 1] < t) ++j;
    const std::size_t k = std::min(j + 1, h.t.size() - 1);
    const double span = h.t[k] - h.t[j], f = span > 0 ? (t - h.t[j]) / span : 0.0;
    const Eigen::Vector3d run((1 - f) * h.omega_x[j] + f * h.omega_x[k],
                              (1 - f) * h.omega_y[j] + f * h.omega_y[k],
                              (1 - f) * h.omega_z[j] + f * h.omega_z[k]);
    s.x.push_back(t);
    s.y.push_back((run - m.omega.col(static_cast<Eigen::Index>(i))).norm());
  }
  s.r = colour.r, s.g = colour.g, s.b = colour.b;
  return s;
}

std::vector<overlay::PlotSpec> single_plots(const PanelRun& run, double t_end,
                                            std::optional<double> cursor) {
  const DiagnosticsHistory& h = *run.history;
  const std::string& unit = run.time_unit;
  auto omega = axes("angular velocity ω, body frame", "ω (" + rate_unit(unit) + ")", kOmegaSpan,
                    t_end, cursor, unit);
  omega.series = {series("ω_x", h.t, h.omega_x, kRed), series("ω_y", h.t, h.omega_y, kGreen),
                  series("ω_z", h.t, h.omega_z, kBlue)};
  auto drift = axes("relative energy drift", "E/E₀ − 1", kDriftSpan, t_end, cursor, unit);
  drift.series = {series("E/E₀ − 1", h.t, h.energy_drift, kPurple)};
  drift.legend = false;
  if (run.measured) {
    // A measured ω beside the run (a fitted toss): its samples as dots on the ω plot, and the
    // residual in place of the shape error (no rigid run has one).
    const double until = h.t.empty() ? 0.0 : h.t.back();
    const Rgb colours[3] = {kRed, kGreen, kBlue};
    const char* names[3] = {"ω_x measured", "ω_y measured", "ω_z measured"};
    for (int c = 0; c < 3; ++c)
      omega.series.push_back(measured_dots(*run.measured, c, until, colours[c], names[c]));
    auto residual =
        axes("residual |ω − ω_measured|", rate_unit(unit), kOmegaSpan, t_end, cursor, unit);
    residual.series = {measured_residual(h, *run.measured, "|ω − ω_measured|", kOrange)};
    residual.legend = false;
    return {omega, drift, residual};
  }
  auto shape = axes("shape error", "dimensionless", kShapeSpan, t_end, cursor, unit);
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
  const std::string& unit = runs.front().time_unit;
  const std::string name = std::string("ω_") + kAxis[axis];
  auto omega = axes(name + ", body frame (the flips)", name + " (" + rate_unit(unit) + ")",
                    kOmegaSpan, t_end, cursor, unit);
  auto drift = axes("relative energy drift", "E/E₀ − 1", kDriftSpan, t_end, cursor, unit);
  // The third plot: the shape error where a run deforms (the particle and lattice models);
  // where none does (rigid models, engines, a measured ω beside a fit), each run's distance from
  // the first run's ω, the residual of a fit against its measurement.
  bool deforms = false;
  for (const PanelRun& run : runs) deforms |= run.kind == physics::ModelKind::particle;
  auto shape = deforms ? axes("shape error: max strain |ℓ/ℓ₀ − 1|", "dimensionless", kShapeSpan,
                              t_end, cursor, unit)
                       : axes("|ω − ω of " + runs.front().label + "|", rate_unit(unit), kOmegaSpan,
                              t_end, cursor, unit);
  drift.legend = shape.legend = false;  // the same colours as the ω_x legend
  const DiagnosticsHistory& first = *runs.front().history;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const DiagnosticsHistory& h = *runs[i].history;
    const auto [c, dashed] = run_style(i);
    const std::vector<double>& w = axis == 0 ? h.omega_x : axis == 1 ? h.omega_y : h.omega_z;
    omega.series.push_back(series(runs[i].label, h.t, w, c, dashed));
    drift.series.push_back(series(runs[i].label, h.t, h.energy_drift, c, dashed));
    if (deforms) {
      shape.series.push_back(series(runs[i].label, h.t, h.strain_max, c, dashed));
    } else if (i > 0) {  // runs in lockstep: the same frames
      std::vector<double> t, d;
      for (std::size_t f = 0; f < std::min(h.t.size(), first.t.size()); ++f) {
        t.push_back(h.t[f]);
        d.push_back(Eigen::Vector3d(h.omega_x[f] - first.omega_x[f],
                                    h.omega_y[f] - first.omega_y[f],
                                    h.omega_z[f] - first.omega_z[f])
                        .norm());
      }
      shape.series.push_back(series(runs[i].label, t, d, c, dashed));
    }
  }
  return {omega, drift, shape};
}

}  // namespace

RunStyle run_style(std::size_t index) { return {palette_colour(index), index % 2 == 1}; }

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

PanelLayout panel_layout(const PixelRect& rect, const std::vector<overlay::PlotSpec>& plots) {
  overlay::CairoCanvas measure(1, 1);
  cairo_t* cr = measure.cr();
  const double inset = 0.01 * rect.height;
  const double width = rect.width - 2 * inset, height = rect.height - 2 * inset;
  // Below about 100 px a plot has no room for its ticks and labels.
  if (!(width >= 100) || !(height >= 100)) return {};
  // The smallest text: kMinFont in a panel as wide as a 960 × 540 frame's (360 px inside) and
  // wider; a narrower panel (a smaller clip) scales it down with its width, to 9 px at most
  // 270 px wide, so that its plots' titles and legends still fit it.
  const double least = std::clamp(overlay::kMinFont * width / 360.0, 9.0, overlay::kMinFont);
  for (std::size_t n = plots.size(); n > 0; --n) {
    PanelLayout out;
    out.font = std::clamp(height / static_cast<double>(n) / 22.0, least, 18.0);
    out.plots.assign(plots.begin(), plots.begin() + static_cast<std::ptrdiff_t>(n));
    for (std::size_t i = 0; i < n; ++i) {
      out.plots[i].font = out.font;
      out.plots[i].x_axis_text = i + 1 == n;  // one time axis, under the lowest plot
    }
    overlay::align_left_margins(cr, height / static_cast<double>(n), out.plots);
    std::vector<double> frames;
    double frame_total = 0;
    for (const auto& p : out.plots) {
      frames.push_back(overlay::plot_frame_height(cr, width, p, out.font));
      frame_total += frames.back();
    }
    const double area = (height - frame_total) / static_cast<double>(n);
    if (area < kPanelMinPlotFonts * out.font) continue;
    double y = rect.y + inset;
    for (std::size_t i = 0; i < n; ++i) {
      out.rects.push_back({rect.x + inset, y, width, frames[i] + area});
      y += frames[i] + area;
    }
    // The left margin again at each plot's own height, which decides whether its y label
    // takes two lines (overlay::plot_left_margin): the widest, for every plot.
    double left = 0;
    for (std::size_t i = 0; i < n; ++i) {
      overlay::PlotSpec alone = out.plots[i];
      alone.left_margin = 0;
      left = std::max(left, overlay::plot_left_margin(cr, out.rects[i].height, alone));
    }
    for (auto& p : out.plots) p.left_margin = left;
    return out;
  }
  return {};
}

void draw_panel(RgbaImage& image, const PixelRect& rect,
                const std::vector<overlay::PlotSpec>& plots) {
  const PanelLayout layout = panel_layout(rect, plots);
  // Where not even one plot fits: better none than a smudge.
  if (layout.plots.empty()) return;
  // Only the panel's pixels: its cost per frame is its own area, not the frame's.
  overlay::CairoCanvas canvas(image.width, image.height,
                              overlay::region_around(rect.x, rect.y, rect.width, rect.height, 2.0,
                                                     image.width, image.height));
  cairo_t* cr = canvas.cr();
  cairo_rectangle(cr, rect.x, rect.y, rect.width, rect.height);
  cairo_set_source_rgba(cr, 0.98, 0.98, 0.97, 0.9);
  cairo_fill(cr);
  for (std::size_t i = 0; i < layout.plots.size(); ++i) {
    const PixelRect& r = layout.rects[i];
    overlay::draw_plot(cr, r.x, r.y, r.width, r.height, layout.plots[i]);
  }
  canvas.composite_onto(image);
}

std::vector<PanelRun> single_run(const scene::Scene& scene, const DiagnosticsHistory& history) {
  return {PanelRun(scene, history)};
}

double clip_end_time(const scene::Scene& scene) {
  return static_cast<double>(scene.frames - 1) * scene.steps_per_frame * scene.dt;
}

bool clip_to_range_before(std::vector<overlay::PlotSpec>& plots,
                          const std::function<double(const overlay::Series&)>& t_blow) {
  bool clipped = false;
  for (auto& plot : plots) {
    if (plot.log_y) continue;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo, all_lo = lo, all_hi = -lo;
    for (const auto& s : plot.series) {
      const double until = t_blow(s);
      for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
        if (!std::isfinite(s.y[i])) continue;
        all_lo = std::min(all_lo, s.y[i]), all_hi = std::max(all_hi, s.y[i]);
        if (s.x[i] <= until) lo = std::min(lo, s.y[i]), hi = std::max(hi, s.y[i]);
      }
    }
    if (!std::isfinite(lo)) continue;
    if (hi - lo < plot.min_y_span) {
      const double mid = 0.5 * (lo + hi);
      lo = mid - 0.5 * plot.min_y_span, hi = mid + 0.5 * plot.min_y_span;
    }
    const double pad = 0.1 * std::max(hi - lo, 1e-12);
    if (all_lo >= lo - pad && all_hi <= hi + pad) continue;  // nothing leaves: fit the data
    plot.y_range = std::pair{lo - pad, hi + pad};
    clipped = true;
  }
  return clipped;
}

std::optional<double> blow_up_time(const DiagnosticsHistory& history) {
  for (std::size_t i = 0; i < history.size(); ++i)
    if (!(std::abs(history.energy_drift[i]) < 1.0)) return history.t[i];
  return std::nullopt;
}

}  // namespace bookspin::charts
