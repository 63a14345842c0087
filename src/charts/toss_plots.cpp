#include "charts/toss_plots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "charts/sphere_view.hpp"
#include "overlay/plot.hpp"
#include "physics/exact_solution.hpp"

namespace bookspin::charts {

namespace {

/// L/|L| in the principal frame for principal ω `w` and moments `moments`.
Eigen::Vector3d momentum_direction(const Eigen::Vector3d& moments, const Eigen::Vector3d& w) {
  return moments.cwiseProduct(w).normalized();
}

}  // namespace

overlay::SphereSpec toss_sphere_spec(const fit::GyroRecording& recording, const fit::FitResult& fit,
                                     int toss) {
  const Eigen::Vector3d& moments = fit.body.ratios;
  const Eigen::Matrix3d& axes = fit.body.axes;
  overlay::SphereSpec spec = sphere_spec(moments, {});
  spec.title = "L/|L|, principal axes 1 < 2 < 3";
  static const char* const kPhone[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    // The phone axis the principal axis lies nearest, with its sign.
    Eigen::Index nearest = 0;
    axes.col(i).cwiseAbs().maxCoeff(&nearest);
    spec.axes[i].label =
        std::to_string(i + 1) + " · phone " + (axes(nearest, i) < 0 ? "-" : "") + kPhone[nearest];
  }
  // The fitted exact orbit: one period of ω, or the flight where there is none.
  const fit::TossFit& fitted = fit.tosses.at(toss);
  const physics::ExactRotation exact(moments, axes.transpose() * fitted.omega0,
                                     physics::ExactParts::omega_only);
  const double span =
      std::isfinite(exact.period()) ? exact.period() : fitted.flight.t_end - fitted.flight.t_start;
  overlay::SphereCurve orbit;
  constexpr int kOrbitPoints = 720;
  for (int i = 0; i <= kOrbitPoints; ++i)
    orbit.points.push_back(momentum_direction(moments, exact.omega_body(span * i / kOrbitPoints)));
  orbit.colour = kFittedOrbitColour;
  orbit.width = 3.2;  // wider than the measured trail drawn over it, so both show
  spec.curves.push_back(std::move(orbit));
  std::vector<double> t;
  std::vector<Eigen::Vector3d> omega;
  fit::measured_omega(recording, fit, toss, t, omega);
  overlay::SphereTrail measured;
  for (const Eigen::Vector3d& w : omega)
    if (w.squaredNorm() > 0)
      measured.points.push_back(momentum_direction(moments, axes.transpose() * w));
  measured.colour = kMeasuredLColour;
  measured.width = 1.0;
  spec.trails.push_back(std::move(measured));
  return spec;
}

RgbaImage toss_image(const fit::GyroRecording& recording, const fit::FitResult& fit, int toss,
                     int width, int height) {
  const int side = std::max(1, static_cast<int>(std::min<double>(height, 0.4 * width)));
  const int plot_width = std::max(1, width - side);
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
  // A stable toss's ω circles an end axis: its component about axis 2 changes sign with the
  // wobble, and those are not flips.
  const bool stable = fit.tosses.at(toss).stable;
  for (std::size_t i = 1; i < tf.size() && !stable; ++i) {
    const double a = axis2.dot(wf[i - 1]), b = axis2.dot(wf[i]);
    if ((a > 0) == (b > 0)) continue;
    const double when = tf[i - 1] + (tf[i] - tf[i - 1]) * a / (a - b);
    flips.x.insert(flips.x.end(), {when, when, nan});
    flips.y.insert(flips.y.end(), {-1.05 * peak, 1.05 * peak, nan});
  }
  if (!flips.x.empty()) spec.series.push_back(std::move(flips));
  // The sphere's two colours, in the legend (no points in the plot).
  overlay::Series sphere_measured, sphere_fitted;
  sphere_measured.label = "sphere: measured L/|L|";
  sphere_measured.r = kMeasuredLColour.r, sphere_measured.g = kMeasuredLColour.g,
  sphere_measured.b = kMeasuredLColour.b;
  sphere_fitted.label = "sphere: fitted exact orbit";
  sphere_fitted.r = kFittedOrbitColour.r, sphere_fitted.g = kFittedOrbitColour.g,
  sphere_fitted.b = kFittedOrbitColour.b;
  spec.series.push_back(std::move(sphere_measured));
  spec.series.push_back(std::move(sphere_fitted));
  spec.y_range = std::pair{-1.1 * peak, 1.1 * peak};
  const RgbaImage plot = overlay::plot_image(spec, plot_width, height);
  RgbaImage image(width, height);
  std::fill(image.pixels.begin(), image.pixels.end(), std::uint8_t{255});
  for (int y = 0; y < height; ++y)
    std::copy_n(plot.pixels.data() + 4 * static_cast<std::size_t>(y) * plot_width, 4 * plot_width,
                image.pixels.data() + 4 * static_cast<std::size_t>(y) * width);
  const PixelRect square{static_cast<double>(plot_width), 0.5 * (height - side),
                         static_cast<double>(side), static_cast<double>(side)};
  overlay::draw_sphere(image, square, toss_sphere_spec(recording, fit, toss));
  return image;
}

}  // namespace bookspin::charts
