#include "charts/accuracy_plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

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

/// The turn-over chart's y range: 0 (never turns over) to the largest ratio drawn, rounded up
/// to a whole number, at least 2 (twice the exact count) and at most kMaxTurnoverRatio; a
/// ratio beyond that is drawn to the top edge, with a mark where its line leaves the range.
constexpr double kMinTurnoverTop = 2.0;
constexpr double kMaxTurnoverRatio = 10.0;

/// The energy chart's top: a relative energy error of 100 (E off by a hundred times E0); a
/// larger one is drawn at the top edge with a mark.
constexpr double kMaxEnergyError = 1e2;

/// The families of the engines' modes (docs/engines.md), which the charts colour alike.
enum class ModeFamily { explicit_euler, implicit_euler, rk4, no_gyroscopic_term };

ModeFamily family_of(physics::Integrator integrator) {
  switch (integrator) {
    case physics::Integrator::euler:          // MuJoCo's semi-implicit Euler: explicit gyroscopic
    case physics::Integrator::explicit_gyro:  // Bullet's explicit gyroscopic force
      return ModeFamily::explicit_euler;
    case physics::Integrator::rk4:
      return ModeFamily::rk4;
    case physics::Integrator::none:
      return ModeFamily::no_gyroscopic_term;
    default:  // MuJoCo's implicit, Bullet's implicit body and world, ODE's step and quickstep
      return ModeFamily::implicit_euler;
  }
}

/// The palette index of a family: explicit as bookspin's Euler (blue), RK4 as bookspin's RK4
/// (pink), implicit green, no gyroscopic term brown.
std::size_t family_colour(ModeFamily family) {
  switch (family) {
    case ModeFamily::explicit_euler:
      return integrator_colour(physics::Integrator::euler);
    case ModeFamily::rk4:
      return integrator_colour(physics::Integrator::rk4);
    case ModeFamily::no_gyroscopic_term:
      return 8;
    default:
      return 2;
  }
}

/// "; |ω0| = 6.28 rad/t, ω·dt = 0.0016 … 0.21 rad": the spin of the run (rad per time unit)
/// and the angle it turns per step at the rows' smallest and largest dt, short enough to share
/// a title line; "" without a spin.
std::string spin_text(double spin_rate, const std::vector<analysis::AccuracyRow>& rows) {
  if (!(spin_rate > 0.0) || rows.empty()) return "";
  double lo = rows.front().dt, hi = lo;
  for (const auto& r : rows) lo = std::min(lo, r.dt), hi = std::max(hi, r.dt);
  char text[120];
  if (lo == hi) {
    std::snprintf(text, sizeof text, "; |ω0| = %.3g rad/t, ω·dt = %.2g rad", spin_rate,
                  spin_rate * lo);
  } else {
    std::snprintf(text, sizeof text, "; |ω0| = %.3g rad/t, ω·dt = %.2g … %.2g rad", spin_rate,
                  spin_rate * lo, spin_rate * hi);
  }
  return text;
}

}  // namespace

void style_series(const analysis::Method& m, overlay::Series& s) {
  paint(s, integrator_colour(m.integrator));
  s.dashed = m.kind == physics::ModelKind::rigid_quaternion;
  if (m.kind == physics::ModelKind::particle)
    s.r = s.g = s.b = 0.55 - 0.15 * static_cast<int>(m.integrator);
  // The engines (docs/engines.md): one mark per engine, one colour per family of modes
  // (explicit, implicit, RK4, no gyroscopic term), solid; bookspin's own models have no mark.
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
  const ModeFamily family = family_of(m.integrator);
  paint(s, family_colour(family));
  // A second mode of the same family in one engine (Bullet's implicit body and world, ODE's
  // step and quickstep): the family's colour, lighter, so the two lines stay apart.
  int before = 0;
  for (const auto& e : analysis::engine_methods()) {
    if (same_method(e, m)) break;
    if (e.kind == m.kind && family_of(e.integrator) == family) ++before;
  }
  if (before > 0) {
    const double toward_white = 0.5;
    s.r += (1.0 - s.r) * toward_white, s.g += (1.0 - s.g) * toward_white;
    s.b += (1.0 - s.b) * toward_white;
  }
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
                                               double flips, double spin_rate) {
  overlay::PlotSpec spec = against_dt(
      rows, methods, true, [](const analysis::AccuracyRow& r) { return r.orientation_error; });
  spec.title = spin_rate > 0.0 ? title_of("Orientation error after %d flips", flips) +
                                     spin_text(spin_rate, rows)
                               : title_of(
                                     "Orientation error after %d flips, against the exact "
                                     "solution",
                                     flips);
  spec.y_label = "orientation error (rad)";
  return spec;
}

overlay::PlotSpec energy_vs_dt_plot(const std::vector<analysis::AccuracyRow>& rows,
                                    const std::vector<analysis::Method>& methods, double flips,
                                    double spin_rate) {
  overlay::PlotSpec spec = against_dt(
      rows, methods, true, [](const analysis::AccuracyRow& r) { return r.energy_drift; });
  // An error beyond kMaxEnergyError (a run that blew up, its largest error before it did) is
  // drawn at the top edge with a mark, not off the chart and not left out.
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const overlay::Series& s : spec.series) {
    for (double y : s.y) {
      if (!(std::isfinite(y) && y > 0.0)) continue;
      lo = std::min(lo, y), hi = std::max(hi, y);
    }
  }
  if (hi > kMaxEnergyError)
    spec.y_range = std::pair{std::pow(10.0, std::floor(std::log10(lo))), kMaxEnergyError};
  spec.title =
      spin_rate > 0.0
          ? title_of("Energy error over %d flip periods", flips) + spin_text(spin_rate, rows)
          : title_of(
                "Largest relative energy error over %d exact flip periods, against the time "
                "step",
                flips);
  spec.y_label = "relative energy error max |E/E0 - 1|";
  return spec;
}

overlay::PlotSpec turnovers_vs_dt_plot(const std::vector<analysis::AccuracyRow>& rows,
                                       const std::vector<analysis::Method>& methods, double flips,
                                       double spin_rate) {
  overlay::PlotSpec spec = against_dt(rows, methods, false, [](const analysis::AccuracyRow& r) {
    return r.flips_exact > 0 ? static_cast<double>(r.flips) / r.flips_exact : std::nan("");
  });
  spec.title =
      title_of("Turn-overs / exact over %d flip periods", flips) + spin_text(spin_rate, rows);
  spec.y_label = "turn-overs / exact turn-overs (1: right)";
  spec.log_y = false;
  double top = kMinTurnoverTop;
  for (const overlay::Series& s : spec.series)
    for (double y : s.y)
      if (std::isfinite(y)) top = std::max(top, std::min(std::ceil(y), kMaxTurnoverRatio));
  spec.y_range = std::pair{0.0, top};
  for (overlay::Series& s : spec.series) {
    bool turns = false;
    for (const auto& r : rows)
      if (r.method.label == s.label && r.flips > 0) turns = true;
    if (!turns) s.label += " (never turns over)";
  }
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
                             double spin_rate,
                             const std::vector<analysis::EnergyHistory>& histories,
                             double history_flips) {
  return {orientation_error_vs_dt_plot(rows, methods, flips, spin_rate),
          work_precision_plot(rows, flips), energy_vs_dt_plot(rows, methods, flips, spin_rate),
          turnovers_vs_dt_plot(rows, methods, flips, spin_rate),
          long_time_energy_plot(histories, history_flips)};
}

AccuracyImages accuracy_images(const std::vector<analysis::AccuracyRow>& rows,
                               const std::vector<analysis::Method>& methods, double flips,
                               double spin_rate,
                               const std::vector<analysis::EnergyHistory>& histories,
                               double history_flips) {
  const AccuracyPlots plots =
      accuracy_plots(rows, methods, flips, spin_rate, histories, history_flips);
  const auto image = [](const overlay::PlotSpec& spec) {
    return overlay::plot_image(spec, 1280, 640);  // whole on a 1366×768 screen
  };
  return {image(plots.orientation_error_vs_dt), image(plots.work_precision),
          image(plots.energy_vs_dt), image(plots.turnovers_vs_dt), image(plots.long_time_energy)};
}

}  // namespace bookspin::charts
