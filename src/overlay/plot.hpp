#pragma once
// Line plots drawn with cairo: the accuracy plot (log-log), static diagnostics plots and,
// later, the live panel in clips.
#include <optional>
#include <string>
#include <vector>

#include <cairo.h>

#include "common/rgba_image.hpp"

namespace bookspin::overlay {

struct Series {
  std::string label;
  std::vector<double> x, y;  ///< same length; non-finite or (on a log axis) non-positive
                             ///< points break the line
  double r = 0, g = 0, b = 0;
  bool dashed = false;
};

struct PlotSpec {
  std::string title;
  std::string x_label;  ///< with units, e.g. "time step dt (time units)"
  std::string y_label;
  bool log_x = false;
  bool log_y = false;
  std::vector<Series> series;
  std::optional<double> cursor_x;  ///< a vertical time cursor
  bool legend = true;
};

/// Draws `spec` into the rectangle (x, y, width, height) of `cr` (pixels).
void draw_plot(cairo_t* cr, double x, double y, double width, double height, const PlotSpec& spec);

/// Draws `spec` on a white width×height image.
RgbaImage plot_image(const PlotSpec& spec, int width, int height);

/// A qualitative colour palette (Okabe–Ito, colour-blind safe), cycled by index.
void palette_colour(int index, double& r, double& g, double& b);

}  // namespace bookspin::overlay
