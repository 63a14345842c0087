#pragma once
// The simulated body as a parameter: the book, a preset shape or a closed triangle mesh, in
// its principal frame (docs/physics.md §12). Pure math: no files.
#include <Eigen/Core>
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "physics/book.hpp"

namespace bookspin::physics {

enum class BodyShape { book, t_handle, tennis_racket, phone, mesh };

/// A rigid body in its principal frame: centre of mass at the origin, body axes x, y, z the
/// principal axes (docs/physics.md §12).
struct Body {
  BodyShape shape = BodyShape::book;
  /// Book: the book itself. Others: the box symmetric about the origin that holds the surface
  /// in the principal frame (size = 2·max|coordinate| per axis), mass = body mass. Its 8
  /// corners (Book::body_corners, 3×8) are what the simulators move (Pose::corners) and
  /// what the drawing interpolates the surface from.
  Book cage;
  /// Principal moments about body x, y, z (mass·length²). Book: cage.principal_moments().
  /// Others: ascending (x smallest, y intermediate, z largest).
  Eigen::Vector3d moments = Book{}.principal_moments();
  /// 3×V surface vertices, principal frame (length units); empty for the book (drawn as the
  /// textured book).
  Eigen::Matrix3Xd vertices;
  Eigen::Matrix3Xi triangles;     ///< 3×N vertex indices, outward (counter-clockwise) winding
  Eigen::Matrix3Xf face_colours;  ///< 3×N linear RGB in [0, 1], one per triangle
  bool smooth = false;            ///< smooth (per-vertex) normals when drawing, else flat
  double volume = 0.0;            ///< length³ (0 for the book: not needed)
  /// Rows: the principal axes x, y, z in the axes the body was built in (a preset's
  /// construction frame, a mesh file's axes), so that a surface point's built coordinates are
  /// c + principal_axesᵀ · v (c the centre of mass, v its principal-frame coordinates; a
  /// rotation, det +1). Identity for the book, whose body frame is its own.
  Eigen::Matrix3d principal_axes = Eigen::Matrix3d::Identity();
};

/// The book as a Body: cage = book, moments = book.principal_moments(), no surface mesh.
Body book_body(const Book& book);

/// The outcome of body_from_mesh(): the body, or why there is none.
struct BodyResult {
  Body body;                          ///< meaningful only when ok()
  std::string error;                  ///< empty on success, else one line (see mass_properties)
  std::vector<std::string> warnings;  ///< e.g. a shell wound inward that was turned around
  bool ok() const { return error.empty(); }
};

/// Moves a closed mesh (3×V `vertices`, 3×N `triangles`, any frame) into its principal frame
/// after scaling every coordinate by `scale` (> 0): the centre of mass goes to the origin and
/// the rows of MassProperties::principal_axes (ascending moments, right-handed) become x, y, z,
/// so the moments come out ascending. Uniform density, total mass `mass` (> 0). Winding is
/// kept (a shell wound inward on its own is turned around, with a warning, as mass_properties
/// does; a cavity keeps its inward winding). A mass or inertia beyond the double range is the
/// error physics::kOverflow.
/// `face_colours` (3×N, or empty: a default grey) and `smooth` are passed through; `shape`
/// is recorded. No I/O, no exceptions for bad input: a bad mesh or a non-positive or
/// non-finite mass or scale gives an error string. docs/physics.md §11–12.
BodyResult body_from_mesh(const Eigen::Matrix3Xd& vertices, const Eigen::Matrix3Xi& triangles,
                          double mass, double scale, const Eigen::Matrix3Xf& face_colours = {},
                          bool smooth = false, BodyShape shape = BodyShape::mesh);

/// Indices of the body axes sorted by ascending moment (ties keep axis order): for the
/// default book {1, 0, 2} (y, x, z), for every other body {0, 1, 2}.
std::array<int, 3> principal_order(const Eigen::Vector3d& moments);

/// How many of the three principal moments differ (two count as one within 1e-12 of the
/// larger): 1 for a cube or a sphere (every axis principal, every spin steady), 2 for a
/// symmetric body (no intermediate axis: it never flips), 3 otherwise.
int distinct_moments(const Eigen::Vector3d& moments);

/// "book" | "t-handle" | "tennis-racket" | "phone" | "mesh".
std::string_view to_string(BodyShape shape);
/// Parses the names of to_string(BodyShape); false if unknown.
bool parse_body_shape(std::string_view text, BodyShape& out);

}  // namespace bookspin::physics
