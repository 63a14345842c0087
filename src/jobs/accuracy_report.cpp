#include "jobs/accuracy_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/csv_writer.hpp"
#include "common/errors.hpp"

namespace bookspin::jobs {

namespace {

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
                r.method.label.c_str(), 1.0 / r.dt, r.orientation_error, r.energy_drift, r.L_drift,
                flip_error, first_error, r.flips, r.flips_exact, r.ns_per_step,
                r.diverged ? "  diverged" : "",
                r.divergence_reason.empty() ? "" : (": " + r.divergence_reason).c_str());
  return line;
}

}  // namespace

namespace {

/// Every dt must make a run of at least one step and at most kMaxAccuracySteps.
void check_step_counts(const AccuracyRequest& request, double flip_period) {
  if (!std::isfinite(flip_period)) {
    // The cause: a body without an intermediate axis never flips, whatever its start.
    const int distinct = physics::distinct_moments(request.scene.body.moments);
    if (distinct == 1)
      throw InputError(request.scene.name +
                       ": the body's three principal moments are equal (a cube or a sphere: "
                       "every axis is principal), so it never flips, whatever its spin or "
                       "jiggle: no flip period to measure the runs over");
    if (distinct == 2)
      throw InputError(request.scene.name +
                       ": two of the body's principal moments are equal (a symmetric body: no "
                       "intermediate axis), so it never flips, whatever its spin or jiggle: no "
                       "flip period to measure the runs over");
    throw InputError(request.scene.name +
                     ": the motion never flips (its L starts on a principal axis or on the "
                     "separatrix), so there is no flip period to measure the runs over: "
                     "initial.jiggle or initial.angular_velocity off the axis gives one");
  }
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

/// `poll` at `stage` as a plain "stop now?" predicate, for analysis' physics loops, which know
/// nothing of signals. Empty when `poll` is.
std::function<bool()> stop_predicate(const StopPoll& poll, std::string stage) {
  if (!poll) return {};
  return [poll, stage = std::move(stage)] { return poll(stage) != 0; };
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

std::vector<analysis::Method> long_time_methods(const std::vector<analysis::Method>& methods) {
  const auto same = [](const analysis::Method& a, const analysis::Method& b) {
    return a.kind == b.kind && a.integrator == b.integrator;
  };
  const std::vector<analysis::Method> every = analysis::accuracy_methods();
  if (std::equal(methods.begin(), methods.end(), every.begin(), every.end(), same))
    return analysis::rigid_methods();
  std::vector<analysis::Method> long_time;
  for (const auto& m : methods)
    if (m.kind != physics::ModelKind::particle) long_time.push_back(m);
  return long_time;
}

AccuracyReport measure_accuracy(const AccuracyRequest& request) {
  const std::function<bool()> stop_steps = stop_predicate(request.stop_signal, "accuracy steps");
  const std::function<bool()> stop_energy_steps =
      stop_predicate(request.stop_signal, "accuracy energy steps");
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
  AccuracyReport report;
  report.flips = request.flips;
  report.spin_rate = request.scene.initial.omega0_body.norm();
  report.methods = request.methods.empty() ? analysis::accuracy_methods() : request.methods;
  const std::vector<analysis::Method> long_time = long_time_methods(report.methods);
  for (const auto& method : report.methods) {
    for (double dt : request.dts) {
      stop_if_asked(request.stop_signal, "accuracy runs");
      report.rows.push_back(analysis::measure(settings, exact, method, dt, stop_steps));
      stop_if_asked(request.stop_signal, "accuracy runs");  // the row of a stopped run is cut
      say(table_row(report.rows.back()));
    }
  }
  for (const auto& method : long_time) {
    stop_if_asked(request.stop_signal, "accuracy energy");
    report.energy.push_back(analysis::energy_history(
        settings, exact, method, kLongTimeDt, kLongTimeFlips, kLongTimeWindows, stop_energy_steps));
    stop_if_asked(request.stop_signal, "accuracy energy");
  }
  report.table = accuracy_csv(report);
  report.energy_table = energy_csv(report);
  return report;
}

CsvTable accuracy_csv(const AccuracyReport& report) {
  const auto unless = [](bool empty, double value) {
    return empty ? std::optional<double>() : std::optional<double>(value);
  };
  CsvTable table{accuracy_csv_columns(), {}};
  for (const auto& r : report.rows) {
    const bool no_flips = std::isnan(r.flip_period);
    table.rows.push_back({
        std::string(physics::to_string(r.method.kind)),
        std::string(physics::to_string(r.method.integrator)),
        CsvNumber{r.dt},
        std::to_string(r.steps),
        CsvNumber{r.t_end},
        CsvNumber{unless(r.diverged, r.orientation_error), "%.6e"},
        CsvNumber{r.energy_drift, "%.6e"},
        CsvNumber{r.L_drift, "%.6e"},
        CsvNumber{unless(no_flips, r.flip_period)},
        CsvNumber{unless(no_flips, r.flip_period_error), "%.6e"},
        CsvNumber{r.ns_per_step, "%.2f"},
        std::string(r.diverged ? "1" : "0"),
        CsvNumber{unless(std::isnan(r.first_flip), r.first_flip)},
        CsvNumber{unless(std::isnan(r.first_flip_error), r.first_flip_error), "%.6e"},
        std::to_string(r.flips),
        std::to_string(r.flips_exact),
    });
  }
  return table;
}

CsvTable energy_csv(const AccuracyReport& report) {
  const std::vector<analysis::EnergyHistory>& histories = report.energy;
  CsvTable table{{"t"}, {}};
  for (const auto& h : histories) table.columns.push_back(h.method.label);
  // Every history has the same windows (one dt, run length and window count); a diverged
  // one stops early, whichever it is, so the rows and their times are the longest history's.
  const analysis::EnergyHistory* longest = nullptr;
  for (const auto& h : histories)
    if (longest == nullptr || h.t.size() > longest->t.size()) longest = &h;
  const std::size_t rows = longest == nullptr ? 0 : longest->t.size();
  for (std::size_t i = 0; i < rows; ++i) {
    std::vector<CsvCell> row{CsvNumber{longest->t[i], "%.9g"}};
    for (const auto& h : histories)
      row.push_back(CsvNumber{i < h.relative_error.size()
                                  ? std::optional<double>(h.relative_error[i])
                                  : std::optional<double>(),
                              "%.6e"});
    table.rows.push_back(std::move(row));
  }
  return table;
}

}  // namespace bookspin::jobs
