#pragma once
// A line plot's labels and layout (plot.hpp draws a plot through it): its labels as the text
// layout laid them out (values: no text is measured here), the margins they need, the plot area,
// where each label goes, and the legend's box and samples. Its axes and ticks are
// plot_axes.hpp's; its grid and curves drawn with cairo plot_lines.hpp's.
#include <cairo.h>

#include <string>
#include <vector>

#include "overlay/plot_axes.hpp"
#include "overlay/plot_lines.hpp"
#include "overlay/plot_spec.hpp"
#include "typeface/face.hpp"
#include "typeface/laid_out_text.hpp"

namespace bookspin::overlay {

/// A plot's labels laid out, each once: the title (bold; none where spec.title is empty) as
/// measured and as drawn (made smaller where wider than the plot), the x label, the y label
/// flat (as measured) and turned a quarter left (as drawn), on one line and as its quantity and
/// unit ("ω", "(rad / time unit)"; none where it has no unit), the legend's entries (one a
/// series), the tick labels of the axes as fitted, and every other y tick label the plot's area
/// may ask for (its ticks follow its height: plot_label_requests()).
struct PlotLabels {
  std::vector<typeface::LaidOutText> title, title_drawn;  ///< one each, or none
  typeface::LaidOutText x_label, y_label, y_label_turned;
  std::vector<typeface::LaidOutText> y_label_parts;  ///< turned; two, or none
  std::vector<typeface::LaidOutText> legend;
  std::vector<typeface::LaidOutText> x_ticks, y_ticks;  ///< ticks(ax), ticks(ay) in order
  std::vector<typeface::LaidOutText> other_y_ticks;
};

/// The texts of a plot drawn `width` pixels wide with text `font` pixels high, axes `ax` and
/// `ay` as fitted, to lay out in one call: their order is the one plot_labels() reads them in.
/// The y ticks drawn follow the plot area's height (2 … 5 intervals, more where that gives
/// fewer than two ticks): the labels of every step any of those can take are among them.
std::vector<typeface::TextRequest> plot_label_requests(const PlotSpec& spec, const Axis& ax,
                                                       const Axis& ay, double font, double width);

/// The laid-out texts of plot_label_requests(spec, ax, ay, …), in its order, as PlotLabels.
PlotLabels plot_labels(const PlotSpec& spec, const Axis& ax, const Axis& ay,
                       std::vector<typeface::LaidOutText> laid);

/// The pixels left of the plot area that `spec` needs drawn `height` pixels tall with text
/// `font` pixels high (the rotated y label and the widest y tick label), at least
/// spec.left_margin.
double plot_labels_left_margin(const PlotSpec& spec, const PlotLabels& labels, double height,
                               double font);

/// The plot area of `spec` drawn in the rectangle (x, y, width, height) with its labels.
Area plot_area(const PlotSpec& spec, const PlotLabels& labels, double x, double y, double width,
               double height, double font);

/// Where a plot's texts go: the tick labels (drawn after the grid, under the curves), the
/// axis labels and title (after the curves), the legend's entries (after its box and samples).
struct PlotTextPlaces {
  std::vector<typeface::PlacedText> ticks, labels, legend;
};

/// Every text of the plot drawn in the rectangle (x, y, width, height) placed; the places
/// point into `labels`, which must outlive them. A y tick whose label is not among them is an
/// internal error.
PlotTextPlaces place_plot_texts(const PlotSpec& spec, const PlotLabels& labels, const Axis& ax,
                                const Axis& ay_drawn, const Area& area, double x, double y,
                                double width, double height);

/// The legend's box (placed right) and each series' sample, where place_plot_texts() puts
/// their words.
void draw_legend_marks(cairo_t* cr, const PlotSpec& spec, const PlotLabels& labels,
                       const Area& area, double y);

}  // namespace bookspin::overlay
