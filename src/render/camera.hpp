#pragma once
// Perspective camera: settings struct, default placement and the matrices it implies.
#include <Eigen/Dense>

namespace bookspin::render {

/// A perspective camera in world coordinates (length units of the scene).
struct Camera {
  double fov_y_deg = 30.0;                ///< vertical field of view, degrees, in (0, 180)
  Eigen::Vector3d eye{0.0, 0.0, 8.0};     ///< camera position, world
  Eigen::Vector3d target{0.0, 0.0, 0.0};  ///< point looked at, world
  Eigen::Vector3d up{0.0, 1.0, 0.0};      ///< world direction that appears upward
};

/// The default view: looks at the origin from direction (0.9, 0.6, 3.2), up +y, 30° vertical
/// field of view, far enough that a sphere of `bounding_radius` (world units) around the
/// origin stays in view for a width×height (pixels) image:
/// distance = r / sin(fov/2) × 1.1, using the horizontal field of view when it is narrower.
/// Throws RenderError if bounding_radius is not finite and > 0 or a size is not > 0.
Camera default_camera(double bounding_radius, int width, int height);

/// The radius about the origin (where the default camera looks) of the smallest sphere
/// holding every column of `points` (3×K, world): the bounding_radius for default_camera of
/// a body of any extent, e.g. its box's 8 corners or its surface's vertices. Throws
/// RenderError if K = 0, a point is not finite, or all points are at the origin.
double bounding_radius(const Eigen::Matrix3Xd& points);

/// World → view (camera) transform, 4×4, column-major (OpenGL convention: camera looks
/// along −z). Throws RenderError for a degenerate camera (eye == target, up ∥ view
/// direction, non-finite values, fov outside (0, 180)).
Eigen::Matrix4d view_matrix(const Camera& camera);

/// View → clip transform, 4×4, for an image of the given aspect ratio (width / height).
/// Near and far planes follow from the eye–target distance (near = d/50, far = 50·d).
Eigen::Matrix4d projection_matrix(const Camera& camera, double aspect);

/// Validates a camera (see view_matrix); throws RenderError naming the problem.
void validate_camera(const Camera& camera);

}  // namespace bookspin::render
