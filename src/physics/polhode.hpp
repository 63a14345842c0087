#pragma once
// The momentum sphere (docs/physics.md §15): the body-frame direction u = L_body/|L| of a
// free rigid body stays on the unit sphere (|L| conserved) and on the energy ellipsoid
// Σ u_i²/I_i = 2E/|L|² (E conserved). Their intersections are the polhodes; the two through
// the intermediate axis are the separatrices. Source: Landau & Lifshitz, Mechanics, §37;
// Goldstein, Classical Mechanics (3rd ed.), §5.6.
#include <Eigen/Dense>
#include <array>
#include <functional>
#include <vector>

#include "physics/body.hpp"  // principal_order
#include "physics/simulator.hpp"

namespace bookspin::physics {

/// One closed curve on the unit sphere of body-frame momentum directions.
struct Polhode {
  /// Unit 3-vectors, body frame; the curve is closed: the last point equals the first.
  std::vector<Eigen::Vector3d> points;
  /// 2E/|L|² = Σ u_i²/I_i on the curve, 1/(mass·length²).
  double energy_ratio = 0.0;
  bool separatrix = false;  ///< one of the two great circles through the intermediate axis
  int pole_axis = -1;       ///< body axis (0, 1, 2) the curve circles; -1 for a separatrix
};

/// Σ u_i²/I_i for a direction u (body frame, need not be unit) and principal moments I
/// (mass·length², all > 0): 2E/|L|² when u = L_body/|L|.
double energy_ratio(const Eigen::Vector3d& moments, const Eigen::Vector3d& u);

/// The polhode family of principal moments `moments` (body frame, mass·length², all > 0):
/// `levels` energies in each family, 2E/|L|² = 1/I_mid + f·(1/I_min − 1/I_mid) around the
/// smallest axis and 1/I_mid − f·(1/I_mid − 1/I_max) around the largest, f = (j + 0.5)/levels,
/// each energy two curves (around +axis and −axis); then the two separatrices
/// (2E/|L|² = 1/I_mid; closed form: the planes u_min·√(1/I_min − 1/I_mid) =
/// ±u_max·√(1/I_mid − 1/I_max), great circles through the intermediate axis). A family whose
/// moments coincide (a symmetric body) has no curves; the separatrices of a symmetric body
/// coincide (one great circle, drawn twice). Points are spaced at most `max_step` (radians,
/// chord) apart: intervals are halved until they are, which resolves the tight turns of
/// polhodes near the separatrix. Throws std::invalid_argument for moments ≤ 0 or
/// non-finite, levels < 1 or max_step ≤ 0.
std::vector<Polhode> polhode_family(const Eigen::Vector3d& moments, int levels = 4,
                                    double max_step = 0.02);

/// The body-frame momentum direction u = RᵀL/|L| of a state (unit 3-vector, body frame),
/// from its diagnostics: u_d = cos(body axis d in world, L) = `cos_axis_L[d]`, exact for a
/// rotation R (rigid and exact models); the particle model measures it with its best-fit
/// body frame (docs/physics.md §9). Renormalized to the sphere (a rigid matrix that is not
/// orthogonal leaves it slightly off). Zero when L = 0.
Eigen::Vector3d momentum_direction_body(const Diagnostics& d);

/// The body-frame momentum directions L/|L| of sampled angular velocities: `omega` 3×N (body
/// frame, rad per time unit), `moments` the principal moments about body x, y, z; L = I·ω. The
/// samples whose L is zero (or not finite) have no direction and are left out: `samples` lists
/// the index of each column of `u` (3×M, unit vectors, body frame). docs/physics.md §15. What
/// the explorer draws of a measured ω (scene::page_data, the fit's toss scenes).
struct MomentumDirections {
  std::vector<Eigen::Index> samples;
  Eigen::Matrix3Xd u;
};
MomentumDirections momentum_directions(const Eigen::Vector3d& moments,
                                       const Eigen::Matrix3Xd& omega);

/// Points of the closed curve `curve`(φ), φ in [0, 2π), from φ = 0 round to the start again
/// (the last point is curve(0)): 64 equal intervals of φ, each halved while its chord is
/// longer than `max_step` (depth-limited: 2^20 points per interval at most). Used for the
/// polhodes on the sphere and on the inertia ellipsoid (docs/physics.md §15, §16).
std::vector<Eigen::Vector3d> sample_closed_curve(
    const std::function<Eigen::Vector3d(double)>& curve, double max_step);

/// The polhode of 2E/|L|² = `c` about the `sign` (±1) end of body axis `pole`, for principal
/// moments `moments` (body frame, mass·length², all > 0; `b` and `d` the other two axes): with
/// u_pole² = 1 − u_b² − u_d², Σ u_i²/I_i = c is the ellipse u_b = r_b cos φ, u_d = r_d sin φ,
/// r_i = √(|c − 1/I_pole| / |1/I_i − 1/I_pole|) (docs/physics.md §15). Unit 3-vectors, body
/// frame, sampled by sample_closed_curve at most `max_step` apart. The caller keeps `c`
/// between 1/I_pole and the separatrix's 1/I_mid and 1/I_b, 1/I_d away from 1/I_pole.
std::vector<Eigen::Vector3d> polhode_about(const Eigen::Vector3d& moments, int pole, int b, int d,
                                           double c, double sign, double max_step);

}  // namespace bookspin::physics
