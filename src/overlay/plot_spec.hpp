#pragma once
// What a line plot shows (plot.hpp draws it): its series, axes, labels and legend, as a value.
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace bookspin::overlay {

/// The mark at each point of a series with few points (≤ 16). The legend shows every mark
/// but the default circle.
enum class Marker { circle, square, triangle, diamond };

struct Series {
  std::string label;
  std::vector<double> x, y;  ///< same length; non-finite or (on a log axis) non-positive
                             ///< points break the line
  double r = 0, g = 0, b = 0;
  bool dashed = false;
  Marker marker = Marker::circle;
  /// A dot at every point and no line (measured samples, e.g. a gyroscope's).
  bool dots = false;
};

/// Where the legend goes: right of the plot area (wide plots), or in rows between the
/// title and the plot area (narrow plots such as the panel beside a book).
enum class LegendPlacement { right, top };

struct PlotSpec {
  std::string title;
  std::string x_label;  ///< with units, e.g. "time step dt (time units)"
  std::string y_label;
  bool log_x = false;
  bool log_y = false;
  std::vector<Series> series;
  std::optional<double> cursor_x;  ///< a vertical time cursor
  bool legend = true;
  LegendPlacement legend_placement = LegendPlacement::right;
  /// Fixed x range (linear axes): curves that grow with time then fill it left to right
  /// instead of rescaling every frame. Unset: fitted to the data.
  std::optional<std::pair<double, double>> x_range;
  /// Smallest y span (linear axes), centred on the data, so that round-off noise in a
  /// quantity that should be constant draws as a flat line rather than as wild swings.
  double min_y_span = 0.0;
  /// Fixed y range, e.g. the range before a run blew up (on a log axis both ends positive,
  /// else ignored): curves beyond it are cut at the plot's edge, and each place a curve leaves
  /// the range is marked by a small triangle in its colour on that edge (pointing up at the
  /// top, down at the bottom). Unset: fitted to the data.
  std::optional<std::pair<double, double>> y_range;
  /// Opacity of a white background behind the whole plot (0: none).
  double background_alpha = 0.0;
  /// Pixels left of the plot area, at least: stacked plots share the largest, so their
  /// time axes line up (see plot_left_margin).
  double left_margin = 0.0;
  /// Text size, pixels; 0: from the plot's height (plot_font). Plots stacked in a panel share
  /// one.
  double font = 0.0;
  /// Whether the x axis has its tick labels and label. False: a plot stacked above another
  /// that shares its x axis (a panel's time axis), which names it once at the bottom.
  bool x_axis_text = true;
};

}  // namespace bookspin::overlay
