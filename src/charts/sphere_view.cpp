#include "charts/sphere_view.hpp"

#include <algorithm>
#include <string>

#include "overlay/caption.hpp"
#include "physics/polhode.hpp"

namespace bookspin::charts {

namespace {

// The body axes in the colours of the rendered body axes (x red, y green, z blue), a little
// darker for text on the light inset.
constexpr std::array<Rgb, 3> kAxisColours{
    {{0.80, 0.12, 0.08}, {0.08, 0.52, 0.16}, {0.12, 0.30, 0.85}}};
constexpr Rgb kPolhodeColour{0.55, 0.57, 0.62};

}  // namespace

Eigen::Vector3d sphere_moments(const scene::Scene& scene) { return scene.body.moments; }

overlay::SphereSpec sphere_spec(const Eigen::Vector3d& moments,
                                const std::vector<SphereRun>& runs) {
  return sphere_spec(physics::principal_order(moments), physics::polhode_family(moments), runs);
}

overlay::SphereSpec sphere_spec(const std::array<int, 3>& order,
                                std::vector<physics::Polhode> polhodes,
                                const std::vector<SphereRun>& runs) {
  overlay::SphereSpec spec;
  spec.title = "L/|L| in the body frame";
  static const char* const kRank[3] = {"smallest I", "intermediate I", "largest I"};
  static const char* const kName[3] = {"x", "y", "z"};
  for (int rank = 0; rank < 3; ++rank) {
    const int axis = order[rank];
    overlay::SphereAxis a;
    a.direction = Eigen::Vector3d::Unit(axis);
    a.label = std::string(kName[axis]) + " · " + kRank[rank];
    a.colour = kAxisColours[axis];
    spec.axes.push_back(a);
  }
  // Fixed oblique view: the intermediate axis (where the flips start) towards the viewer,
  // the largest up.
  spec.view = 1.0 * Eigen::Vector3d::Unit(order[1]) + 0.55 * Eigen::Vector3d::Unit(order[0]) +
              0.4 * Eigen::Vector3d::Unit(order[2]);
  spec.up = Eigen::Vector3d::Unit(order[2]);
  for (auto& p : polhodes) {
    overlay::SphereCurve c;
    c.points = std::move(p.points);
    c.colour = p.separatrix ? kSeparatrixColour : kPolhodeColour;
    c.width = p.separatrix ? 1.4 : 0.8;
    spec.curves.push_back(std::move(c));
  }
  spec.trails = sphere_trails(runs);
  return spec;
}

std::vector<overlay::SphereTrail> sphere_trails(const std::vector<SphereRun>& runs) {
  std::vector<overlay::SphereTrail> trails;
  for (const auto& run : runs) {
    overlay::SphereTrail t;
    for (const auto& u : run.history->momentum_direction)
      if (u.squaredNorm() > 0 && u.allFinite()) t.points.push_back(u);
    t.colour = run.colour;
    // Trails drawn later are narrower, so runs in lockstep (one curve) still show every colour.
    t.width = 1.6 + 0.9 * static_cast<double>(runs.size() - 1 - (&run - runs.data()));
    trails.push_back(std::move(t));
  }
  return trails;
}

PixelRect sphere_rect(int width, int height, double book_width, int caption_lines) {
  (void)width;
  const double side = std::min(0.45 * height, 0.42 * book_width);
  const double margin = 0.012 * std::min(width, height);
  // Below the caption: 0.19·height under three lines, a line height lower for each more, and
  // at least under its box (a margin of 0.6 font sizes above it).
  const double font = overlay::default_caption_font(height);
  const double top = std::max(
      {margin, 0.19 * height + std::max(0, caption_lines - 3) * 1.35 * font,
       0.6 * font + overlay::caption_height(static_cast<std::size_t>(caption_lines), font)});
  return {margin, top, side, side};
}

std::pair<PixelRect, PixelRect> split_for_sphere(const PixelRect& column) {
  const double side = std::min(column.width, 0.42 * column.height);
  const PixelRect sphere{column.x + 0.5 * (column.width - side), column.y, side, side};
  const double gap = 0.02 * column.height;
  return {sphere, {column.x, column.y + side + gap, column.width, column.height - side - gap}};
}

}  // namespace bookspin::charts
