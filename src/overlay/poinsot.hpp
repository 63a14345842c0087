#pragma once
// Poinsot's construction inset: the inertia ellipsoid rolling on the invariable plane, seen in
// the world frame in orthographic projection (docs/physics.md §16). Pure drawing: the charts stage
// gives the geometry (physics::poinsot_state) as world-frame points and vectors.
#include <Eigen/Dense>
#include <string>
#include <vector>

#include "common/pixel_rect.hpp"
#include "common/rgba_image.hpp"

namespace bookspin::overlay {

/// What the inset shows, all in the world frame (one length unit for every entry).
struct PoinsotSpec {
  std::string title = "Poinsot's construction";
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  ///< L/|L|: the plane's normal, unit
  double plane_distance = 1.0;                        ///< from the centre to the plane, > 0
  /// The ellipsoid's semi-axes as vectors (3×3, columns: axis i times its semi-axis length).
  Eigen::Matrix3d semi_axes = Eigen::Matrix3d::Identity();
  Eigen::Vector3d contact = Eigen::Vector3d::UnitZ();  ///< the contact point (on the plane)
  std::vector<Eigen::Vector3d> polhode;     ///< closed curve on the ellipsoid, as placed now
  std::vector<Eigen::Vector3d> herpolhode;  ///< on the plane, the contact point so far
  double plane_radius = 1.0;                ///< radius of the plane's disc drawn, > 0
  /// A unit vector ⟂ normal fixing the view's azimuth (the view looks along it, from
  /// slightly below the plane, with the normal up on screen).
  Eigen::Vector3d across = Eigen::Vector3d::UnitX();
};

/// Draws `spec` into `rect` of `image` on a translucent light background: the plane as a
/// disc (seen from below), the herpolhode on it, the ellipsoid (outline and its three
/// principal sections, far side faint and dashed), the polhode on it, the contact point, L as
/// an arrow on the plane's normal, the title and a legend. Throws std::invalid_argument for a
/// non-finite spec or a plane distance or radius ≤ 0.
void draw_poinsot(RgbaImage& image, const PixelRect& rect, const PoinsotSpec& spec);

/// Screen position (pixels, y down) of world point p in the inset `rect` drawn for `spec`.
Eigen::Vector2d poinsot_to_inset(const PoinsotSpec& spec, const PixelRect& rect,
                                 const Eigen::Vector3d& p);

}  // namespace bookspin::overlay
