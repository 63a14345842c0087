#include "charts/accuracy_plots.hpp"

#include <cstdio>

namespace bookspin::charts {

namespace {

bool same_method(const analysis::Method& a, const analysis::Method& b) {
  return a.kind == b.kind && a.integrator == b.integrator;
}

}  // namespace

std::string method_label(const analysis::Method& m) {
  return std::string(physics::to_string(m.kind)) + " " +
         std::string(physics::to_string(m.integrator));
}

void style_series(const analysis::Method& m, overlay::Series& s) {
  overlay::palette_colour(static_cast<int>(m.integrator), s.r, s.g, s.b);
  s.dashed = m.kind == physics::ModelKind::rigid_quaternion;
  if (m.kind == physics::ModelKind::particle)
    s.r = s.g = s.b = 0.55 - 0.15 * static_cast<int>(m.integrator);
  if (!physics::is_engine(m.kind)) return;
  // The engines (docs/engines.md): one mark per engine, one colour per mode within it, solid.
  s.marker = m.kind == physics::ModelKind::mujoco   ? overlay::Marker::square
             : m.kind == physics::ModelKind::bullet ? overlay::Marker::triangle
                                                    : overlay::Marker::diamond;
  int mode = 0;
  for (const auto& e : analysis::engine_methods()) {
    if (same_method(e, m)) break;
    if (e.kind == m.kind) ++mode;
  }
  overlay::palette_colour(mode, s.r, s.g, s.b);
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
    s.label = method_label(method);
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
  spec.title = "Orientation error after " + std::to_string(static_cast<int>(flips)) +
               " flips, against the exact solution";
  spec.y_label = "orientation error (rad)";
  return spec;
}

overlay::PlotSpec energy_vs_dt_plot(const std::vector<analysis::AccuracyRow>& rows,
                                    const std::vector<analysis::Method>& methods, double flips) {
  overlay::PlotSpec spec = against_dt(
      rows, methods, false, [](const analysis::AccuracyRow& r) { return r.energy_drift; });
  spec.title = "Largest relative energy error over " + std::to_string(static_cast<int>(flips)) +
               " exact flip periods, against the time step";
  spec.y_label = "relative energy error max |E/E0 - 1|";
  return spec;
}

overlay::PlotSpec work_precision_plot(const std::vector<analysis::AccuracyRow>& rows,
                                      double flips) {
  overlay::PlotSpec spec;
  spec.title = "Work-precision: orientation error after " +
               std::to_string(static_cast<int>(flips)) + " flips vs cost, one point per dt";
  spec.x_label = "cost: CPU time of step() per simulated time unit (microseconds)";
  spec.y_label = "orientation error (rad)";
  spec.log_x = spec.log_y = true;
  for (const auto& method : analysis::accuracy_methods()) {
    overlay::Series s;
    s.label = method_label(method);
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
    s.label = method_label(h.method) + (h.diverged ? " (diverged)" : "");
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
