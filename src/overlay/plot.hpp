#pragma once
// Line plots drawn with cairo: the accuracy plot (log-log), the static diagnostics plots
// (`bookspin plot`) and the live panel composited over clips.
#include <cairo.h>

#include <vector>

#include "common/pixel_rect.hpp"
#include "common/rgba_image.hpp"
#include "overlay/plot_spec.hpp"

namespace bookspin::overlay {

/// The text size (pixels) of `spec` drawn `height` pixels tall: spec.font where set, else
/// height/22 within kMinFont (caption.hpp) … 18.
double plot_font(double height, const PlotSpec& spec);

/// Draws `spec` into the rectangle (x, y, width, height) of `cr` (pixels), its text
/// plot_font(height, spec) pixels high.
void draw_plot(cairo_t* cr, double x, double y, double width, double height, const PlotSpec& spec);

/// The pixels of a plot `width` wide with text `font` pixels high that are not its plot
/// area: the title and legend rows above it, the x axis's text below it.
double plot_frame_height(cairo_t* cr, double width, const PlotSpec& spec, double font);

/// The pixels left of the plot area that draw_plot needs for `spec` drawn `height` pixels
/// tall (the rotated y label and the widest y tick label).
double plot_left_margin(cairo_t* cr, double height, const PlotSpec& spec);

/// Sets every plot's left_margin to the largest any of them needs at `height` pixels tall.
void align_left_margins(cairo_t* cr, double height, std::vector<PlotSpec>& plots);

/// Draws each of `plots` into its rectangle of `rects` (pixels), their left margins first set to
/// the largest any of them needs at its rectangle's height (align_left_margins, where the
/// rectangles are as tall): a sheet's plots.
void draw_aligned_plots(cairo_t* cr, std::vector<PlotSpec> plots,
                        const std::vector<PixelRect>& rects);

/// Draws `spec` on a white width×height image: a chart.
RgbaImage plot_image(const PlotSpec& spec, int width, int height);

/// bookspin::palette_colour (common/colour.hpp) as the three channels a Series holds.
void palette_colour(int index, double& r, double& g, double& b);

}  // namespace bookspin::overlay
