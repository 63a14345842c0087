#pragma once
// A line plot's lines drawn with cairo (plot.hpp draws a plot through them): the grid at the
// ticks and the area's frame, each series' curve (thinned to quarter-pixel columns) or dots and
// its marks, where a curve leaves a fixed y range, and a legend entry's sample.
#include <cairo.h>

#include "overlay/plot_axes.hpp"
#include "overlay/plot_spec.hpp"

namespace bookspin::overlay {

/// The grid lines at the ticks and the plot area's frame.
void draw_grid_lines(cairo_t* cr, const Axis& ax, const Axis& ay, const Area& area);

/// Curves and cursor, clipped to the plot area, and where a curve leaves a fixed y range.
void draw_data(cairo_t* cr, const PlotSpec& spec, const Axis& ax, const Axis& ay, const Area& area);

/// A legend entry's sample of series `s` (its line, dashes, dots or mark) left of (x, y), the
/// baseline of its words, with text `font` pixels high.
void legend_sample(cairo_t* cr, const Series& s, double x, double y, double font);

}  // namespace bookspin::overlay
