#include "overlay/sphere.hpp"

#include <algorithm>
#include <cmath>

#include "overlay/cairo_canvas.hpp"

namespace bookspin::overlay {

namespace {

constexpr double kFarAlpha = 0.35;  // the far hemisphere: faint and dashed

struct Basis {
  Eigen::Vector3d right, up, towards;
};

Basis basis_of(const SphereSpec& spec) {
  Basis b;
  b.towards = spec.view.normalized();
  b.up = (spec.up - spec.up.dot(b.towards) * b.towards).normalized();
  b.right = b.up.cross(b.towards);
  return b;
}

double title_height(const PixelRect& rect) { return 0.1 * rect.height; }
double font_for(const PixelRect& rect) { return std::max(9.0, 0.052 * rect.height); }

void stroke_polyline(cairo_t* cr, const std::vector<Eigen::Vector2d>& pts, Rgb c, double alpha,
                     double width, bool dashed) {
  if (pts.size() < 2) return;
  cairo_new_path(cr);
  cairo_move_to(cr, pts[0].x(), pts[0].y());
  for (std::size_t i = 1; i < pts.size(); ++i) cairo_line_to(cr, pts[i].x(), pts[i].y());
  cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
  cairo_set_line_width(cr, width);
  if (dashed) {
    const double dash[] = {2.5 * width, 2.5 * width};
    cairo_set_dash(cr, dash, 2, 0);
  } else {
    cairo_set_dash(cr, nullptr, 0, 0);
  }
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
}

/// Strokes `points` split into runs on the near side (solid) and the far side (faint,
/// dashed); a segment belongs to the side of its midpoint.
void stroke_on_sphere(cairo_t* cr, const SphereSpec& spec, const SphereDisc& disc,
                      const std::vector<Eigen::Vector3d>& points, Rgb c, double width) {
  if (points.size() < 2) return;
  std::vector<Eigen::Vector2d> run;
  bool near_run = true;
  const auto flush = [&] {
    stroke_polyline(cr, run, c, near_run ? 1.0 : kFarAlpha, width, !near_run);
    run.clear();
  };
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const Eigen::Vector3d mid = 0.5 * (points[i] + points[i + 1]);
    double depth = 0;
    project_to_inset(spec, mid, disc.cx, disc.cy, disc.r, &depth);
    const bool near_side = depth >= 0;
    if (!run.empty() && near_side != near_run) {
      const Eigen::Vector2d last = run.back();
      flush();
      run.push_back(last);
    }
    near_run = near_side;
    if (run.empty()) run.push_back(project_to_inset(spec, points[i], disc.cx, disc.cy, disc.r));
    run.push_back(project_to_inset(spec, points[i + 1], disc.cx, disc.cy, disc.r));
  }
  flush();
}

}  // namespace

Eigen::Vector2d project_to_inset(const SphereSpec& spec, const Eigen::Vector3d& p, double cx,
                                 double cy, double r, double* depth) {
  const Basis b = basis_of(spec);
  if (depth) *depth = p.dot(b.towards);
  return {cx + r * p.dot(b.right), cy - r * p.dot(b.up)};
}

SphereDisc sphere_disc(const PixelRect& rect) {
  const double top = title_height(rect);
  const double r = 0.37 * std::min(rect.width, rect.height - top);
  return {rect.x + 0.5 * rect.width, rect.y + top + 0.5 * (rect.height - top), r};
}

void draw_sphere(RgbaImage& image, const PixelRect& rect, const SphereSpec& spec) {
  if (rect.width < 60 || rect.height < 60) return;  // no room for a readable sphere
  CairoCanvas canvas(
      image.width, image.height,
      region_around(rect.x, rect.y, rect.width, rect.height, 2.0, image.width, image.height));
  cairo_t* cr = canvas.cr();
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_rectangle(cr, rect.x, rect.y, rect.width, rect.height);
  cairo_set_source_rgba(cr, 0.98, 0.98, 0.97, 0.9);
  cairo_fill(cr);

  const SphereDisc disc = sphere_disc(rect);
  const double unit = rect.height / 150.0;  // line widths scale with the inset
  const double font = font_for(rect);

  // Title.
  select_overlay_font(cr, true, font);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_text_extents_t ext;
  cairo_text_extents(cr, spec.title.c_str(), &ext);
  cairo_move_to(cr, rect.x + 0.5 * (rect.width - ext.x_advance),
                rect.y + 0.75 * title_height(rect));
  cairo_show_text(cr, spec.title.c_str());

  // Outline.
  cairo_new_path(cr);
  cairo_arc(cr, disc.cx, disc.cy, disc.r, 0, 2 * M_PI);
  cairo_set_source_rgba(cr, 0.93, 0.94, 0.96, 1.0);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, 0.35, 0.35, 0.38);
  cairo_set_line_width(cr, 1.2 * unit);
  cairo_stroke(cr);

  // Axes: through the centre, the far half faint; labels just beyond the + end.
  for (const auto& axis : spec.axes) {
    stroke_on_sphere(cr, spec, disc, {-axis.direction, Eigen::Vector3d::Zero(), axis.direction},
                     axis.colour, 0.8 * unit);
  }
  for (const auto& c : spec.curves)
    stroke_on_sphere(cr, spec, disc, c.points, c.colour, c.width * unit);
  for (const auto& t : spec.trails) {
    stroke_on_sphere(cr, spec, disc, t.points, t.colour, t.width * unit);
    if (t.points.empty()) continue;
    double depth = 0;
    const Eigen::Vector2d dot =
        project_to_inset(spec, t.points.back(), disc.cx, disc.cy, disc.r, &depth);
    cairo_new_path(cr);
    cairo_arc(cr, dot.x(), dot.y(), (2.0 + 0.8 * t.width) * unit, 0, 2 * M_PI);
    cairo_set_source_rgba(cr, t.colour.r, t.colour.g, t.colour.b, depth >= 0 ? 1.0 : 0.6);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
    cairo_set_line_width(cr, 0.8 * unit);
    cairo_stroke(cr);
  }

  // Axis labels last, on top, clamped inside the inset.
  select_overlay_font(cr, false, 0.85 * font);
  for (const auto& axis : spec.axes) {
    double depth = 0;
    const Eigen::Vector2d end =
        project_to_inset(spec, axis.direction, disc.cx, disc.cy, disc.r, &depth);
    Eigen::Vector2d out = end - Eigen::Vector2d(disc.cx, disc.cy);
    out = out.norm() > 1e-9 ? out.normalized() : Eigen::Vector2d(1, 0);
    cairo_text_extents(cr, axis.label.c_str(), &ext);
    const double pad = 0.4 * font;
    const Eigen::Vector2d anchor = end + pad * out;
    // Place the text's box on the outward side of the anchor.
    double x = anchor.x() - 0.5 * ext.x_advance * (1.0 - out.x());
    double y = anchor.y() + 0.35 * font * (1.0 + out.y());
    x = std::clamp(x, rect.x + 2, rect.right() - ext.x_advance - 2);
    y = std::clamp(y, rect.y + title_height(rect) + font, rect.bottom() - 3);
    cairo_set_source_rgba(cr, axis.colour.r, axis.colour.g, axis.colour.b, depth >= 0 ? 1.0 : 0.75);
    cairo_move_to(cr, x, y);
    cairo_show_text(cr, axis.label.c_str());
  }
  canvas.composite_onto(image);
}

}  // namespace bookspin::overlay
