#include "overlay/sphere.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <utility>

#include "overlay/cairo_canvas.hpp"
#include "typeface/text_layout.hpp"
#include "typeface/typeface.hpp"

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

using Polyline = std::vector<Eigen::Vector2d>;

Eigen::Vector2d project(const Basis& b, const SphereDisc& disc, const Eigen::Vector3d& p) {
  return {disc.cx + disc.r * p.dot(b.right), disc.cy - disc.r * p.dot(b.up)};
}

/// Polylines split into runs on the near side and on the far side; a segment belongs to the
/// side of its midpoint.
struct SideRuns {
  std::vector<Polyline> near_side, far_side;

  void add(const Basis& b, const SphereDisc& disc, const std::vector<Eigen::Vector3d>& points) {
    std::vector<Polyline>* current = nullptr;
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
      auto* side = (points[i] + points[i + 1]).dot(b.towards) >= 0 ? &near_side : &far_side;
      if (side != current) {
        side->push_back({project(b, disc, points[i])});
        current = side;
      }
      side->back().push_back(project(b, disc, points[i + 1]));
    }
  }
};

/// Strokes `runs` as one path (one cairo stroke for many curves: the polhodes cost one
/// stroke per style, not one per curve).
void stroke_runs(cairo_t* cr, const std::vector<Polyline>& runs, Rgb c, double alpha, double width,
                 bool dashed) {
  cairo_new_path(cr);
  for (const auto& run : runs) {
    if (run.size() < 2) continue;
    cairo_move_to(cr, run[0].x(), run[0].y());
    for (std::size_t i = 1; i < run.size(); ++i) cairo_line_to(cr, run[i].x(), run[i].y());
  }
  cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
  cairo_set_line_width(cr, width);
  if (dashed) {
    const double dash[] = {2.5 * width, 2.5 * width};
    cairo_set_dash(cr, dash, 2, 0);
  }
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0);
}

/// Strokes the runs: the far side first (faint, dashed), then the near side (solid).
void stroke_sides(cairo_t* cr, const SideRuns& runs, Rgb c, double width) {
  stroke_runs(cr, runs.far_side, c, kFarAlpha, width, true);
  stroke_runs(cr, runs.near_side, c, 1.0, width, false);
}

}  // namespace

Eigen::Vector2d project_to_inset(const SphereSpec& spec, const Eigen::Vector3d& p, double cx,
                                 double cy, double r, double* depth) {
  const Basis b = basis_of(spec);
  if (depth) *depth = p.dot(b.towards);
  return {cx + r * p.dot(b.right), cy - r * p.dot(b.up)};
}

SphereDisc sphere_disc(const PixelRect& rect) {
  const double top = inset_title_height(rect);
  const double r = 0.37 * std::min(rect.width, rect.height - top);
  return {rect.x + 0.5 * rect.width, rect.y + top + 0.5 * (rect.height - top), r};
}

namespace {

/// The title, centred in the band above the disc (which nothing else reaches: it may be drawn
/// before or after the rest).
void draw_title(cairo_t* cr, const PixelRect& rect, const SphereSpec& spec, double font,
                double title_height) {
  typeface::select(cr, typeface::Face::sans_bold, font);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_text_extents_t ext;
  typeface::text_extents(cr, spec.title.c_str(), &ext);
  cairo_move_to(cr, rect.x + 0.5 * (rect.width - ext.x_advance), rect.y + 0.75 * title_height);
  typeface::show_text(cr, spec.title.c_str());
}

/// The background, outline, axes and curves: what draw_top and the title leave.
void draw_shapes(cairo_t* cr, const PixelRect& rect, const SphereSpec& spec) {
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_rectangle(cr, rect.x, rect.y, rect.width, rect.height);
  cairo_set_source_rgba(cr, 0.98, 0.98, 0.97, 0.9);
  cairo_fill(cr);

  const SphereDisc disc = sphere_disc(rect);
  const double unit = rect.height / 150.0;  // line widths scale with the inset

  // Outline.
  cairo_new_path(cr);
  cairo_arc(cr, disc.cx, disc.cy, disc.r, 0, 2 * M_PI);
  cairo_set_source_rgba(cr, 0.93, 0.94, 0.96, 1.0);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, 0.35, 0.35, 0.38);
  cairo_set_line_width(cr, 1.2 * unit);
  cairo_stroke(cr);

  // Axes: through the centre, the far half faint; labels just beyond the + end.
  const Basis basis = basis_of(spec);
  for (const auto& axis : spec.axes) {
    SideRuns runs;
    runs.add(basis, disc, {-axis.direction, Eigen::Vector3d::Zero(), axis.direction});
    stroke_sides(cr, runs, axis.colour, 0.8 * unit);
  }
  // Consecutive curves of one style go into one stroke.
  for (std::size_t i = 0; i < spec.curves.size();) {
    const SphereCurve& first = spec.curves[i];
    SideRuns runs;
    for (; i < spec.curves.size(); ++i) {
      const SphereCurve& c = spec.curves[i];
      if (c.width != first.width || c.colour.r != first.colour.r || c.colour.g != first.colour.g ||
          c.colour.b != first.colour.b)
        break;
      runs.add(basis, disc, c.points);
    }
    stroke_sides(cr, runs, first.colour, first.width * unit);
  }
}

/// The trails with their end dots, then (with the title where `title`) the axis labels on top:
/// what draw_shapes leaves. Every text last, after the shapes and the places they go.
void draw_top(cairo_t* cr, const PixelRect& rect, const SphereSpec& spec, bool title) {
  cairo_save(cr);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  const SphereDisc disc = sphere_disc(rect);
  const double unit = rect.height / 150.0;
  const double font = inset_font(rect), title_height = inset_title_height(rect);
  const Basis basis = basis_of(spec);
  cairo_text_extents_t ext;
  for (const auto& t : spec.trails) {
    SideRuns runs;
    runs.add(basis, disc, t.points);
    stroke_sides(cr, runs, t.colour, t.width * unit);
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

  // Where each axis ends on the inset, and how deep.
  std::vector<Eigen::Vector2d> ends;
  std::vector<double> depths;
  for (const auto& axis : spec.axes) {
    double depth = 0;
    ends.push_back(project_to_inset(spec, axis.direction, disc.cx, disc.cy, disc.r, &depth));
    depths.push_back(depth);
  }
  if (title) draw_title(cr, rect, spec, font, title_height);

  // Axis labels last, on top, clamped inside the inset with a margin, each on a patch of the
  // inset's paper so that no curve runs through its letters.
  typeface::select(cr, typeface::Face::sans, 0.85 * font);
  cairo_font_extents_t fe;
  cairo_font_extents(cr, &fe);
  for (std::size_t i = 0; i < spec.axes.size(); ++i) {
    const auto& axis = spec.axes[i];
    const double depth = depths[i];
    const Eigen::Vector2d end = ends[i];
    Eigen::Vector2d out = end - Eigen::Vector2d(disc.cx, disc.cy);
    out = out.norm() > 1e-9 ? out.normalized() : Eigen::Vector2d(1, 0);
    typeface::text_extents(cr, axis.label.c_str(), &ext);
    const double pad = 0.4 * font;
    const Eigen::Vector2d anchor = end + pad * out;
    // Place the text's box on the outward side of the anchor.
    double x = anchor.x() - 0.5 * ext.x_advance * (1.0 - out.x());
    double y = anchor.y() + 0.35 * font * (1.0 + out.y());
    const double margin = 0.4 * font;
    x = std::clamp(x, rect.x + margin, rect.right() - ext.x_advance - margin);
    y = std::clamp(y, rect.y + title_height + font, rect.bottom() - margin);
    cairo_new_path(cr);
    cairo_rectangle(cr, x - 0.15 * font, y - fe.ascent, ext.x_advance + 0.3 * font,
                    fe.ascent + fe.descent);
    cairo_set_source_rgba(cr, 0.98, 0.98, 0.97, 0.8);
    cairo_fill(cr);
    cairo_set_source_rgba(cr, axis.colour.r, axis.colour.g, axis.colour.b, depth >= 0 ? 1.0 : 0.75);
    cairo_move_to(cr, x, y);
    typeface::show_text(cr, axis.label.c_str());
  }
  cairo_restore(cr);
}

bool drawable(const PixelRect& rect) { return rect.width >= 60 && rect.height >= 60; }

PixelRegion inset_region(const RgbaImage& image, const PixelRect& rect) {
  return region_around(rect.x, rect.y, rect.width, rect.height, 2.0, image.width, image.height);
}

}  // namespace

void draw_sphere(RgbaImage& image, const PixelRect& rect, const SphereSpec& spec) {
  if (!drawable(rect)) return;  // no room for a readable sphere
  CairoCanvas canvas(image.width, image.height, inset_region(image, rect));
  draw_shapes(canvas.cr(), rect, spec);
  draw_top(canvas.cr(), rect, spec, true);
  canvas.composite_onto(image);
}

SphereInset::SphereInset(int image_width, int image_height, const PixelRect& rect, SphereSpec spec)
    : width_(image_width), height_(image_height), rect_(rect), spec_(std::move(spec)) {
  spec_.trails.clear();
  if (!drawable(rect_)) return;
  canvas_ = std::make_unique<CairoCanvas>(
      width_, height_,
      region_around(rect.x, rect.y, rect.width, rect.height, 2.0, image_width, image_height));
  draw_shapes(canvas_->cr(), rect_, spec_);
  draw_title(canvas_->cr(), rect_, spec_, inset_font(rect_), inset_title_height(rect_));
  base_ = canvas_->snapshot();
}

SphereInset::~SphereInset() = default;

void SphereInset::draw(RgbaImage& image, std::vector<SphereTrail> trails) {
  if (image.width != width_ || image.height != height_)
    throw std::invalid_argument("SphereInset::draw: an image of another size");
  if (!canvas_) return;
  canvas_->restore(base_);
  spec_.trails = std::move(trails);
  draw_top(canvas_->cr(), rect_, spec_, false);
  canvas_->composite_onto(image);
}

}  // namespace bookspin::overlay
