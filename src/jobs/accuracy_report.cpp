#include "jobs/accuracy_report.hpp"

#include <cmath>
#include <cstdio>

#include "charts/accuracy_plots.hpp"
#include "common/errors.hpp"
#include "output/atomic_output.hpp"
#include "output/finite_number.hpp"
#include "output/output_dir.hpp"
#include "output/png_writer.hpp"
#include "overlay/plot.hpp"

namespace bookspin::jobs {

namespace {

/// `value` in printf `format`, checked finite (output/finite_number.hpp); or "" (an empty
/// cell) when `empty`: no orientation error after a divergence, no flip period where fewer
/// than two flips were seen (docs/outputs.md, "Numbers").
std::string cell(const char* format, double value, const char* column, bool empty = false) {
  if (empty) return "";
  char text[64];
  std::snprintf(text, sizeof text, format,
                output::finite(value, std::string("accuracy CSV column ") + column));
  return text;
}

std::string csv_line(const analysis::AccuracyRow& r) {
  const bool no_flips = std::isnan(r.flip_period);
  return std::string(physics::to_string(r.method.kind)) + "," +
         std::string(physics::to_string(r.method.integrator)) + "," + cell("%.17g", r.dt, "dt") +
         "," + std::to_string(r.steps) + "," + cell("%.17g", r.t_end, "t_end") + "," +
         cell("%.6e", r.orientation_error, "orientation_error_rad", r.diverged) + "," +
         cell("%.6e", r.energy_drift, "energy_drift") + "," + cell("%.6e", r.L_drift, "L_drift") +
         "," + cell("%.17g", r.flip_period, "flip_period", no_flips) + "," +
         cell("%.6e", r.flip_period_error, "flip_period_error", no_flips) + "," +
         cell("%.2f", r.ns_per_step, "ns_per_step") + "," + (r.diverged ? "1" : "0") + "," +
         cell("%.17g", r.first_flip, "first_flip", std::isnan(r.first_flip)) + "," +
         cell("%.6e", r.first_flip_error, "first_flip_error", std::isnan(r.first_flip_error)) +
         "," + std::to_string(r.flips) + "," + std::to_string(r.flips_exact);
}

std::string table_row(const analysis::AccuracyRow& r) {
  // Fewer than two flips seen: no flip period to compare, shown as "-".
  char flip_error[32] = "-";
  if (!std::isnan(r.flip_period_error))
    std::snprintf(flip_error, sizeof flip_error, "%.3e", r.flip_period_error);
  char first_error[32] = "-";
  if (!std::isnan(r.first_flip_error))
    std::snprintf(first_error, sizeof first_error, "%.2e", r.first_flip_error);
  char line[512];
  std::snprintf(line, sizeof line,
                "%-28s 1/%-5.0f %12.3e %11.2e %11.2e %12s %11s %5d/%-5d %9.1f%s%s",
                charts::method_label(r.method).c_str(), 1.0 / r.dt, r.orientation_error,
                r.energy_drift, r.L_drift, flip_error, first_error, r.flips, r.flips_exact,
                r.ns_per_step, r.diverged ? "  diverged" : "",
                r.divergence_reason.empty() ? "" : (": " + r.divergence_reason).c_str());
  return line;
}

void write_csv(const std::filesystem::path& path, const std::vector<analysis::AccuracyRow>& rows) {
  output::AtomicTextFile file(path);
  std::ostream& out = file.stream();
  const auto& columns = accuracy_csv_columns();
  for (std::size_t i = 0; i < columns.size(); ++i) out << (i > 0 ? "," : "") << columns[i];
  out << '\n';
  for (const auto& r : rows) out << csv_line(r) << '\n';
  file.commit();
}

}  // namespace

namespace {

/// Every dt must make a run of at least one step and at most kMaxAccuracySteps.
void check_step_counts(const AccuracyRequest& request, double flip_period) {
  if (!std::isfinite(flip_period))
    throw InputError(request.scene.name +
                     ": the motion never flips (its L starts on a principal axis or on the "
                     "separatrix), so there is no flip period to measure the runs over: "
                     "initial.jiggle or initial.angular_velocity off the axis gives one");
  for (double dt : request.dts) {
    const double steps = request.flips * flip_period / dt;
    if (steps >= 1.0 && steps <= kMaxAccuracySteps) continue;
    char message[256];
    std::snprintf(message, sizeof message,
                  "--dt %g: %g steps for %g flip periods of %g time units (expected 1 to %g)", dt,
                  steps, request.flips, flip_period, kMaxAccuracySteps);
    throw InputError(message);
  }
}

std::string format_line(const char* pattern, const std::string& a, double b, double c, double d) {
  char line[256];
  std::snprintf(line, sizeof line, pattern, a.c_str(), b, c, d);
  return line;
}

}  // namespace

const std::vector<std::string>& accuracy_csv_columns() {
  static const std::vector<std::string> columns{"model",        "integrator",
                                                "dt",           "steps",
                                                "t_end",        "orientation_error_rad",
                                                "energy_drift", "L_drift",
                                                "flip_period",  "flip_period_error",
                                                "ns_per_step",  "diverged",
                                                "first_flip",   "first_flip_error",
                                                "flips",        "flips_exact"};
  return columns;
}

std::vector<std::filesystem::path> run_accuracy(const AccuracyRequest& request) {
  const scene::Scene& scene = request.scene;
  const auto say = [&](const std::string& line) {
    if (request.on_line) request.on_line(line);
  };
  analysis::AccuracySettings settings{scene.body, scene.initial, scene.model, request.flips};
  const auto exact = analysis::exact_reference(settings);
  check_step_counts(request, exact.flip_period());
  say(format_line("%s: exact flip period T/2 = 2K(k)/lambda = %.9g time units (k = %.9g), %g flips",
                  scene.name, exact.flip_period(), exact.modulus(), request.flips));
  char header[256];
  std::snprintf(header, sizeof header, "%-28s %-7s %12s %11s %11s %12s %11s %11s %9s", "method",
                "dt", "orient. err", "energy drift", "|L| drift", "flip T err", "1st flip err",
                "flips/exact", "ns/step");
  say(header);
  const std::vector<analysis::Method> methods =
      request.methods.empty() ? analysis::accuracy_methods() : request.methods;
  std::vector<analysis::AccuracyRow> rows;
  for (const auto& method : methods) {
    for (double dt : request.dts) {
      stop_if_asked(request.stop_signal, "accuracy runs");
      rows.push_back(analysis::measure(settings, exact, method, dt,
                                       stop_predicate(request.stop_signal, "accuracy steps")));
      stop_if_asked(request.stop_signal, "accuracy runs");  // the row of a stopped run is cut
      say(table_row(rows.back()));
    }
  }
  const AccuracyPaths& paths = request.paths;
  output::prepare_output_dir(paths.csv.parent_path());
  // The plots run the long-time histories (a stop there writes nothing), then every file.
  const std::vector<std::filesystem::path> plots = charts::write_accuracy_plots(
      paths.plots, settings, exact, rows, methods, request.stop_signal);
  std::vector<std::filesystem::path> written{paths.csv, paths.png};
  write_csv(written[0], rows);
  output::write_png(written[1], overlay::plot_image(charts::orientation_error_vs_dt_plot(
                                                        rows, methods, request.flips),
                                                    1400, 900));
  written.insert(written.end(), plots.begin(), plots.end());
  return written;
}

}  // namespace bookspin::jobs
