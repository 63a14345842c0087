#include "overlay/plot.hpp"

#include <algorithm>
#include <cstddef>
#include <iterator>
#include <utility>
#include <vector>

#include "common/colour.hpp"
#include "overlay/cairo_canvas.hpp"
#include "overlay/caption.hpp"
#include "overlay/plot_area.hpp"
#include "typeface/text_layout.hpp"

namespace bookspin::overlay {

namespace {

/// Draws each of `plots` into its rectangle of `rects` (pixels). Every label of every plot is
/// laid out once, first, in one call, as values: the plots measure, place and draw them from
/// those. Where `aligned`, their left margins are first set to the largest any of them needs.
void draw_plots(cairo_t* cr, std::vector<PlotSpec> plots, const std::vector<PixelRect>& rects,
                bool aligned) {
  const std::size_t n = std::min(plots.size(), rects.size());
  std::vector<double> fonts;
  std::vector<Axis> xs, ys;
  std::vector<typeface::TextRequest> requests;
  std::vector<std::size_t> firsts;
  for (std::size_t i = 0; i < n; ++i) {
    fonts.push_back(plot_font(rects[i].height, plots[i]));
    xs.push_back(fit_x(plots[i]));
    ys.push_back(fit_y(plots[i]));
    firsts.push_back(requests.size());
    std::vector<typeface::TextRequest> own =
        plot_label_requests(plots[i], xs[i], ys[i], fonts[i], rects[i].width);
    requests.insert(requests.end(), std::make_move_iterator(own.begin()),
                    std::make_move_iterator(own.end()));
  }
  firsts.push_back(requests.size());
  std::vector<typeface::LaidOutText> laid = typeface::lay_out_texts(cr, requests);
  std::vector<PlotLabels> labels;
  for (std::size_t i = 0; i < n; ++i) {
    const auto from = laid.begin() + static_cast<std::ptrdiff_t>(firsts[i]),
               to = laid.begin() + static_cast<std::ptrdiff_t>(firsts[i + 1]);
    labels.push_back(plot_labels(plots[i], xs[i], ys[i],
                                 {std::make_move_iterator(from), std::make_move_iterator(to)}));
  }
  if (aligned) {
    double left = 0;
    for (std::size_t i = 0; i < n; ++i)
      left =
          std::max(left, plot_labels_left_margin(plots[i], labels[i], rects[i].height, fonts[i]));
    for (std::size_t i = 0; i < n; ++i) plots[i].left_margin = left;
  }
  for (std::size_t i = 0; i < n; ++i) {
    const PlotSpec& spec = plots[i];
    const PixelRect& r = rects[i];
    cairo_save(cr);
    if (spec.background_alpha > 0) {
      cairo_rectangle(cr, r.x, r.y, r.width, r.height);
      cairo_set_source_rgba(cr, 1, 1, 1, spec.background_alpha);
      cairo_fill(cr);
    }
    const Area area = plot_area(spec, labels[i], r.x, r.y, r.width, r.height, fonts[i]);
    const Axis ay = drawn_y(ys[i], area);
    const PlotTextPlaces places =
        place_plot_texts(spec, labels[i], xs[i], ay, area, r.x, r.y, r.width, r.height);
    draw_grid_lines(cr, xs[i], ay, area);
    for (const auto& text : places.ticks) draw_placed_text(cr, text);
    draw_data(cr, spec, xs[i], ay, area);
    for (const auto& text : places.labels) draw_placed_text(cr, text);
    draw_legend_marks(cr, spec, labels[i], area, r.y);
    for (const auto& text : places.legend) draw_placed_text(cr, text);
    cairo_restore(cr);
  }
}

/// The labels of `spec` drawn `width` pixels wide, laid out at text `font` pixels high.
PlotLabels laid_out_labels(cairo_t* cr, const PlotSpec& spec, double font, double width) {
  const Axis ax = fit_x(spec), ay = fit_y(spec);
  return plot_labels(spec, ax, ay,
                     typeface::lay_out_texts(cr, plot_label_requests(spec, ax, ay, font, width)));
}

}  // namespace

void palette_colour(int index, double& r, double& g, double& b) {
  const Rgb c = bookspin::palette_colour(static_cast<std::size_t>(index));
  r = c.r, g = c.g, b = c.b;
}

double plot_font(double height, const PlotSpec& spec) {
  return spec.font > 0 ? spec.font : std::clamp(height / 22.0, kMinFont, 18.0);
}

double plot_frame_height(cairo_t* cr, double width, const PlotSpec& spec, double font) {
  const Area a = plot_area(spec, laid_out_labels(cr, spec, font, width), 0, 0, width, 0, font);
  return a.y0 - a.y1;  // drawn 0 pixels tall: the top's rows above the bottom's
}

double plot_left_margin(cairo_t* cr, double height, const PlotSpec& spec) {
  const double font = plot_font(height, spec);
  return plot_labels_left_margin(spec, laid_out_labels(cr, spec, font, 0), height, font);
}

void align_left_margins(cairo_t* cr, double height, std::vector<PlotSpec>& plots) {
  double left = 0;
  for (const auto& p : plots) left = std::max(left, plot_left_margin(cr, height, p));
  for (auto& p : plots) p.left_margin = left;
}

void draw_plot(cairo_t* cr, double x, double y, double width, double height, const PlotSpec& spec) {
  draw_plots(cr, {spec}, {PixelRect{x, y, width, height}}, false);
}

void draw_aligned_plots(cairo_t* cr, std::vector<PlotSpec> plots,
                        const std::vector<PixelRect>& rects) {
  draw_plots(cr, std::move(plots), rects, true);
}

RgbaImage plot_image(const PlotSpec& spec, int width, int height) {
  RgbaImage image(width, height);
  std::fill(image.pixels.begin(), image.pixels.end(), 255);
  CairoCanvas canvas(width, height);
  draw_plot(canvas.cr(), 0, 0, width, height, spec);
  canvas.composite_onto(image);
  return image;
}

}  // namespace bookspin::overlay
