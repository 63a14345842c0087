#include "charts/toss_plots.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "charts/sphere_view.hpp"
#include "common/colour.hpp"
#include "overlay/plot.hpp"

namespace bookspin::charts {

overlay::SphereSpec toss_sphere_spec(const fit::TossChart& chart) {
  // The principal frame's axes 1, 2, 3 are by ascending moment: the order is theirs.
  overlay::SphereSpec spec = sphere_spec({0, 1, 2}, chart.polhodes, {});
  spec.title = "L/|L|, principal axes 1 < 2 < 3";
  for (int i = 0; i < 3; ++i) spec.axes[i].label = chart.axis_labels[static_cast<std::size_t>(i)];
  overlay::SphereCurve orbit;
  orbit.points = chart.orbit;
  orbit.colour = kFittedOrbitColour;
  orbit.width = 3.2;  // wider than the measured trail drawn over it, so both show
  spec.curves.push_back(std::move(orbit));
  overlay::SphereTrail measured;
  measured.points = chart.measured_L;
  measured.colour = kMeasuredLColour;
  measured.width = 1.0;
  spec.trails.push_back(std::move(measured));
  return spec;
}

RgbaImage toss_image(const fit::TossChart& chart, int width, int height) {
  const overlay::SphereSpec sphere = toss_sphere_spec(chart);
  const int side = std::max(1, static_cast<int>(std::min<double>(height, 0.4 * width)));
  const int plot_width = std::max(1, width - side);
  overlay::PlotSpec spec;
  // Named by its own recording, against its own clock (of several pooled, the one it was
  // thrown in).
  spec.title = (chart.recording.empty() ? "" : chart.recording + ", ") + "toss " +
               std::to_string(chart.toss + 1) + ": measured (dots) and fitted exact motion";
  spec.x_label =
      "time (s, " + (chart.recording.empty() ? "the recording" : chart.recording) + "'s clock)";
  spec.y_label = "ω, phone frame (rad/s)";
  const char* names[] = {"x", "y", "z"};
  double peak = 0.0;
  for (const auto& w : chart.measured) peak = std::max(peak, w.cwiseAbs().maxCoeff());
  for (int c = 0; c < 3; ++c) {
    overlay::Series measured, fitted;
    // ω_x, ω_y, ω_z in their colours everywhere (common/colour.hpp).
    const Rgb colour = kComponentColours[static_cast<std::size_t>(c)];
    measured.r = fitted.r = colour.r;
    measured.g = fitted.g = colour.g;
    measured.b = fitted.b = colour.b;
    measured.label = std::string("measured ω_") + names[c];
    fitted.label = std::string("fitted ω_") + names[c];
    measured.dots = true;
    measured.x = chart.t;
    fitted.x = chart.curve_t;
    for (const auto& w : chart.measured) measured.y.push_back(w[c]);
    for (const auto& w : chart.curve) fitted.y.push_back(w[c]);
    spec.series.push_back(std::move(measured));
    spec.series.push_back(std::move(fitted));
  }
  overlay::Series flips;
  flips.label = "flip (fitted)";
  flips.r = flips.g = flips.b = 0.5;
  flips.dashed = true;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const double when : chart.flips) {
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
  overlay::draw_sphere(image, square, sphere);
  return image;
}

}  // namespace bookspin::charts
