#include "overlay/plot_lines.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>
#include <vector>

namespace bookspin::overlay {

namespace {

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

}  // namespace

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

}  // namespace bookspin::overlay
