#pragma once
// Drawing any body from the simulated state: the rest surface carried along by the 8 corners
// the simulators move (docs/physics.md §1 numbering).
#include <Eigen/Dense>

namespace bookspin::clip {

/// The body's surface moved with its box: each vertex's trilinear coordinates (t_x, t_y, t_z)
/// in the rest box, then the same combination of the world corners,
///   world(v) = Σ_p w_p(t) · world_corners.col(p),  w_p(t) = Π_d (bit(p, d) ? t_d : 1 − t_d),
/// with t_d = (v_d − rest_d(corner 0)) / (rest_d(corner 7) − rest_d(corner 0)). Trilinear
/// interpolation reproduces affine functions exactly, so for world corners = M·rest + b (the
/// rigid models' matrix, orthogonal or not) every vertex lands on M·v + b; vertices outside
/// the box are extrapolated by the same formula.
/// rest_corners: 3×8, the body frame, an axis-aligned box of positive extent on every axis
/// whose column p is corner p (docs/physics.md §1: bit 0 = x, bit 1 = y, bit 2 = z, coordinate
/// −size/2 + size·bit about its centre). world_corners: 3×8, world, same numbering.
/// rest_vertices: 3×V, body frame. Returns 3×V, world. Throws std::invalid_argument if the
/// rest corners are not such a box (to 1e-9 of its size).
Eigen::Matrix3Xd trilinear_deform(const Eigen::Matrix<double, 3, 8>& rest_corners,
                                  const Eigen::Matrix<double, 3, 8>& world_corners,
                                  const Eigen::Matrix3Xd& rest_vertices);

}  // namespace bookspin::clip
