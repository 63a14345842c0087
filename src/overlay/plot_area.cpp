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

namespace bookspin::overlay {

double Axis::map(double v, double a, double b) const {
  const double f = log ? (std::log10(v) - lo) / (hi - lo) : (v - lo) / (hi - lo);
  return a + f * (b - a);
}

namespace {

bool usable(double v, bool log) { return std::isfinite(v) && (!log || v > 0.0); }

/// The data range of the x or y values; a span below `min_span` (linear axes) is widened
/// around its middle, a degenerate one to ±0.5.
Axis fit_axis(const std::vector<Series>& series, bool use_x, bool log, double min_span = 0.0) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& s : series) {
    for (double v : use_x ? s.x : s.y) {
      if (!usable(v, log)) continue;
      lo = std::min(lo, log ? std::log10(v) : v);
      hi = std::max(hi, log ? std::log10(v) : v);
    }
  }
  if (!std::isfinite(lo)) lo = 0, hi = 1;
  if (!log && hi - lo < min_span) {
    const double mid = 0.5 * (lo + hi);
    lo = mid - 0.5 * min_span, hi = mid + 0.5 * min_span;
    return {lo, hi, false};
  }
  // A (nearly) constant series: widen it by ±0.5, or by a millionth of its size where ±0.5
  // would be lost in rounding (values of 10¹⁶ and more).
  const double size = std::max(std::abs(lo), std::abs(hi));
  if (hi - lo < 1e-12 * std::max(1.0, size)) {
    const double half = std::max(0.5, 1e-6 * size);
    lo -= half, hi += half;
  }
  if (log) {
    lo = std::floor(lo), hi = std::ceil(hi);
  } else if (!use_x) {
    const double pad = 0.06 * (hi - lo);
    lo -= pad, hi += pad;
  }
  return {lo, hi, log};
}

/// Whether spec.y_range fixes the y axis: a range from low to high, both positive on a log axis.
bool fixed_y_range(const PlotSpec& spec) {
  return spec.y_range && spec.y_range->second > spec.y_range->first &&
         (!spec.log_y || spec.y_range->first > 0.0);
}

}  // namespace

Axis fit_x(const PlotSpec& spec) {
  if (spec.x_range && !spec.log_x && spec.x_range->second > spec.x_range->first) {
    return {spec.x_range->first, spec.x_range->second, false};
  }
  return fit_axis(spec.series, true, spec.log_x);
}

Axis fit_y(const PlotSpec& spec) {
  if (fixed_y_range(spec)) {
    const auto [lo, hi] = *spec.y_range;
    return spec.log_y ? Axis{std::log10(lo), std::log10(hi), true} : Axis{lo, hi, false};
  }
  return fit_axis(spec.series, false, spec.log_y, spec.min_y_span);
}

namespace {

double nice_step(double span, double intervals) {
  const double raw = span / intervals, magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * magnitude >= raw) return m * magnitude;
  return 10.0 * magnitude;
}

/// The ticks of a linear axis `step` apart within it.
std::vector<double> linear_ticks(const Axis& a, double step) {
  std::vector<double> out;
  if (!(step > 0.0) || !std::isfinite(step)) return out;
  // Counted, not summed: the k-th tick is k × step, and at most kMaxTicks of them, so that
  // a step lost in rounding next to huge values cannot loop forever.
  constexpr int kMaxTicks = 50;
  const double first = std::ceil(a.lo / step - 1e-9);  // an end on a tick keeps it
  for (int i = 0; i < kMaxTicks; ++i) {
    const double v = (first + i) * step;
    if (!(v <= a.hi + 1e-9 * step) || (!out.empty() && !(v > out.back()))) break;
    out.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
  }
  return out;
}

std::vector<double> ticks(const Axis& a) {
  std::vector<double> out;
  if (a.log) {
    const int stride = std::max(1, static_cast<int>((a.hi - a.lo) / 8.0) + 1);
    for (int e = static_cast<int>(a.lo); e <= static_cast<int>(a.hi); e += stride)
      out.push_back(std::pow(10.0, e));
    return out;
  }
  // At least two ticks, so that the axis has a scale: a short axis of few intervals may
  // round its step up past the span's half (±2.4 in two intervals: a step of 5).
  for (double intervals = a.intervals;; intervals += 1.0) {
    out = linear_ticks(a, nice_step(a.hi - a.lo, intervals));
    if (out.size() >= 2 || intervals >= 10.0) return out;
  }
}

std::string tick_label(double v, bool log) {
  char text[32];
  if (log) {
    std::snprintf(text, sizeof text, "1e%d", static_cast<int>(std::lround(std::log10(v))));
  } else {
    std::snprintf(text, sizeof text, "%g", v);
  }
  return text;
}

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

/// A polyline in pixels; a NaN point lifts the pen.
using Polyline = std::vector<std::pair<double, double>>;

/// Collects pixel points, thinning runs that fall in one quarter-pixel column to their
/// first, lowest, highest and last points (in their original order). That draws the same
/// line (every vertical extent and every connection between columns is kept; within a
/// quarter pixel a steep stretch's chord is as good as the curve, while whole-pixel columns
/// shift steep edges visibly), at a cost bounded by the plot's width rather than by the
/// number of points: a panel drawn every frame of a long clip would otherwise cost time
/// proportional to the frame index.
class ColumnThinner {
 public:
  explicit ColumnThinner(Polyline& out) : out_(out) {}
  void add(std::size_t index, double px, double py) {
    const double column = std::floor(4.0 * px);  // quarter-pixel columns
    if (count_ > 0 && column != column_) flush();
    if (count_ == 0) column_ = column, first_ = last_ = low_ = high_ = {index, px, py};
    last_ = {index, px, py};
    if (py < low_.py) low_ = last_;
    if (py > high_.py) high_ = last_;
    ++count_;
  }
  void pen_up() {
    flush();
    out_.emplace_back(std::nan(""), std::nan(""));
  }
  void flush() {
    if (count_ == 0) return;
    Point kept[] = {first_, low_, high_, last_};
    std::sort(std::begin(kept), std::end(kept),
              [](const Point& a, const Point& b) { return a.index < b.index; });
    for (std::size_t i = 0; i < std::size(kept); ++i) {
      if (i > 0 && kept[i].index == kept[i - 1].index) continue;
      out_.emplace_back(kept[i].px, kept[i].py);
    }
    count_ = 0;
  }

 private:
  struct Point {
    std::size_t index;
    double px, py;
  };
  Polyline& out_;
  std::size_t count_ = 0;
  double column_ = 0;
  Point first_{}, last_{}, low_{}, high_{};
};

/// The series' usable points mapped to pixels, thinned per quarter-pixel column where x never
/// decreases (a time series); other data are kept point for point.
Polyline series_polyline(const Series& s, const Axis& ax, const Axis& ay, double x0, double x1,
                         double y0, double y1) {
  const std::size_t n = std::min(s.x.size(), s.y.size());
  const bool sorted = std::is_sorted(s.x.begin(), s.x.begin() + static_cast<std::ptrdiff_t>(n));
  Polyline points;
  ColumnThinner thinner(points);
  for (std::size_t i = 0; i < n; ++i) {
    if (!usable(s.x[i], ax.log) || !usable(s.y[i], ay.log)) {
      if (sorted)
        thinner.pen_up();
      else
        points.emplace_back(std::nan(""), std::nan(""));
      continue;
    }
    const double px = ax.map(s.x[i], x0, x1), py = ay.map(s.y[i], y1, y0);
    if (sorted)
      thinner.add(i, px, py);
    else
      points.emplace_back(px, py);
  }
  thinner.flush();
  return points;
}

/// A filled mark of `radius` pixels centred on (x, y).
void draw_marker(cairo_t* cr, Marker marker, double x, double y, double radius) {
  switch (marker) {
    case Marker::circle:
      cairo_arc(cr, x, y, radius, 0, 2 * M_PI);
      break;
    case Marker::square:
      cairo_rectangle(cr, x - 1.15 * radius, y - 1.15 * radius, 2.3 * radius, 2.3 * radius);
      break;
    case Marker::triangle:
      cairo_move_to(cr, x, y - 1.5 * radius);
      cairo_line_to(cr, x + 1.35 * radius, y + 0.9 * radius);
      cairo_line_to(cr, x - 1.35 * radius, y + 0.9 * radius);
      cairo_close_path(cr);
      break;
    case Marker::diamond:
      cairo_move_to(cr, x, y - 1.6 * radius);
      cairo_line_to(cr, x + 1.3 * radius, y);
      cairo_line_to(cr, x, y + 1.6 * radius);
      cairo_line_to(cr, x - 1.3 * radius, y);
      cairo_close_path(cr);
      break;
  }
  cairo_fill(cr);
}

void draw_series(cairo_t* cr, const Series& s, const Axis& ax, const Axis& ay, double x0, double x1,
                 double y0, double y1, double line_width) {
  cairo_set_source_rgb(cr, s.r, s.g, s.b);
  cairo_set_line_width(cr, line_width);
  // Round joins: a thinned column turns back on itself, and a mitred turn would spike.
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  const double dash[] = {4 * line_width, 2.5 * line_width};
  cairo_set_dash(cr, dash, s.dashed ? 2 : 0, 0);
  if (s.dots) {
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!usable(s.x[i], ax.log) || !usable(s.y[i], ay.log)) continue;
      const double px = ax.map(s.x[i], x0, x1), py = ay.map(s.y[i], y1, y0);
      if (px < x0 || px > x1 || py < y0 || py > y1) continue;
      cairo_new_sub_path(cr);
      cairo_arc(cr, px, py, 1.2 * line_width, 0, 2 * 3.14159265358979323846);
    }
    cairo_fill(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
    return;
  }
  bool pen_down = false;
  for (const auto& [px, py] : series_polyline(s, ax, ay, x0, x1, y0, y1)) {
    if (std::isnan(px)) {
      pen_down = false;
      continue;
    }
    pen_down ? cairo_line_to(cr, px, py) : cairo_move_to(cr, px, py);
    pen_down = true;
  }
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
  if (s.x.size() <= 16) {  // few points: mark them
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!usable(s.x[i], ax.log) || !usable(s.y[i], ay.log)) continue;
      draw_marker(cr, s.marker, ax.map(s.x[i], x0, x1), ay.map(s.y[i], y1, y0), 1.6 * line_width);
    }
  }
}

void legend_sample(cairo_t* cr, const Series& s, double x, double y, double font) {
  cairo_set_source_rgb(cr, s.r, s.g, s.b);
  if (s.dots) {  // as drawn: dots, no line
    for (int i = 0; i < 3; ++i) {
      cairo_new_sub_path(cr);
      cairo_arc(cr, x + (0.3 + 0.6 * i) * font, y - 0.35 * font, 0.14 * font, 0,
                2 * 3.14159265358979323846);
    }
    cairo_fill(cr);
    return;
  }
  cairo_set_line_width(cr, 0.18 * font);
  const double dash[] = {0.5 * font, 0.3 * font};
  cairo_set_dash(cr, dash, s.dashed ? 2 : 0, 0);
  cairo_move_to(cr, x, y - 0.35 * font);
  cairo_line_to(cr, x + 1.8 * font, y - 0.35 * font);
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
  if (s.marker != Marker::circle)
    draw_marker(cr, s.marker, x + 0.9 * font, y - 0.35 * font, 0.22 * font);
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

/// The labels of every tick a y axis can have drawn but those of `fitted` (its ticks as
/// fitted): ticks() steps by nice_step(span, n) for n from its intervals (2 … 5 as drawn) up to
/// 11 at most, so by each step m·10^e (m = 1, 2, 5, 10) from nice_step(span, 11) to
/// nice_step(span, 2), computed as nice_step computes it.
std::vector<std::string> other_y_tick_labels(const Axis& a,
                                             const std::vector<std::string>& fitted) {
  std::vector<std::string> out;
  const double span = a.hi - a.lo;
  if (a.log || !(span > 0) || !std::isfinite(span)) return out;
  const double least = nice_step(span, 11.0), most = nice_step(span, 2.0);
  const int e0 = static_cast<int>(std::floor(std::log10(span / 11.0))) - 1;
  const int e1 = static_cast<int>(std::floor(std::log10(span / 2.0))) + 1;
  for (int e = e0; e <= e1; ++e) {
    const double magnitude = std::pow(10.0, static_cast<double>(e));
    for (double m : {1.0, 2.0, 5.0, 10.0}) {
      const double step = m * magnitude;
      if (step < least || step > most) continue;
      for (double t : linear_ticks(a, step)) {
        const std::string label = tick_label(t, false);
        if (std::find(fitted.begin(), fitted.end(), label) == fitted.end() &&
            std::find(out.begin(), out.end(), label) == out.end())
          out.push_back(label);
      }
    }
  }
  return out;
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

Axis drawn_y(Axis ay, const Area& area) {
  ay.intervals = std::clamp((area.y1 - area.y0) / (2.4 * area.font), 2.0, 5.0);
  return ay;
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

void draw_grid_lines(cairo_t* cr, const Axis& ax, const Axis& ay, const Area& a) {
  cairo_set_line_width(cr, 1);
  for (double t : ticks(ax)) {
    const double px = ax.map(t, a.x0, a.x1);
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, px, a.y0), cairo_line_to(cr, px, a.y1), cairo_stroke(cr);
  }
  for (double t : ticks(ay)) {
    const double py = ay.map(t, a.y1, a.y0);
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, a.x0, py), cairo_line_to(cr, a.x1, py), cairo_stroke(cr);
  }
  cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
  cairo_rectangle(cr, a.x0, a.y0, a.x1 - a.x0, a.y1 - a.y0);
  cairo_stroke(cr);
}

namespace {

/// A triangle on the top or bottom edge of the plot area, in the series' colour, where the
/// series goes from inside a fixed y range to beyond it (PlotSpec::y_range).
void mark_range_exits(cairo_t* cr, const Series& s, const Axis& ax, const Axis& ay, const Area& a) {
  const double size = 0.45 * a.font;
  cairo_set_source_rgb(cr, s.r, s.g, s.b);
  bool inside = true;
  for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
    if (!usable(s.x[i], ax.log) || !usable(s.y[i], ay.log)) continue;
    const double y = ay.log ? std::log10(s.y[i]) : s.y[i];
    const bool above = y > ay.hi, below = y < ay.lo;
    if (inside && (above || below)) {
      const double px = std::clamp(ax.map(s.x[i], a.x0, a.x1), a.x0, a.x1);
      const double edge = above ? a.y0 : a.y1, tip = above ? edge - size : edge + size;
      cairo_move_to(cr, px - size, edge), cairo_line_to(cr, px + size, edge);
      cairo_line_to(cr, px, tip), cairo_close_path(cr);
      cairo_fill(cr);
    }
    inside = !above && !below;
  }
}

}  // namespace

void draw_data(cairo_t* cr, const PlotSpec& spec, const Axis& ax, const Axis& ay, const Area& a) {
  cairo_save(cr);
  cairo_rectangle(cr, a.x0, a.y0, a.x1 - a.x0, a.y1 - a.y0);
  cairo_clip(cr);
  for (const auto& s : spec.series) {
    draw_series(cr, s, ax, ay, a.x0, a.x1, a.y0, a.y1, std::max(1.5, a.font / 7));
  }
  if (spec.cursor_x) {
    cairo_set_source_rgba(cr, 0.8, 0.1, 0.1, 0.8);
    cairo_set_line_width(cr, 1.5);
    const double px = ax.map(*spec.cursor_x, a.x0, a.x1);
    cairo_move_to(cr, px, a.y0), cairo_line_to(cr, px, a.y1), cairo_stroke(cr);
  }
  cairo_restore(cr);
  if (fixed_y_range(spec)) {
    for (const auto& s : spec.series) mark_range_exits(cr, s, ax, ay, a);
  }
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
