#pragma once
// The preset bodies: generated geometry, no files (docs/physics.md §12).
#include "physics/body.hpp"

namespace bookspin::physics {

/// A preset's surface as built, in its construction frame (length units, scale 1): closed
/// shells with outward winding, one colour per triangle (linear RGB in [0, 1]).
struct PresetMesh {
  Eigen::Matrix3Xd vertices;      ///< 3×V
  Eigen::Matrix3Xi triangles;     ///< 3×N
  Eigen::Matrix3Xf face_colours;  ///< 3×N
};

/// The geometry of a preset (docs/physics.md §12). Throws std::invalid_argument for
/// BodyShape::book and BodyShape::mesh, which are not presets.
///  - t_handle: Dzhanibekov's wing nut as a T: a red octagonal bar 2.4 long (circumradius
///    0.3) along x, and a grey box stem 1.5 long (0.36 × 0.22) hanging from its flat
///    underside along −y; the stem's end face is white.
///  - tennis_racket: an elliptical frame (outer semi-axes 0.55 × 0.7, 0.07 wide, 0.16 thick)
///    with a 0.02 thick string plate (yellow on +z, green on −z) and a black handle 1.3 long
///    (0.18 × 0.16) with a red butt cap, along −y.
///  - phone: a 1.42 × 2.94 × 0.16 slab (a 7.1 × 14.7 × 0.8 cm phone at 0.2 units per cm),
///    dark screen on +z, silver elsewhere, and a dark camera bump (0.4 × 0.4 × 0.04) at the
///    top left of the back.
PresetMesh preset_mesh(BodyShape shape);

/// The preset as a Body in its principal frame, every coordinate multiplied by `scale` and
/// total mass `mass` (both > 0, else std::invalid_argument).
Body preset_body(BodyShape shape, double mass = 1.0, double scale = 1.0);

}  // namespace bookspin::physics
