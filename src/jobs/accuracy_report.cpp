#include "jobs/accuracy_report.hpp"

#include <cstdio>

#include "common/errors.hpp"
#include "output/atomic_output.hpp"
#include "output/output_dir.hpp"
#include "output/png_writer.hpp"
#include "overlay/plot.hpp"
#include "charts/accuracy_plots.hpp"

namespace bookspin::jobs {

namespace {

std::string csv_line(const analysis::AccuracyRow& r) {
  char line[512];
  std::snprintf(line, sizeof line, "%s,%s,%.17g,%ld,%.17g,%.6e,%.6e,%.6e,%.17g,%.6e,%.2f,%d",
                std::string(physics::to_string(r.method.kind)).c_str(),
                std::string(physics::to_string(r.method.integrator)).c_str(), r.dt, r.steps,
                r.t_end, r.orientation_error, r.energy_drift, r.L_drift, r.flip_period,
                r.flip_period_error, r.ns_per_step, r.diverged ? 1 : 0);
  return line;
}

std::string table_row(const analysis::AccuracyRow& r) {
  char line[512];
  std::snprintf(line, sizeof line, "%-28s 1/%-5.0f %12.3e %11.2e %11.2e %12.3e %9.1f%s%s\n",
                charts::method_label(r.method).c_str(), 1.0 / r.dt, r.orientation_error,
                r.energy_drift, r.L_drift, r.flip_period_error, r.ns_per_step,
                r.diverged ? "  diverged" : "",
                r.divergence_reason.empty() ? "" : (": " + r.divergence_reason).c_str());
  return line;
}

void write_csv(const std::filesystem::path& path, const std::vector<analysis::AccuracyRow>& rows) {
  output::AtomicTextFile file(path);
  std::ostream& out = file.stream();
  out << "model,integrator,dt,steps,t_end,orientation_error_rad,energy_drift,L_drift,"
         "flip_period,flip_period_error,ns_per_step,diverged\n";
  for (const auto& r : rows) out << csv_line(r) << '\n';
  file.commit();
}

overlay::PlotSpec accuracy_plot(const std::vector<analysis::AccuracyRow>& rows, double flips) {
  overlay::PlotSpec spec;
  spec.title = "Orientation error after " + std::to_string(static_cast<int>(flips)) +
               " flips, against the exact solution";
  spec.x_label = "time step dt (time units)";
  spec.y_label = "orientation error (rad)";
  spec.log_x = spec.log_y = true;
  for (const auto& method : analysis::all_methods()) {
    overlay::Series s;
    s.label = charts::method_label(method);
    for (const auto& r : rows) {
      if (r.method.kind != method.kind || r.method.integrator != method.integrator) continue;
      s.x.push_back(r.dt);
      s.y.push_back(r.orientation_error);
    }
    charts::style_series(method, s);
    spec.series.push_back(std::move(s));
  }
  return spec;
}

}  // namespace

namespace {

std::string format_line(const char* pattern, const std::string& a, double b, double c, double d) {
  char line[256];
  std::snprintf(line, sizeof line, pattern, a.c_str(), b, c, d);
  return line;
}

}  // namespace

std::vector<std::filesystem::path> run_accuracy(const AccuracyRequest& request) {
  const scene::Scene& scene = request.scene;
  const auto say = [&](const std::string& line) {
    if (request.on_line) request.on_line(line);
  };
  analysis::AccuracySettings settings{scene.body, scene.initial, scene.model, request.flips};
  const auto exact = analysis::exact_reference(settings);
  say(format_line("%s: exact flip period T/2 = 2K(k)/lambda = %.9g time units (k = %.9g), %g flips",
                  scene.name, exact.flip_period(), exact.modulus(), request.flips));
  char header[256];
  std::snprintf(header, sizeof header, "%-28s %-7s %12s %11s %11s %12s %9s", "method", "dt",
                "orient. err", "energy drift", "|L| drift", "flip T err", "ns/step");
  say(header);
  std::vector<analysis::AccuracyRow> rows;
  for (const auto& method : analysis::all_methods()) {
    for (double dt : request.dts) {
      rows.push_back(analysis::measure(settings, exact, method, dt));
      say(table_row(rows.back()));
    }
  }
  const std::filesystem::path& out = request.out_dir;
  output::prepare_output_dir(out);
  std::vector<std::filesystem::path> written{out / (scene.name + "-accuracy.csv"),
                                             out / (scene.name + "-accuracy.png")};
  write_csv(written[0], rows);
  output::write_png(written[1], overlay::plot_image(accuracy_plot(rows, request.flips), 1400, 900));
  for (const auto& path : charts::write_accuracy_plots(out, scene.name, settings, exact, rows))
    written.push_back(path);
  return written;
}

}  // namespace bookspin::jobs
