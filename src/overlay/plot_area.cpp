#include "overlay/plot_area.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "common/errors.hpp"
#include "overlay/plot_axes.hpp"
#include "overlay/plot_lines.hpp"

namespace bookspin::overlay {

namespace {

/// A text's origin placed as plot.cpp has always placed it: `align_x` of its advance left of
/// x, `align_y` of its ink height below y.
typeface::PlacedText text_at(const typeface::LaidOutText& text, double x, double y, double align_x,
                             double align_y, double grey) {
  typeface::PlacedText placed;
  placed.text = &text;
  placed.origin_x = x - align_x * text.extents.x_advance;
  placed.origin_y = y + align_y * text.extents.height;
  placed.r = placed.g = placed.b = grey;
  return placed;
}

double legend_box_width(const PlotLabels& labels, double font) {
  double width = 0;
  for (const auto& e : labels.legend) width = std::max(width, e.extents.x_advance);
  return width + 3.2 * font;
}

/// Lays the legend entries out in rows across [left, right]; calls `at(i, x, y)` for entry i
/// (baseline y, rows 1.3·font apart from `top`) and returns the height used.
template <typename At>
double flow_legend(const PlotLabels& labels, double left, double right, double top, double font,
                   At at) {
  const double row = 1.3 * font;
  double x = left, y = top + font;
  for (std::size_t i = 0; i < labels.legend.size(); ++i) {
    const double w = 2.3 * font + labels.legend[i].extents.x_advance;
    if (x > left && x + w > right) x = left, y += row;
    at(i, x, y);
    x += w + 1.2 * font;
  }
  return y - top + 0.45 * font;
}

/// Legend rows above the plot area, so a narrow plot keeps its full width.
double top_legend_height(const PlotSpec& spec, const PlotLabels& labels, double left, double right,
                         double font) {
  if (!spec.legend || spec.series.empty() || spec.legend_placement != LegendPlacement::top)
    return 0;
  return flow_legend(labels, left, right, 0, font, [](std::size_t, double, double) {});
}

/// Width of the widest y tick label, pixels.
double y_tick_width(const PlotLabels& labels) {
  double widest = 0;
  for (const auto& e : labels.y_ticks) widest = std::max(widest, e.extents.x_advance);
  return widest;
}

/// The rotated y label as drawn in a plot `height` pixels tall: one line, or where that is
/// longer than the plot is tall, the quantity and its unit ("ω (rad / time unit)": "ω" and
/// "(rad / time unit)") on two.
std::vector<const typeface::LaidOutText*> y_label_lines(const PlotLabels& labels, double height,
                                                        double font) {
  if (labels.y_label.extents.x_advance <= height - font || labels.y_label_parts.size() != 2)
    return {&labels.y_label_turned};
  return {&labels.y_label_parts[0], &labels.y_label_parts[1]};
}

/// Pixels below the plot area: the x tick labels and the x label, or room for the lowest y
/// tick label's lower half where the axis has no text.
double bottom_margin(const PlotSpec& spec, double font) {
  return (spec.x_axis_text ? 3.2 : 0.6) * font;
}

}  // namespace

std::vector<typeface::TextRequest> plot_label_requests(const PlotSpec& spec, const Axis& ax,
                                                       const Axis& ay, double font, double width) {
  using typeface::Face;
  std::vector<typeface::TextRequest> requests;
  const auto add = [&](const std::string& text, Face face, double angle) {
    requests.push_back({text, face, font, angle, 0});
  };
  if (!spec.title.empty()) {
    add(spec.title, Face::sans_bold, 0);
    // Where the plot is narrower than the title, smaller.
    requests.push_back({spec.title, Face::sans_bold, font, 0, width - font});
  }
  add(spec.x_label, Face::sans, 0);
  add(spec.y_label, Face::sans, 0);
  add(spec.y_label, Face::sans, -M_PI / 2);
  const std::size_t unit = spec.y_label.rfind(" (");
  if (unit != std::string::npos && unit != 0) {
    add(spec.y_label.substr(0, unit), Face::sans, -M_PI / 2);
    add(spec.y_label.substr(unit + 1), Face::sans, -M_PI / 2);
  }
  for (const auto& s : spec.series) add(s.label, Face::sans, 0);
  for (double t : ticks(ax)) add(tick_label(t, ax.log), Face::sans, 0);
  std::vector<std::string> y_labels;
  for (double t : ticks(ay)) y_labels.push_back(tick_label(t, ay.log));
  for (const std::string& label : y_labels) add(label, Face::sans, 0);
  for (const std::string& label : other_y_tick_labels(ay, y_labels)) add(label, Face::sans, 0);
  return requests;
}

PlotLabels plot_labels(const PlotSpec& spec, const Axis& ax, const Axis& ay,
                       std::vector<typeface::LaidOutText> laid) {
  PlotLabels labels;
  std::size_t next = 0;
  const auto take = [&]() {
    if (next >= laid.size())
      throw InternalError("the plot's labels: fewer laid out than asked for");
    return std::move(laid[next++]);
  };
  if (!spec.title.empty()) {
    labels.title.push_back(take());
    labels.title_drawn.push_back(take());
  }
  labels.x_label = take();
  labels.y_label = take();
  labels.y_label_turned = take();
  const std::size_t unit = spec.y_label.rfind(" (");
  if (unit != std::string::npos && unit != 0) {
    labels.y_label_parts.push_back(take());
    labels.y_label_parts.push_back(take());
  }
  for (std::size_t i = 0; i < spec.series.size(); ++i) labels.legend.push_back(take());
  for (std::size_t i = 0; i < ticks(ax).size(); ++i) labels.x_ticks.push_back(take());
  for (std::size_t i = 0; i < ticks(ay).size(); ++i) labels.y_ticks.push_back(take());
  while (next < laid.size()) labels.other_y_ticks.push_back(take());
  return labels;
}

double plot_labels_left_margin(const PlotSpec& spec, const PlotLabels& labels, double height,
                               double font) {
  const double label = 1.2 * font * static_cast<double>(y_label_lines(labels, height, font).size());
  return std::max(
      {4.0 * font + label, 1.2 * font + label + y_tick_width(labels), spec.left_margin});
}

Area plot_area(const PlotSpec& spec, const PlotLabels& labels, double x, double y, double width,
               double height, double font) {
  const bool right = spec.legend && spec.legend_placement == LegendPlacement::right;
  const double legend_width = right ? legend_box_width(labels, font) + 0.8 * font : 0.0;
  Area a{x + plot_labels_left_margin(spec, labels, height, font),
         x + width - 1.4 * font - legend_width, 0, y + height - bottom_margin(spec, font), font};
  a.y0 = y + (spec.title.empty() ? 0.8 : 2.0) * font +
         top_legend_height(spec, labels, a.x0, a.x1, font);
  // Room above the area for the markers where a curve leaves a fixed range (mark_range_exits).
  if (fixed_y_range(spec)) a.y0 += 0.5 * font;
  return a;
}

PlotTextPlaces place_plot_texts(const PlotSpec& spec, const PlotLabels& labels, const Axis& ax,
                                const Axis& ay_drawn, const Area& a, double x, double y,
                                double width, double height) {
  PlotTextPlaces places;
  // Tick labels: under the x axis, left of the y axis.
  if (spec.x_axis_text) {
    const std::vector<double> tx = ticks(ax);
    for (std::size_t i = 0; i < tx.size() && i < labels.x_ticks.size(); ++i)
      places.ticks.push_back(
          text_at(labels.x_ticks[i], ax.map(tx[i], a.x0, a.x1), a.y1 + 1.25 * a.font, 0.5, 0, 0.2));
  }
  for (double t : ticks(ay_drawn)) {
    const std::string text = tick_label(t, ay_drawn.log);
    const typeface::LaidOutText* laid = nullptr;
    for (const auto* list : {&labels.y_ticks, &labels.other_y_ticks})
      for (const auto& e : *list)
        if (laid == nullptr && e.utf8 == text) laid = &e;
    if (laid == nullptr)
      throw InternalError("the plot's labels: the y tick " + text + " not laid out");
    places.ticks.push_back(
        text_at(*laid, a.x0 - 0.4 * a.font, ay_drawn.map(t, a.y1, a.y0), 1, 0.5, 0.2));
  }
  if (spec.x_axis_text) {
    // Centred under the plot area; where that runs past the plot's sides (a plot two a row),
    // under the middle of the plot's rectangle.
    double centre = 0.5 * (a.x0 + a.x1);
    if (labels.x_label.extents.x_advance > 2.0 * std::min(centre - x, x + width - centre) - a.font)
      centre = x + 0.5 * width;
    places.labels.push_back(text_at(labels.x_label, centre, a.y1 + 2.6 * a.font, 0.5, 0, 0.1));
  }
  const auto y_lines = y_label_lines(labels, height, a.font);
  for (std::size_t i = 0; i < y_lines.size(); ++i) {
    typeface::PlacedText turned = text_at(*y_lines[i], 0, 0, 0.5, 0, 0.1);
    turned.x = x + (1.3 + 1.2 * static_cast<double>(i)) * a.font;
    turned.y = 0.5 * (a.y0 + a.y1);
    turned.angle = -M_PI / 2;
    places.labels.push_back(turned);
  }
  if (!labels.title.empty()) {
    // Centred over the plot area; where that runs past the plot's sides, over the plot, and
    // where the plot is narrower than the title, smaller (plot_label_requests()).
    double centre = 0.5 * (a.x0 + a.x1);
    if (labels.title[0].extents.x_advance > 2.0 * std::min(centre - x, x + width - centre) - a.font)
      centre = x + 0.5 * width;
    places.labels.push_back(text_at(labels.title_drawn[0], centre, y + 1.3 * a.font, 0.5, 0, 0.1));
  }
  if (!spec.legend || spec.series.empty()) return places;
  if (spec.legend_placement == LegendPlacement::right) {
    const double row = 1.3 * a.font, left = a.x1 + 0.8 * a.font;
    double yy = a.y0 + 0.4 * a.font + row;
    for (const auto& e : labels.legend) {
      places.legend.push_back(text_at(e, left + 2.7 * a.font, yy, 0, 0, 0.1));
      yy += row;
    }
  } else {
    const double top = y + (spec.title.empty() ? 0.8 : 2.0) * a.font;
    flow_legend(labels, a.x0, a.x1, top, a.font, [&](std::size_t i, double xx, double yy) {
      places.legend.push_back(text_at(labels.legend[i], xx + 2.3 * a.font, yy, 0, 0, 0.1));
    });
  }
  return places;
}

void draw_legend_marks(cairo_t* cr, const PlotSpec& spec, const PlotLabels& labels, const Area& a,
                       double y) {
  if (!spec.legend || spec.series.empty()) return;
  const double font = a.font;
  if (spec.legend_placement == LegendPlacement::right) {
    // Right of the plot area, so it never hides data.
    const double row = 1.3 * font, box_w = legend_box_width(labels, font), left = a.x1 + 0.8 * font;
    cairo_rectangle(cr, left, a.y0 + 0.4 * font, box_w, row * spec.series.size() + 0.5 * font);
    cairo_set_source_rgba(cr, 1, 1, 1, 0.85);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
    cairo_set_line_width(cr, 1);
    cairo_stroke(cr);
    double yy = a.y0 + 0.4 * font + row;
    for (const auto& s : spec.series) {
      legend_sample(cr, s, left + 0.4 * font, yy, font);
      yy += row;
    }
    return;
  }
  const double top = y + (spec.title.empty() ? 0.8 : 2.0) * font;
  flow_legend(labels, a.x0, a.x1, top, font, [&](std::size_t i, double x, double yy) {
    legend_sample(cr, spec.series[i], x, yy, font);
  });
}

}  // namespace bookspin::overlay
