#pragma once
// Integrators shared by the two rigid models (docs/physics.md §10). Each takes the body-frame angular
// momentum Π = Rᵀ L and returns the body-frame rotation increment Δ, so that the new
// orientation is R·Δ (matrix model) or q ⊗ Δ (quaternion model).
#include <Eigen/Geometry>

namespace bookspin::physics {

/// One classical Runge–Kutta 4 step of ẏ = f(y) for any Eigen state (Hairer, Nørsett &
/// Wanner, Solving ODEs I, §II.1). Fourth order; does not preserve |q| or RᵀR = I.
template <typename State, typename F>
State rk4_step(const State& y, double dt, F&& f) {
  const State k1 = f(y);
  const State k2 = f(State(y + (0.5 * dt) * k1));
  const State k3 = f(State(y + (0.5 * dt) * k2));
  const State k4 = f(State(y + dt * k3));
  return y + (dt / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

/// Implicit midpoint rule on the Lie–Poisson equation Π̇ = Π × I⁻¹Π, with the orientation
/// advanced by the Cayley transform of dt·ω_mid (Austin, Krishnaprasad & Wang 1993;
/// Hairer, Lubich & Wanner, Geometric Numerical Integration, §VII.5). Second order;
/// conserves the energy and |L| exactly (both quadratic) and world L exactly, since
/// Π_{n+1} = cay(dt ω_mid)ᵀ Π_n. The implicit equation is solved by fixed-point iteration
/// to round-off. `inverse_moments` = diagonal of I_body⁻¹; `Pi_body` body frame.
Eigen::Quaterniond implicit_midpoint_increment(const Eigen::Vector3d& Pi_body,
                                               const Eigen::Vector3d& inverse_moments, double dt);

/// Symmetric (Strang) splitting of the free rotor into the three exactly solvable flows of
/// T_i = Π_i²/(2 I_i), in the order x(dt/2) y(dt/2) z(dt) y(dt/2) x(dt/2) (Dullweber,
/// Leimkuhler & McLachlan, J. Chem. Phys. 107 (1997); the quaternion form is NO_SQUISH,
/// Miller et al. 2002). Second order, symplectic, conserves |L| and world L exactly.
Eigen::Quaterniond splitting_increment(const Eigen::Vector3d& Pi_body,
                                       const Eigen::Vector3d& inverse_moments, double dt);

}  // namespace bookspin::physics
