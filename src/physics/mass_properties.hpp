#pragma once
// Mass properties of a solid bounded by a closed triangle mesh, uniform density
// (docs/physics.md §11). Pure math: vertices and triangles in, numbers out; no files.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace bookspin::physics {

/// What a closed triangle mesh of uniform density weighs and how it resists turning.
/// Lengths in the mesh's units, the frame is the mesh's own axes.
struct MassProperties {
  double volume = 0.0;                                       ///< length³, > 0
  double mass = 0.0;                                         ///< density · volume
  Eigen::Vector3d center_of_mass = Eigen::Vector3d::Zero();  ///< mesh axes
  /// 3×3 inertia tensor about the centre of mass, mesh axes: diagonal ∫ρ(y²+z²) …,
  /// off-diagonal −∫ρ xy … (products of inertia with a minus sign).
  Eigen::Matrix3d I_body = Eigen::Matrix3d::Zero();
  Eigen::Vector3d principal_moments =
      Eigen::Vector3d::Zero();  ///< eigenvalues of I_body, ascending
  /// 3×3, row i = unit axis (mesh axes) of principal_moments(i); a right-handed frame
  /// (determinant +1), each of rows 0 and 1 with its largest-magnitude component positive.
  Eigen::Matrix3d principal_axes = Eigen::Matrix3d::Identity();
  int shells = 0;  ///< connected components (triangles linked by shared vertices)
  /// One line each: a shell wound inward on its own that was turned around, degenerate
  /// triangles skipped.
  std::vector<std::string> warnings;
  /// Columns of the input's triangles whose shell was turned around (wound inward and inside
  /// no other shell), ascending; a drawing reverses them to face outward.
  std::vector<int> turned_triangles;
};

/// The outcome of mass_properties(): the properties, or why there are none.
struct MassPropertiesResult {
  MassProperties properties;  ///< meaningful only when ok()
  /// Empty on success, else one line: "empty mesh: no triangles", "non-finite vertex
  /// coordinate (vertex N)", "open mesh: N boundary edges", "non-manifold mesh: …",
  /// "inconsistent winding: …", "mesh size out of range: …", "zero volume: …",
  /// "triangle N refers to missing vertex M", or kOverflow.
  std::string error;
  bool ok() const { return error.empty(); }
};

/// The error of a result that would not fit in a double (density × volume, say).
inline constexpr const char* kOverflow =
    "overflow: the mass or inertia is beyond the range of a double";
/// The longest side of a mesh's bounding box must lie in [kMinExtent, kMaxExtent] (length
/// units): the second moments grow as the fifth power of it.
inline constexpr double kMinExtent = 1e-50;
inline constexpr double kMaxExtent = 1e50;

/// Volume, centre of mass, inertia about the centre of mass and principal frame of the solid
/// bounded by `triangles` (3×N vertex indices into `vertices`, 3×V, any units) at uniform
/// `density` (mass / length³, > 0). Each shell (connected component) must be closed and
/// consistently wound. Shells wound outward add up as separate solids; a shell wound inward
/// (negative signed volume) inside a shell wound outward is a cavity and subtracts; one wound
/// inward inside no other shell is turned around with a warning. Triangles that repeat a
/// vertex enclose nothing and are skipped with a warning. A result beyond the double range
/// is the error kOverflow, never NaN or infinity. Divergence theorem over signed tetrahedra (Tonon
/// 2004; Eberly, "Polyhedral Mass Properties (Revisited)"); docs/physics.md §11.
MassPropertiesResult mass_properties(const Eigen::Matrix3Xd& vertices,
                                     const Eigen::Matrix3Xi& triangles, double density = 1.0);

/// The same body at total mass `mass` (> 0): mass and inertia scale by mass / p.mass; the
/// volume, centre of mass and axes stay. May overflow: check with all_finite().
MassProperties with_mass(MassProperties p, double mass);

/// Whether every number of `p` is finite.
bool all_finite(const MassProperties& p);

/// The error of a mass or moment so small that it underflows (0 or subnormal): a body that
/// has volume has a positive mass and positive principal moments.
inline constexpr const char* kUnderflow =
    "underflow: the mass or inertia is below the range of a double";

/// Why `p` does not fit in doubles: kOverflow (a number that is not finite), kUnderflow (a
/// mass or principal moment below the smallest normal double), or "" when it does.
std::string range_error(const MassProperties& p);

/// The principal moments (ascending) and a right-handed principal frame (rows) of a
/// symmetric 3×3 inertia tensor; see MassProperties for the sign convention of the axes.
void principal_frame(const Eigen::Matrix3d& I_body, Eigen::Vector3d& moments,
                     Eigen::Matrix3d& axes);

}  // namespace bookspin::physics
