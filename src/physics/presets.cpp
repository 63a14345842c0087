#include "physics/presets.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace bookspin::physics {

namespace {

using Colour = Eigen::Vector3f;
using Outline = std::vector<Eigen::Vector2d>;  ///< a closed polygon, counter-clockwise

/// Builds closed shells triangle by triangle.
class MeshBuilder {
 public:
  int vertex(const Eigen::Vector3d& p) {
    points_.push_back(p);
    return static_cast<int>(points_.size()) - 1;
  }
  void triangle(int a, int b, int c, const Colour& colour) {
    triangles_.push_back({a, b, c});
    colours_.push_back(colour);
  }
  void quad(int a, int b, int c, int d, const Colour& colour) {
    triangle(a, b, c, colour);
    triangle(a, c, d, colour);
  }
  PresetMesh finish() const {
    PresetMesh mesh;
    mesh.vertices.resize(3, static_cast<Eigen::Index>(points_.size()));
    for (std::size_t i = 0; i < points_.size(); ++i) mesh.vertices.col(i) = points_[i];
    mesh.triangles.resize(3, static_cast<Eigen::Index>(triangles_.size()));
    mesh.face_colours.resize(3, static_cast<Eigen::Index>(triangles_.size()));
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
      mesh.triangles.col(t) = Eigen::Vector3i(triangles_[t][0], triangles_[t][1], triangles_[t][2]);
      mesh.face_colours.col(t) = colours_[t];
    }
    return mesh;
  }

 private:
  std::vector<Eigen::Vector3d> points_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<Colour> colours_;
};

/// The point (u, v, w) with w along body axis `axis` and (u, v, w) a cyclic, right-handed
/// permutation of (x, y, z).
Eigen::Vector3d place(int axis, double u, double v, double w) {
  Eigen::Vector3d p;
  p[(axis + 1) % 3] = u;
  p[(axis + 2) % 3] = v;
  p[axis] = w;
  return p;
}

struct PrismColours {
  Colour side, low, high;  ///< walls, cap at w0 and cap at w1
};

/// The prism over a convex outline (counter-clockwise in u, v) from w = w0 to w1 > w0, along
/// body axis `axis`: one closed shell, outward winding, caps fanned.
void prism(MeshBuilder& m, const Outline& outline, int axis, double w0, double w1,
           const PrismColours& colours) {
  const int n = static_cast<int>(outline.size());
  std::vector<int> low(n), high(n);
  for (int i = 0; i < n; ++i) {
    low[i] = m.vertex(place(axis, outline[i].x(), outline[i].y(), w0));
    high[i] = m.vertex(place(axis, outline[i].x(), outline[i].y(), w1));
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    m.quad(low[i], low[j], high[j], high[i], colours.side);
  }
  for (int i = 1; i + 1 < n; ++i) {
    m.triangle(high[0], high[i], high[i + 1], colours.high);
    m.triangle(low[0], low[i + 1], low[i], colours.low);
  }
}

/// The closed ring between two outlines with the same number of points (outer around inner,
/// both counter-clockwise), from w0 to w1 along `axis`.
void ring(MeshBuilder& m, const Outline& outer, const Outline& inner, int axis, double w0,
          double w1, const Colour& colour) {
  const int n = static_cast<int>(outer.size());
  std::vector<int> ol(n), oh(n), il(n), ih(n);
  for (int i = 0; i < n; ++i) {
    ol[i] = m.vertex(place(axis, outer[i].x(), outer[i].y(), w0));
    oh[i] = m.vertex(place(axis, outer[i].x(), outer[i].y(), w1));
    il[i] = m.vertex(place(axis, inner[i].x(), inner[i].y(), w0));
    ih[i] = m.vertex(place(axis, inner[i].x(), inner[i].y(), w1));
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    m.quad(ol[i], ol[j], oh[j], oh[i], colour);  // outer wall, facing out
    m.quad(il[i], ih[i], ih[j], il[j], colour);  // inner wall, facing the hole
    m.quad(oh[i], oh[j], ih[j], ih[i], colour);  // face at w1
    m.quad(ol[i], il[i], il[j], ol[j], colour);  // face at w0
  }
}

Outline rectangle(double u0, double v0, double u1, double v1) {
  return {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}};
}

/// Regular polygon of `n` corners on a circle of radius `r`, rotated so that one edge is
/// horizontal at the bottom (v = −r cos(π/n)).
Outline regular_polygon(int n, double r) {
  Outline out;
  const double pi = std::numbers::pi;
  for (int i = 0; i < n; ++i) {
    const double angle = -0.5 * pi + pi / n + 2.0 * pi * i / n;
    out.emplace_back(r * std::cos(angle), r * std::sin(angle));
  }
  return out;
}

/// `n` points of the ellipse with semi-axes (a, b), from the angle where x = half_width at the
/// bottom round to x = −half_width, so the closing edge is a flat bottom of width 2·half_width.
Outline cut_ellipse(double a, double b, double half_width, int n) {
  const double pi = std::numbers::pi;
  const double phi = std::asin(half_width / a);
  Outline out;
  for (int i = 0; i < n; ++i) {
    const double angle = -0.5 * pi + phi + (2.0 * pi - 2.0 * phi) * i / (n - 1);
    out.emplace_back(a * std::cos(angle), b * std::sin(angle));
  }
  return out;
}

// Colours, linear RGB.
const Colour kRed{0.70f, 0.05f, 0.04f};
const Colour kGrey{0.45f, 0.47f, 0.50f};
const Colour kWhite{0.85f, 0.85f, 0.82f};
const Colour kNavy{0.03f, 0.06f, 0.30f};
const Colour kStringsFront{0.80f, 0.75f, 0.20f};
const Colour kStringsBack{0.20f, 0.55f, 0.25f};
const Colour kBlack{0.03f, 0.03f, 0.03f};
const Colour kSilver{0.62f, 0.63f, 0.66f};
const Colour kScreen{0.02f, 0.05f, 0.12f};
const Colour kCamera{0.08f, 0.08f, 0.09f};

// The T-handle: octagonal bar along x, flat underside at y = −apothem, box stem below it.
PresetMesh t_handle() {
  MeshBuilder m;
  const double radius = 0.3, half_length = 1.2;
  const Outline bar = regular_polygon(8, radius);  // in (y, z) for axis x
  // regular_polygon's flat edge is at v = −r cos(π/8); with axis x, (u, v) = (y, z), so turn
  // the outline a quarter so the flat edge faces −y: (u, v) → (v, −u).
  Outline turned;
  for (const auto& p : bar) turned.emplace_back(p.y(), -p.x());
  prism(m, turned, 0, -half_length, half_length, {kRed, kRed, kRed});
  const double apothem = radius * std::cos(std::numbers::pi / 8.0);
  // Stem along y (axis 1: (u, v) = (z, x)), from y = −apothem − 1.5 up to the bar's flat side;
  // its z extent (0.22) fits the flat side's width 2r sin(π/8) = 0.23.
  prism(m, rectangle(-0.11, -0.18, 0.11, 0.18), 1, -apothem - 1.5, -apothem,
        {kGrey, kWhite, kGrey});
  return m.finish();
}

// The tennis racket: elliptical frame and string plate in the x–y plane, handle along −y.
PresetMesh tennis_racket() {
  MeshBuilder m;
  const double a = 0.55, b = 0.7, rim = 0.07, half_thick = 0.08, half_handle = 0.09;
  const int n = 48;
  const Outline outer = cut_ellipse(a, b, half_handle, n);
  const Outline inner = cut_ellipse(a - rim, b - rim, half_handle * (a - rim) / a, n);
  ring(m, outer, inner, 2, -half_thick, half_thick, kNavy);
  prism(m, inner, 2, -0.01, 0.01, {kStringsFront, kStringsBack, kStringsFront});
  // Handle: axis y ((u, v) = (z, x)), from the frame's flat bottom edge down 1.3.
  const double top = outer.front().y();
  prism(m, rectangle(-half_thick, -half_handle, half_thick, half_handle), 1, top - 1.3, top,
        {kBlack, kRed, kBlack});
  return m.finish();
}

// The phone: a slab, screen on +z, a camera bump on the back at the top left (seen from the
// back).
PresetMesh phone() {
  MeshBuilder m;
  const double hx = 0.71, hy = 1.47, hz = 0.08;
  prism(m, rectangle(-hx, -hy, hx, hy), 2, -hz, hz, {kSilver, kSilver, kScreen});
  prism(m, rectangle(hx - 0.5, hy - 0.5, hx - 0.1, hy - 0.1), 2, -hz - 0.04, -hz,
        {kCamera, kCamera, kCamera});
  return m.finish();
}

}  // namespace

PresetMesh preset_mesh(BodyShape shape) {
  switch (shape) {
    case BodyShape::t_handle:
      return t_handle();
    case BodyShape::tennis_racket:
      return tennis_racket();
    case BodyShape::phone:
      return phone();
    default:
      throw std::invalid_argument("preset_mesh: '" + std::string(to_string(shape)) +
                                  "' is not a preset shape");
  }
}

Body preset_body(BodyShape shape, double mass, double scale) {
  const PresetMesh mesh = preset_mesh(shape);
  BodyResult result =
      body_from_mesh(mesh.vertices, mesh.triangles, mass, scale, mesh.face_colours, false, shape);
  if (!result.ok())
    throw std::invalid_argument("preset '" + std::string(to_string(shape)) + "': " + result.error);
  return result.body;
}

}  // namespace bookspin::physics
