#include "charts/accuracy_plots.hpp"

#include <cstdio>

#include "common/colour.hpp"

namespace bookspin::charts {

namespace {

bool same_method(const analysis::Method& a, const analysis::Method& b) {
  return a.kind == b.kind && a.integrator == b.integrator;
}

/// `pattern` with the whole number of `flips` in its one %d: a plot's title.
std::string title_of(const char* pattern, double flips) {
  char title[160];
  std::snprintf(title, sizeof title, pattern, static_cast<int>(flips));
  return title;
}

/// `s` in the palette's colour `index` (common/colour.hpp, cycled).
void paint(overlay::Series& s, std::size_t index) {
  const Rgb& c = kPalette[index % kPalette.size()];
  s.r = c.r, s.g = c.g, s.b = c.b;
}

/// The palette index of bookspin's own integrator: its place in physics::Integrator, except
/// rescaled_euler, whose place would cycle onto splitting's colour (an engine's mode is
/// painted by its place among that engine's modes, in style_series).
std::size_t integrator_colour(physics::Integrator integrator) {
  return integrator == physics::Integrator::rescaled_euler ? 7
                                                           : static_cast<std::size_t>(integrator);
}

}  // namespace

void style_series(const analysis::Method& m, overlay::Series& s) {
  paint(s, integrator_colour(m.integrator));
  s.dashed = m.kind == physics::ModelKind::rigid_quaternion;
  if (m.kind == physics::ModelKind::particle)
    s.r = s.g = s.b = 0.55 - 0.15 * static_cast<int>(m.integrator);
  // The engines (docs/engines.md): one mark per engine, one colour per mode within it, solid.
  // bookspin's own models have no mark.
  switch (m.kind) {
    case physics::ModelKind::mujoco:
      s.marker = overlay::Marker::square;
      break;
    case physics::ModelKind::bullet:
      s.marker = overlay::Marker::triangle;
      break;
    case physics::ModelKind::ode:
      s.marker = overlay::Marker::diamond;
      break;
    default:
      return;
  }
  std::size_t mode = 0;
  for (const auto& e : analysis::engine_methods()) {
    if (same_method(e, m)) break;
    if (e.kind == m.kind) ++mode;
  }
  paint(s, mode);
}

namespace {

/// One line per method of `methods` through its rows' (dt, value(row)), log–log; a method
/// without rows (not run) gets no line, a diverged row is left out unless `keep_diverged`.
overlay::PlotSpec against_dt(const std::vector<analysis::AccuracyRow>& rows,
                             const std::vector<analysis::Method>& methods, bool keep_diverged,
                             double (*value)(const analysis::AccuracyRow&)) {
  overlay::PlotSpec spec;
  spec.x_label = "time step dt (time units)";
  spec.log_x = spec.log_y = true;
  for (const auto& method : methods) {
    overlay::Series s;
    s.label = method.label;
    for (const auto& r : rows) {
      if (!same_method(r.method, method) || (r.diverged && !keep_diverged)) continue;
      s.x.push_back(r.dt);
      s.y.push_back(value(r));
    }
    if (s.x.empty()) continue;
    style_series(method, s);
    spec.series.push_back(std::move(s));
  }
  return spec;
}

}  // namespace

overlay::PlotSpec orientation_error_vs_dt_plot(const std::vector<analysis::AccuracyRow>& rows,
                                               const std::vector<analysis::Method>& methods,
                                               double flips) {
  overlay::PlotSpec spec = against_dt(
      rows, methods, true, [](const analysis::AccuracyRow& r) { return r.orientation_error; });
  spec.title = title_of("Orientation error after %d flips, against the exact solution", flips);
  spec.y_label = "orientation error (rad)";
  return spec;
}

overlay::PlotSpec energy_vs_dt_plot(const std::vector<analysis::AccuracyRow>& rows,
                                    const std::vector<analysis::Method>& methods, double flips) {
  overlay::PlotSpec spec = against_dt(
      rows, methods, false, [](const analysis::AccuracyRow& r) { return r.energy_drift; });
  spec.title = title_of(
      "Largest relative energy error over %d exact flip periods, against the time step", flips);
  spec.y_label = "relative energy error max |E/E0 - 1|";
  return spec;
}

overlay::PlotSpec work_precision_plot(const std::vector<analysis::AccuracyRow>& rows,
                                      double flips) {
  overlay::PlotSpec spec;
  spec.title =
      title_of("Work-precision: orientation error after %d flips vs cost, one point per dt", flips);
  spec.x_label = "cost: CPU time of step() per simulated time unit (microseconds)";
  spec.y_label = "orientation error (rad)";
  spec.log_x = spec.log_y = true;
  for (const auto& method : analysis::accuracy_methods()) {
    overlay::Series s;
    s.label = method.label;
    for (const auto& r : rows) {
      if (!same_method(r.method, method)) continue;
      s.x.push_back(r.ns_per_step / r.dt * 1e-3);
      s.y.push_back(r.orientation_error);
    }
    if (s.x.empty()) continue;  // a method the report did not run (--methods)
    style_series(method, s);
    spec.series.push_back(std::move(s));
  }
  return spec;
}

overlay::PlotSpec long_time_energy_plot(const std::vector<analysis::EnergyHistory>& histories,
                                        double flips) {
  overlay::PlotSpec spec;
  const double dt = histories.empty() ? 0.0 : histories.front().dt;
  char title[160];
  std::snprintf(title, sizeof title,
                "Relative energy error over %d flip periods at dt = 1/%.0f (largest per window)",
                static_cast<int>(flips), dt > 0.0 ? 1.0 / dt : 0.0);
  spec.title = title;
  spec.x_label = "time t (time units)";
  spec.y_label = "relative energy error |E/E0 - 1|";
  spec.log_y = true;
  for (const auto& h : histories) {
    overlay::Series s;
    s.label = h.method.label + (h.diverged ? " (diverged)" : "");
    s.x = h.t;
    s.y = h.relative_error;
    style_series(h.method, s);
    spec.series.push_back(std::move(s));
  }
  return spec;
}

AccuracyPlots accuracy_plots(const std::vector<analysis::AccuracyRow>& rows,
                             const std::vector<analysis::Method>& methods, double flips,
                             const std::vector<analysis::EnergyHistory>& histories,
                             double history_flips) {
  return {orientation_error_vs_dt_plot(rows, methods, flips), work_precision_plot(rows, flips),
          energy_vs_dt_plot(rows, methods, flips), long_time_energy_plot(histories, history_flips)};
}

AccuracyImages accuracy_images(const std::vector<analysis::AccuracyRow>& rows,
                               const std::vector<analysis::Method>& methods, double flips,
                               const std::vector<analysis::EnergyHistory>& histories,
                               double history_flips) {
  const AccuracyPlots plots = accuracy_plots(rows, methods, flips, histories, history_flips);
  const auto image = [](const overlay::PlotSpec& spec) {
    return overlay::plot_image(spec, 1400, 900);
  };
  return {image(plots.orientation_error_vs_dt), image(plots.work_precision),
          image(plots.energy_vs_dt), image(plots.long_time_energy)};
}

}  // namespace bookspin::charts
