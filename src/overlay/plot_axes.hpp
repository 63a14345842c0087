#pragma once
// A line plot's axes (plot_area.hpp lays a plot out on them): each axis's range fitted to the
// data or fixed, its ticks and their labels, and the plot area in pixels.
#include <string>
#include <vector>

#include "overlay/plot_spec.hpp"

namespace bookspin::overlay {

/// An axis: its range (log10 of it on a log axis) and about how many tick intervals span it
/// (linear axes).
struct Axis {
  double lo = 0, hi = 1;
  bool log = false;
  double intervals = 5;
  /// value → pixel in [a, b]
  double map(double v, double a, double b) const;
};

/// The x axis of `spec`: its fixed range, else fitted to the data.
Axis fit_x(const PlotSpec& spec);

/// The y axis of `spec`: its fixed range, else fitted to the data (at least spec.min_y_span).
Axis fit_y(const PlotSpec& spec);

/// The plot area inside a plot's rectangle, in pixels.
struct Area {
  double x0, x1, y0, y1;  ///< left, right, top, bottom
  double font;
};

/// Whether `v` can be drawn on an axis: finite, and positive on a log axis.
bool usable(double v, bool log);

/// Whether spec.y_range fixes the y axis: a range from low to high, both positive on a log axis.
bool fixed_y_range(const PlotSpec& spec);

/// The ticks of axis `a` (values, not log10): a log axis's powers of ten, a linear axis's steps
/// of 1, 2 or 5 × 10^e, about a.intervals of them and at least two.
std::vector<double> ticks(const Axis& a);

/// A tick's label: "%g", or "1eN" on a log axis.
std::string tick_label(double v, bool log);

/// The labels of every tick a y axis `a` can have drawn (its ticks follow the plot area's
/// height) but those of `fitted` (its ticks as fitted), each once.
std::vector<std::string> other_y_tick_labels(const Axis& a, const std::vector<std::string>& fitted);

/// The y axis as drawn in `area`: ticks at least 2.4 text heights apart (2 … 5 intervals).
Axis drawn_y(Axis ay, const Area& area);

}  // namespace bookspin::overlay
