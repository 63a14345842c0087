#pragma once
// Line plots drawn with cairo: the accuracy plot (log-log), the static diagnostics plots
// (`bookspin plot`) and the live panel composited over clips.
#include <cairo.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "common/rgba_image.hpp"

namespace bookspin::overlay {

struct Series {
  std::string label;
  std::vector<double> x, y;  ///< same length; non-finite or (on a log axis) non-positive
                             ///< points break the line
  double r = 0, g = 0, b = 0;
  bool dashed = false;
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
  /// Opacity of a white background behind the whole plot (0: none).
  double background_alpha = 0.0;
  /// Pixels left of the plot area, at least: stacked plots share the largest, so their
  /// time axes line up (see plot_left_margin).
  double left_margin = 0.0;
};

/// Draws `spec` into the rectangle (x, y, width, height) of `cr` (pixels). Text scales with
/// the height (height/22, 9 … 18 px).
void draw_plot(cairo_t* cr, double x, double y, double width, double height, const PlotSpec& spec);

/// The axis ranges draw_plot fits to `spec` (lo, hi; on a log axis their log10): with the
/// spec's texts, what a plot's frame (grid, tick labels) depends on.
struct PlotRanges {
  double x_lo = 0, x_hi = 1, y_lo = 0, y_hi = 1;
  bool x_log = false, y_log = false;
  bool operator==(const PlotRanges& o) const {
    return x_lo == o.x_lo && x_hi == o.x_hi && y_lo == o.y_lo && y_hi == o.y_hi &&
           x_log == o.x_log && y_log == o.y_log;
  }
  bool operator!=(const PlotRanges& o) const { return !(*this == o); }
};
PlotRanges plot_ranges(const PlotSpec& spec);

/// The plot area of a plot drawn by draw_plot_frame, pixels, and its font size.
struct PlotArea {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;  ///< left, right, top, bottom
  double font = 0;
};

/// draw_plot in two parts, for a plot drawn again on every frame of a clip with new data and
/// the same frame: draw_plot_frame draws everything but the curves and the cursor (the
/// background, grid, tick labels, axis labels, title and legend) and returns the plot area;
/// draw_plot_data draws only the curves and the cursor, clipped to that area. The data are
/// clipped to the plot area and nothing else draw_plot draws after them reaches into it,
/// so draw_plot_frame then draw_plot_data (with the same plot_ranges) give draw_plot's
/// pixels, also with other plots' frames drawn in between.
PlotArea draw_plot_frame(cairo_t* cr, double x, double y, double width, double height,
                         const PlotSpec& spec);
void draw_plot_data(cairo_t* cr, const PlotArea& area, const PlotSpec& spec);

/// The pixels left of the plot area that draw_plot needs for `spec` drawn `height` pixels
/// tall (the rotated y label and the widest y tick label).
double plot_left_margin(cairo_t* cr, double height, const PlotSpec& spec);

/// Sets every plot's left_margin to the largest any of them needs at `height` pixels tall.
void align_left_margins(cairo_t* cr, double height, std::vector<PlotSpec>& plots);

/// Draws `spec` on a white width×height image.
RgbaImage plot_image(const PlotSpec& spec, int width, int height);

/// bookspin::palette_colour (common/colour.hpp) as the three channels a Series holds.
void palette_colour(int index, double& r, double& g, double& b);

}  // namespace bookspin::overlay
