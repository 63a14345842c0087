#include "fit/report.hpp"

#include <cmath>
#include <utility>

#include "common/errors.hpp"
#include "fit/fit_tables.hpp"
#include "fit/pool.hpp"
#include "physics/exact_solution.hpp"

namespace bookspin::fit {
namespace {

/// L/|L| in the principal frame for principal ω `w` and moments `moments`.
Eigen::Vector3d momentum_direction(const Eigen::Vector3d& moments, const Eigen::Vector3d& w) {
  return moments.cwiseProduct(w).normalized();
}

/// The points of the fitted exact orbit on the sphere (one period of ω, or the flight).
constexpr int kOrbitPoints = 720;
/// The chart's lines: the fitted ω every millisecond (s).
constexpr double kCurveStep = 0.001;

}  // namespace

TossChart toss_chart(const GyroRecording& recording, const FitResult& fit, int toss) {
  const TossFit& fitted = fit.tosses.at(static_cast<std::size_t>(toss));
  const BodyEstimate& body = fit.body;
  TossChart chart;
  chart.toss = toss;
  const Flight& flight = fitted.flight;
  // Its own recording's name and clock (of several pooled, the one it was thrown in).
  const RecordingPart& part = part_at(fit.parts, flight.t_start);
  chart.recording = part.name;
  chart.t_offset = part.t_offset;
  measured_omega(recording, fit, toss, chart.t, chart.measured);
  for (double& s : chart.t) {
    chart.fitted.push_back(fitted_omega(fit, toss, s));
    s -= chart.t_offset;
  }
  for (double s = flight.t_start; s <= flight.t_end + 1e-12; s += kCurveStep) {
    chart.curve_t.push_back(s - chart.t_offset);
    chart.curve.push_back(fitted_omega(fit, toss, s));
  }
  const Eigen::Vector3d axis2 = body.axes.col(1);
  for (std::size_t i = 1; i < chart.curve_t.size() && !fitted.stable; ++i) {
    const double a = axis2.dot(chart.curve[i - 1]), b = axis2.dot(chart.curve[i]);
    if ((a > 0) == (b > 0)) continue;
    chart.flips.push_back(chart.curve_t[i - 1] +
                          (chart.curve_t[i] - chart.curve_t[i - 1]) * a / (a - b));
  }
  // The sphere, in the fitted principal frame.
  chart.moments = body.ratios;
  static const char* const kPhone[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    // The phone axis the principal axis lies nearest, with its sign.
    Eigen::Index nearest = 0;
    body.axes.col(i).cwiseAbs().maxCoeff(&nearest);
    chart.axis_labels[static_cast<std::size_t>(i)] = std::to_string(i + 1) + " · phone " +
                                                     (body.axes(nearest, i) < 0 ? "-" : "") +
                                                     kPhone[nearest];
  }
  chart.polhodes = physics::polhode_family(chart.moments);
  const physics::ExactRotation exact(body.ratios, body.axes.transpose() * fitted.omega0,
                                     physics::ExactParts::omega_only);
  const double span =
      std::isfinite(exact.period()) ? exact.period() : flight.t_end - flight.t_start;
  for (int i = 0; i <= kOrbitPoints; ++i)
    chart.orbit.push_back(
        momentum_direction(body.ratios, exact.omega_body(span * i / kOrbitPoints)));
  for (const Eigen::Vector3d& w : chart.measured)
    if (w.squaredNorm() > 0)
      chart.measured_L.push_back(momentum_direction(body.ratios, body.axes.transpose() * w));
  return chart;
}

FitReport fit_report(const GyroRecording& recording, const FitRequest& request,
                     const StopPoll& stop) {
  stop_if_asked(stop, "fit flights");
  const std::string tosses = tosses_name(request.reader);
  if (recording.parts.size() >= 2 && !request.tosses.empty())
    throw InputError(tosses + ": with one recording only (the times are that recording's)");
  const FlightSearch search = request.tosses.empty()
                                  ? find_flights(recording)
                                  : hand_flights(recording, request.tosses, tosses);
  // Nothing found: why, in the data's terms, and how to name the flights by hand at this door.
  if (search.flights.empty())
    throw_no_flight(recording, search, hand_flights_remedy(request.reader));
  FitReport report;
  report.recording = recording.name;
  report.source = recording.source;
  FitSettings settings = request.settings;
  if (!settings.stop) settings.stop = stop;     // polled by the solver too
  settings.trim_ends = request.tosses.empty();  // flights by hand are fitted as given
  report.result = fit_recording(recording, search, settings);
  const FitResult& result = report.result;
  report.toss_csv = csv_text(fit_toss_csv(result), "fit CSV");
  report.body_csv = csv_text(fit_body_csv(result), "fit body CSV");
  report.summary = fit_summary(result, request.reader);
  report.dropped = fit_dropped_lines(result);
  report.has_scenes = toss_book(result.body).has_value();
  if (!report.has_scenes) report.summary.push_back(kNoSceneLine);
  for (int k = 0; k < static_cast<int>(result.tosses.size()); ++k) {
    stop_if_asked(stop, "fit charts");
    TossReport toss{toss_chart(recording, result, k), toss_scene(recording, result, k), {}, {}};
    if (toss.scene) {
      toss.scene_text = toss_scene_text(*toss.scene, k, recording.name);
      toss.measured_csv = csv_text(toss_measured_csv(*toss.scene), "fit measured CSV");
    }
    report.tosses.push_back(std::move(toss));
  }
  return report;
}

}  // namespace bookspin::fit
