#include "charts/toss_plots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "overlay/plot.hpp"

namespace bookspin::charts {

RgbaImage toss_image(const fit::GyroRecording& recording, const fit::FitResult& fit, int toss,
                     int width, int height) {
  std::vector<double> t;
  std::vector<Eigen::Vector3d> omega;
  fit::measured_omega(recording, fit, toss, t, omega);
  const fit::Flight& flight = fit.tosses.at(toss).flight;
  overlay::PlotSpec spec;
  spec.title = "toss " + std::to_string(toss + 1) + ": measured (dots) and fitted exact motion";
  spec.x_label = "time (s)";
  spec.y_label = "omega, phone frame (rad/s)";
  const char* names[] = {"x", "y", "z"};
  double peak = 0.0;
  for (const auto& w : omega) peak = std::max(peak, w.cwiseAbs().maxCoeff());
  // The fitted motion every millisecond, and its flips: sign changes about axis 2.
  std::vector<double> tf;
  std::vector<Eigen::Vector3d> wf;
  for (double s = flight.t_start; s <= flight.t_end + 1e-12; s += 0.001) {
    tf.push_back(s);
    wf.push_back(fit::fitted_omega(fit, toss, s));
  }
  for (int c = 0; c < 3; ++c) {
    overlay::Series measured, fitted;
    overlay::palette_colour(c, measured.r, measured.g, measured.b);
    overlay::palette_colour(c, fitted.r, fitted.g, fitted.b);
    measured.label = std::string("measured omega_") + names[c];
    fitted.label = std::string("fitted omega_") + names[c];
    measured.dots = true;
    measured.x = t;
    fitted.x = tf;
    for (const auto& w : omega) measured.y.push_back(w[c]);
    for (const auto& w : wf) fitted.y.push_back(w[c]);
    spec.series.push_back(std::move(measured));
    spec.series.push_back(std::move(fitted));
  }
  overlay::Series flips;
  flips.label = "flip (fitted)";
  flips.r = flips.g = flips.b = 0.5;
  flips.dashed = true;
  const Eigen::Vector3d axis2 = fit.body.axes.col(1);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 1; i < tf.size(); ++i) {
    const double a = axis2.dot(wf[i - 1]), b = axis2.dot(wf[i]);
    if ((a > 0) == (b > 0)) continue;
    const double when = tf[i - 1] + (tf[i] - tf[i - 1]) * a / (a - b);
    flips.x.insert(flips.x.end(), {when, when, nan});
    flips.y.insert(flips.y.end(), {-1.05 * peak, 1.05 * peak, nan});
  }
  if (!flips.x.empty()) spec.series.push_back(std::move(flips));
  spec.y_range = std::pair{-1.1 * peak, 1.1 * peak};
  return overlay::plot_image(spec, width, height);
}

}  // namespace bookspin::charts
