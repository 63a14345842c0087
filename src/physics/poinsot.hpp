#pragma once
// Poinsot's construction (docs/physics.md §16): the inertia ellipsoid xᵀ I x = 1, fixed in the
// body, rolls without slipping on the invariable plane, perpendicular to L at distance
// √(2E)/|L| from the centre; the contact point ρ = ω/√(2E) traces the polhode on the ellipsoid
// and the herpolhode on the plane. Sources: Goldstein, Classical Mechanics (3rd ed.), §5.6;
// Landau & Lifshitz, Mechanics, §37.
#include <Eigen/Dense>
#include <vector>

#include "physics/book.hpp"  // Corners

namespace bookspin::physics {

/// The construction at one instant, world frame.
struct PoinsotState {
  Eigen::Vector3d normal;     ///< L/|L| (unit), the invariable plane's normal
  double plane_distance = 0;  ///< √(2E)/|L|, length/√(mass·length²) = 1/√(mass)
  Eigen::Vector3d contact;    ///< ρ = R ω_body/√(2E), on the plane and on the ellipsoid
  Eigen::Matrix3d rotation;   ///< R, body → world (the ellipsoid's axes are its columns)
  Eigen::Vector3d semi_axes;  ///< 1/√I_i of the inertia ellipsoid, body axes x, y, z
  double energy = 0;          ///< E = ½ Σ L_i²/I_i (L_i body components)
};

/// The construction for principal moments `moments` (body, mass·length², > 0), orientation
/// `rotation` (body → world, orthonormal) and angular momentum `L` (world, not zero).
/// Throws std::invalid_argument for moments ≤ 0 or non-finite, or L = 0.
PoinsotState poinsot_state(const Eigen::Vector3d& moments, const Eigen::Matrix3d& rotation,
                           const Eigen::Vector3d& L);

/// xᵀ I x for a world point x (x = Rᵀ x_world in the body): 1 on the inertia ellipsoid.
double inertia_ellipsoid_value(const PoinsotState& s, const Eigen::Vector3d& moments,
                               const Eigen::Vector3d& x_world);

/// Unit outward normal of the inertia ellipsoid at world point x: R I Rᵀ x, normalized.
Eigen::Vector3d inertia_ellipsoid_normal(const PoinsotState& s, const Eigen::Vector3d& moments,
                                         const Eigen::Vector3d& x_world);

/// Closed-form bounds of the herpolhode's distance from the L axis, |ρ − (ρ·n) n| with
/// |ρ|² = |ω|²/(2E): over the motion (L_1², L_2², L_3²) moves on the segment cut from the
/// positive octant by Σ L_i² = |L|², Σ L_i²/I_i = 2E, and |ω|² = Σ L_i²/I_i² is linear along
/// it, so its extremes are at the segment's ends (one L_i = 0; Landau & Lifshitz §37).
/// `L_norm` = |L| > 0, `energy` = E > 0. Returns {min, max}, length/√(mass·length²).
struct HerpolhodeBounds {
  double min = 0, max = 0;
};
HerpolhodeBounds herpolhode_bounds(const Eigen::Vector3d& moments, double L_norm, double energy);

/// The polhode through the body-frame momentum direction u (unit, docs/physics.md §15),
/// carried onto the inertia ellipsoid: ρ_body = I⁻¹ L_body/√(2E) along the closed curve of the
/// momentum sphere through u (3×N body-frame points, closed: last = first; one point for a
/// steady spin). Same sampling as polhode_family (chord ≤ max_step on the sphere).
std::vector<Eigen::Vector3d> polhode_on_ellipsoid(const Eigen::Vector3d& moments,
                                                  const Eigen::Vector3d& u, double max_step = 0.02);

/// The body → world rotation of a rigidly moved box from its 8 corners (3×8, numbering of
/// docs/physics.md §1: corner p at −size/2 + size·bit(p, d) on body axis d): column d is the
/// mean edge along d, made orthonormal (polar factor). Exact for the rigid and exact models;
/// the lattice's corners are its best-fit rotation (§13).
Eigen::Matrix3d rotation_from_corners(const Corners& corners);

}  // namespace bookspin::physics
