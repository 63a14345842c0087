#include "overlay/poinsot.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

#include "common/colour.hpp"
#include "overlay/cairo_canvas.hpp"
#include "typeface/text_layout.hpp"

namespace bookspin::overlay {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kElevation = -0.30;  // radians: the view from slightly below the plane

struct View {
  Eigen::Vector3d right, up, towards;
  double cx, cy, scale;  // pixels: the centre of the ellipsoid and pixels per length unit
};

struct LegendItem {
  const char* text;
  double r, g, b;
};
constexpr LegendItem kLegend[] = {{"polhode", 0.0, 0.55, 0.25},
                                  {"herpolhode", 0.05, 0.25, 0.75},
                                  {"invariable plane", 0.35, 0.45, 0.60}};

/// The legend's items in rows that fit the inset's width, from the top row (indices into
/// kLegend), measured at 0.85 of the title's font.
std::vector<std::vector<int>> legend_rows(const PixelRect& rect) {
  CairoCanvas measure(1, 1);
  cairo_t* cr = measure.cr();
  const double font = inset_font(rect), left = rect.x + 0.04 * rect.width;
  select_overlay_font(cr, false, 0.85 * font);
  std::vector<std::vector<int>> rows(1);
  double x = left;
  for (int i = 0; i < 3; ++i) {
    cairo_text_extents_t ext;
    typeface::text_extents(cr, kLegend[i].text, &ext);
    if (!rows.back().empty() && x + ext.x_advance > rect.right() - 0.04 * rect.width)
      rows.emplace_back(), x = left;
    rows.back().push_back(i);
    x += ext.x_advance + 0.9 * font;
  }
  return rows;
}

/// The legend's line height, pixels.
double legend_line(const PixelRect& rect) { return 1.25 * 0.85 * inset_font(rect); }

/// The view of `spec` in `rect` above a legend of `legend_rows` rows (legend_rows).
View view_of(const PoinsotSpec& spec, const PixelRect& rect, std::size_t legend_rows) {
  View v;
  v.up = spec.normal.normalized();
  const Eigen::Vector3d across = (spec.across - spec.across.dot(v.up) * v.up).normalized();
  v.towards = std::cos(kElevation) * across + std::sin(kElevation) * v.up;
  v.right = v.up.cross(v.towards).normalized();
  v.up = v.towards.cross(v.right);
  // Fit: the ellipsoid's largest semi-axis and the plane's disc, the plane in the upper part.
  const double a_max = spec.semi_axes.colwise().norm().maxCoeff();
  const double half_width = 1.08 * std::max(a_max, spec.plane_radius);
  const double top = rect.y + 1.25 * inset_title_height(rect);
  // The legend below: its rows above the last, which is where one row alone would be.
  const double legend = static_cast<double>(legend_rows - 1) * legend_line(rect);
  const double bottom = rect.y + rect.height - 0.09 * rect.height - legend;
  const double span_up = spec.plane_distance + 0.45 * a_max;  // room for the L arrow
  const double span_down = 1.05 * a_max;
  v.scale = std::min(0.5 * rect.width / half_width, (bottom - top) / (span_up + span_down));
  v.cx = rect.x + 0.5 * rect.width;
  v.cy = top + span_up * v.scale;
  return v;
}

Eigen::Vector2d project(const View& v, const Eigen::Vector3d& p) {
  return {v.cx + v.scale * p.dot(v.right), v.cy - v.scale * p.dot(v.up)};
}

/// Adds the polyline through `points` (pixels) to the current path.
void polyline(cairo_t* cr, const std::vector<Eigen::Vector2d>& points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i == 0)
      cairo_move_to(cr, points[i].x(), points[i].y());
    else
      cairo_line_to(cr, points[i].x(), points[i].y());
  }
}

void path_of(cairo_t* cr, const View& v, const std::vector<Eigen::Vector3d>& points) {
  std::vector<Eigen::Vector2d> screen;
  screen.reserve(points.size());
  for (const Eigen::Vector3d& p : points) screen.push_back(project(v, p));
  polyline(cr, screen);
}

/// Closes the current path, fills it with `fill` at opacity `alpha` and strokes its outline
/// in `line`, `width` pixels wide.
void fill_and_outline(cairo_t* cr, const Rgb& fill, double alpha, const Rgb& line, double width) {
  cairo_close_path(cr);
  cairo_set_source_rgba(cr, fill.r, fill.g, fill.b, alpha);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, line.r, line.g, line.b);
  cairo_set_line_width(cr, width);
  cairo_stroke(cr);
}

/// Strokes a curve on the ellipsoid: segments whose surface normal faces the viewer solid,
/// the others faint and dashed.
void stroke_on_ellipsoid(cairo_t* cr, const View& v, const Eigen::Matrix3d& inverse_axes,
                         const std::vector<Eigen::Vector3d>& points, double r, double g, double b,
                         double width) {
  // At x = axes·s (s on the unit sphere) the outward normal is along axes⁻ᵀ s.
  const Eigen::Vector3d facing = inverse_axes * v.towards;
  for (const bool near : {false, true}) {
    cairo_new_path(cr);
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
      const Eigen::Vector3d mid = 0.5 * (points[i] + points[i + 1]);
      if (((inverse_axes * mid).dot(facing) >= 0) != near) continue;
      const Eigen::Vector2d a = project(v, points[i]), c = project(v, points[i + 1]);
      cairo_move_to(cr, a.x(), a.y());
      cairo_line_to(cr, c.x(), c.y());
    }
    cairo_set_source_rgba(cr, r, g, b, near ? 1.0 : 0.35);
    cairo_set_line_width(cr, width);
    if (!near) {
      const double dash[] = {2.5 * width, 2.5 * width};
      cairo_set_dash(cr, dash, 2, 0);
    }
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
  }
}

void label(cairo_t* cr, const std::string& text, double x, double y, double r, double g, double b) {
  cairo_set_source_rgb(cr, r, g, b);
  cairo_move_to(cr, x, y);
  typeface::show_text(cr, text.c_str());
}

}  // namespace

Eigen::Vector2d poinsot_to_inset(const PoinsotSpec& spec, const PixelRect& rect,
                                 const Eigen::Vector3d& p) {
  return project(view_of(spec, rect, legend_rows(rect).size()), p);
}

void draw_poinsot(RgbaImage& image, const PixelRect& rect, const PoinsotSpec& spec) {
  if (!spec.normal.allFinite() || !(spec.normal.norm() > 0) || !spec.semi_axes.allFinite() ||
      !spec.contact.allFinite() || !std::isfinite(spec.plane_distance) ||
      !(spec.plane_distance > 0) || !std::isfinite(spec.plane_radius) || !(spec.plane_radius > 0) ||
      std::abs(spec.semi_axes.determinant()) == 0)
    throw std::invalid_argument("draw_poinsot: the construction must be finite and not degenerate");
  if (rect.width < 16 || rect.height < 16) return;
  CairoCanvas canvas(
      image.width, image.height,
      region_around(rect.x, rect.y, rect.width, rect.height, 1.0, image.width, image.height));
  cairo_t* cr = canvas.cr();
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_rectangle(cr, rect.x, rect.y, rect.width, rect.height);
  cairo_set_source_rgba(cr, 0.98, 0.98, 0.97, 0.9);
  cairo_fill(cr);
  cairo_rectangle(cr, rect.x, rect.y, rect.width, rect.height);
  cairo_clip(cr);

  const auto rows = legend_rows(rect);
  const View v = view_of(spec, rect, rows.size());
  const double unit = rect.height / 150.0;
  const double font = inset_font(rect);
  const Eigen::Vector3d n = spec.normal.normalized();
  const Eigen::Vector3d e1 = (spec.across - spec.across.dot(n) * n).normalized(), e2 = n.cross(e1);
  const Eigen::Vector3d foot = spec.plane_distance * n;

  // The invariable plane: a disc about the foot of the normal, seen from below.
  std::vector<Eigen::Vector3d> rim;
  for (int i = 0; i <= 96; ++i) {
    const double a = 2 * kPi * i / 96;
    rim.push_back(foot + spec.plane_radius * (std::cos(a) * e1 + std::sin(a) * e2));
  }
  cairo_new_path(cr);
  path_of(cr, v, rim);
  fill_and_outline(cr, {0.72, 0.80, 0.92}, 0.55, {0.35, 0.45, 0.60}, 0.9 * unit);

  // The herpolhode so far, on the plane.
  if (spec.herpolhode.size() >= 2) {
    cairo_new_path(cr);
    path_of(cr, v, spec.herpolhode);
    cairo_set_source_rgb(cr, 0.05, 0.25, 0.75);
    cairo_set_line_width(cr, 1.3 * unit);
    cairo_stroke(cr);
  }

  // The ellipsoid: its outline is the ellipse {s : sᵀ M⁻¹ s = 1}, M = P A Aᵀ Pᵀ with P the
  // screen rows and A the semi-axis matrix (the image of the unit ball under P·A).
  Eigen::Matrix<double, 2, 3> P;
  P.row(0) = v.right.transpose();
  P.row(1) = v.up.transpose();
  const Eigen::Matrix2d M = P * spec.semi_axes * spec.semi_axes.transpose() * P.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(M);
  const Eigen::Matrix2d root =
      eig.eigenvectors() * eig.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal();
  std::vector<Eigen::Vector2d> outline;
  for (int i = 0; i <= 120; ++i) {
    const double a = 2 * kPi * i / 120;
    const Eigen::Vector2d s = root * Eigen::Vector2d(std::cos(a), std::sin(a));
    outline.emplace_back(v.cx + v.scale * s.x(), v.cy - v.scale * s.y());
  }
  cairo_new_path(cr);
  polyline(cr, outline);
  fill_and_outline(cr, {0.96, 0.78, 0.52}, 0.55, {0.55, 0.35, 0.15}, 1.1 * unit);

  // Its three principal sections (fixed in the body: they show it turning).
  const Eigen::Matrix3d inverse_axes = spec.semi_axes.inverse();
  for (int k = 0; k < 3; ++k) {
    std::vector<Eigen::Vector3d> ring;
    for (int i = 0; i <= 96; ++i) {
      const double a = 2 * kPi * i / 96;
      Eigen::Vector3d s = Eigen::Vector3d::Zero();
      s[(k + 1) % 3] = std::cos(a);
      s[(k + 2) % 3] = std::sin(a);
      ring.push_back(spec.semi_axes * s);
    }
    stroke_on_ellipsoid(cr, v, inverse_axes, ring, 0.55, 0.35, 0.15, 0.6 * unit);
  }
  // The polhode.
  if (spec.polhode.size() >= 2)
    stroke_on_ellipsoid(cr, v, inverse_axes, spec.polhode, 0.0, 0.55, 0.25, 1.5 * unit);

  // ω: from the centre to the contact point (ρ = ω/√(2E) is along ω).
  {
    const Eigen::Vector2d o = project(v, Eigen::Vector3d::Zero()), c = project(v, spec.contact);
    cairo_new_path(cr);
    cairo_move_to(cr, o.x(), o.y());
    cairo_line_to(cr, c.x(), c.y());
    cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
    cairo_set_line_width(cr, 0.8 * unit);
    const double dash[] = {2.5 * unit, 2.0 * unit};
    cairo_set_dash(cr, dash, 2, 0);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0);
    cairo_arc(cr, o.x(), o.y(), 1.6 * unit, 0, 2 * kPi);
    cairo_fill(cr);
    select_overlay_font(cr, false, font);
    const Eigen::Vector2d m = 0.5 * (o + c);
    label(cr, "ω", m.x() + 0.6 * font, m.y() + 0.3 * font, 0.3, 0.3, 0.3);
  }
  // L on the plane's normal, from its foot.
  {
    const double a_max = spec.semi_axes.colwise().norm().maxCoeff();
    const Eigen::Vector2d f = project(v, foot), t = project(v, foot + 0.38 * a_max * n);
    cairo_new_path(cr);
    cairo_move_to(cr, f.x(), f.y());
    cairo_line_to(cr, t.x(), t.y());
    cairo_set_source_rgb(cr, 0.75, 0.1, 0.1);
    cairo_set_line_width(cr, 1.4 * unit);
    cairo_stroke(cr);
    const Eigen::Vector2d d = (t - f).normalized(), side(-d.y(), d.x());
    const double head = 4.0 * unit;
    cairo_move_to(cr, t.x(), t.y());
    cairo_line_to(cr, t.x() - head * d.x() + 0.55 * head * side.x(),
                  t.y() - head * d.y() + 0.55 * head * side.y());
    cairo_line_to(cr, t.x() - head * d.x() - 0.55 * head * side.x(),
                  t.y() - head * d.y() - 0.55 * head * side.y());
    cairo_close_path(cr);
    cairo_fill(cr);
    select_overlay_font(cr, true, font);
    label(cr, "L", t.x() + 0.4 * font, t.y() + 0.35 * font, 0.75, 0.1, 0.1);
  }
  // The contact point.
  {
    const Eigen::Vector2d c = project(v, spec.contact);
    cairo_new_path(cr);
    cairo_arc(cr, c.x(), c.y(), 2.6 * unit, 0, 2 * kPi);
    cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_set_line_width(cr, 0.7 * unit);
    cairo_stroke(cr);
  }

  // Title and legend.
  cairo_reset_clip(cr);
  select_overlay_font(cr, true, font);
  cairo_text_extents_t ext;
  typeface::text_extents(cr, spec.title.c_str(), &ext);
  label(cr, spec.title, rect.x + 0.5 * (rect.width - ext.x_advance),
        rect.y + 0.75 * inset_title_height(rect), 0.1, 0.1, 0.1);
  select_overlay_font(cr, false, 0.85 * font);
  double y = rect.y + rect.height - 0.03 * rect.height -
             static_cast<double>(rows.size() - 1) * legend_line(rect);
  for (const auto& row : rows) {
    double x = rect.x + 0.04 * rect.width;
    for (int i : row) {
      const LegendItem& item = kLegend[i];
      label(cr, item.text, x, y, item.r, item.g, item.b);
      typeface::text_extents(cr, item.text, &ext);
      x += ext.x_advance + 0.9 * font;
    }
    y += legend_line(rect);
  }
  canvas.composite_onto(image);
}

}  // namespace bookspin::overlay
