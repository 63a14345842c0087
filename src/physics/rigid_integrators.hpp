#pragma once
// Integrators shared by the two rigid models (docs/physics.md §10). Each takes the
// body-frame angular momentum Π = Rᵀ L and returns the body-frame rotation increment Δ, so
// that the new orientation is R·Δ (matrix model) or q ⊗ Δ (quaternion model).
#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <span>
#include <string>

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

/// One step of Jolt's and Rapier's gyroscopic integration (`rescaled-euler`,
/// docs/physics.md §10.7): explicit Euler on the body-frame momentum, Π' = Π − dt·ω × Π with
/// ω = I⁻¹Π, rescaled to |Π'| = |Π|, then the body turned about the new ω = I⁻¹Π' by the
/// angle |ω|·dt (the exponential map). First order; keeps |L| exactly, not the energy (it
/// drifts towards the separatrix value L²/(2 I2)) and not the direction of world L.
/// `inverse_moments` = diagonal of I_body⁻¹; `Pi_body` body frame; dt in time units.
struct RescaledEulerStep {
  Eigen::Vector3d Pi_body;       ///< Π' in the body frame after the step (= before the turn)
  Eigen::Quaterniond increment;  ///< the body-frame turn, exp(½ dt ω')
};
RescaledEulerStep rescaled_euler_step(const Eigen::Vector3d& Pi_body,
                                      const Eigen::Vector3d& inverse_moments, double dt);

/// Most fixed-point iterations implicit_midpoint_increment() takes before it gives up.
inline constexpr int kMidpointMaxIterations = 50;

/// Implicit midpoint rule on the Lie–Poisson equation Π̇ = Π × I⁻¹Π, with the orientation
/// advanced by the Cayley transform of dt·ω_mid (Austin, Krishnaprasad & Wang 1993;
/// Hairer, Lubich & Wanner, Geometric Numerical Integration, §VII.5). Second order;
/// conserves the energy and |L| exactly (both quadratic) and world L exactly, since
/// Π_{n+1} = cay(dt ω_mid)ᵀ Π_n. `inverse_moments` = diagonal of I_body⁻¹; `Pi_body` body
/// frame; dt in time units.
///
/// The implicit equation is solved by fixed-point iteration until the update reaches
/// round-off (|ΔΠ|∞ ≤ 4ε|Π|∞, or it stops shrinking below 1e-12|Π|∞: the round-off floor).
/// Returns std::nullopt when it has not converged after kMidpointMaxIterations: the
/// iteration contracts only for dt·|ω| below about 1 (docs/physics.md §10), and a
/// non-converged step is not a midpoint step. Never throws.
std::optional<Eigen::Quaterniond> implicit_midpoint_increment(
    const Eigen::Vector3d& Pi_body, const Eigen::Vector3d& inverse_moments, double dt);

/// The reason a rigid model gives for ending its run when implicit_midpoint_increment()
/// fails at time t (time units) with step dt.
std::string midpoint_failure(double t, double dt);

/// Body axes (0 = x, 1 = y, 2 = z) sorted by increasing principal moment, i.e. by
/// decreasing `inverse_moments`; ties keep index order. For the book: y, x, z.
std::array<int, 3> axes_by_moment(const Eigen::Vector3d& inverse_moments);

/// Symmetric (Strang) splitting of the free rotor H = Σ T_i, T_i = Π_i²/(2 I_i), into the
/// exactly solvable flows of the T_i (Dullweber, Leimkuhler & McLachlan, J. Chem. Phys.
/// 107 (1997); the quaternion form is NO_SQUISH, Miller et al. 2002), composed as
/// a(dt/2) b(dt/2) c(dt) b(dt/2) a(dt/2) for `order` = {a, b, c}. Second order,
/// symplectic, conserves |L| and world L exactly. One sine and cosine per sub-flow.
/// Throws std::invalid_argument if `order` is not a permutation of 0, 1, 2.
Eigen::Quaterniond splitting_increment(const Eigen::Vector3d& Pi_body,
                                       const Eigen::Vector3d& inverse_moments, double dt,
                                       const std::array<int, 3>& order);

/// The splitting in the sorted order a, b, c = smallest, middle, largest moment (for the
/// book y, x, z, x, y): the order with the smallest error constant, since the fastest flow
/// (largest Π_i/I_i for comparable Π_i) then sits outermost and the slowest innermost
/// (Touma & Wisdom, Astron. J. 107 (1994); measured in docs/physics.md §10: 5–40× more
/// accurate than the index order x, y, z at the same cost).
Eigen::Quaterniond splitting_increment(const Eigen::Vector3d& Pi_body,
                                       const Eigen::Vector3d& inverse_moments, double dt);

/// The coefficient list {1}: one Strang step, composed of nothing.
std::span<const double> strang_gammas();

/// Coefficients γ of symmetric compositions Φ(γ_1 dt) ∘ … ∘ Φ(γ_s dt) of a symmetric
/// second-order step Φ that are fourth order (Σγ = 1, Σγ³ = 0; Hairer, Lubich & Wanner,
/// Geometric Numerical Integration, §II.4 and §V.3).
namespace composition4 {
/// Yoshida, Phys. Lett. A 150 (1990) (also Suzuki 1990, Forest & Ruth 1990), the triple
/// jump: γ1 = γ3 = 1/(2 − 2^{1/3}), γ2 = 1 − 2γ1.
std::span<const double> triple_jump();
/// Suzuki, Phys. Lett. A 146 (1990): γ1 = γ2 = γ4 = γ5 = 1/(4 − 4^{1/3}), γ3 = 1 − 4γ1.
std::span<const double> suzuki5();
/// McLachlan, SIAM J. Sci. Comput. 16 (1995), a 5-stage method of small error constant
/// (GNI §V.3.2): γ1 = γ5 = 0.28, γ2 = γ4 = 0.62546642846767004501, γ3 = 1 − 2(γ1 + γ2).
std::span<const double> mclachlan5();
}  // namespace composition4

/// The sorted splitting composed with the coefficients `gammas` (one Strang step of
/// γ_i·dt each, the adjacent outer half-flows of consecutive steps merged into one).
Eigen::Quaterniond composed_splitting_increment(const Eigen::Vector3d& Pi_body,
                                                const Eigen::Vector3d& inverse_moments, double dt,
                                                std::span<const double> gammas);

/// Fourth-order symplectic method of the rigid models (`splitting4`): the sorted splitting
/// composed by Suzuki's 5-stage coefficients (composition4::suzuki5), 21 sub-flows per step.
/// Chosen by measurement (docs/physics.md §10): on five motions of the book the triple jump
/// (13 sub-flows) is 64–83× less accurate and McLachlan's (21) 1.9–2.3× less. Conserves |L|
/// and world L exactly, energy without drift.
Eigen::Quaterniond splitting4_increment(const Eigen::Vector3d& Pi_body,
                                        const Eigen::Vector3d& inverse_moments, double dt);

/// The sorted splitting (`gammas` = {1}) or a composition of it (composition4) as a stepper
/// that keeps its own state between steps, for the rigid models. Two savings over calling
/// composed_splitting_increment() each step, neither of which changes the method:
/// - the body-frame momentum Π is carried from step to step by the sub-flows (each turns
///   Π exactly), so it is not recomputed from the orientation: the chain of dependent
///   operations that bounds a step's cost no longer runs through the orientation;
/// - the outer half-flow that ends one step and the one that starts the next are one flow
///   (T_O commutes with itself; "first same as last"), so a Strang step costs 4 sub-flows,
///   not 5. The state therefore lags the step's end by one pending outer half-flow: the
///   caller keeps its orientation R_lag, right-multiplies it by each step()'s increment, and
///   reads the orientation at the step's end as R_lag·pending_increment().
/// Carried alone, Π would gather rounding (an energy drift of ~1e-12 over ten flips at
/// dt = 1/240, and ~400× the orientation error of Π = Rᵀ L there), so each step adds back
/// the difference between Rᵀ L and Π at its start, computed beside the sub-flows: Π stays
/// Rᵀ L to one step's rounding, and only that addition sits on the chain.
/// Between reset() and the first step() nothing is pending (the increment is the identity).
class SplittingStepper {
 public:
  /// `inverse_moments` = diagonal of I_body⁻¹ (body frame); the sub-flows run in the sorted
  /// order (axes_by_moment). `gammas` must outlive the stepper (the composition4 tables do).
  SplittingStepper(const Eigen::Vector3d& inverse_moments, std::span<const double> gammas);
  /// Starts from body-frame momentum `Pi_body` with nothing pending.
  void reset(const Eigen::Vector3d& Pi_body);
  /// Advances by dt (time units) and turns `orientation` (body→world, a unit quaternion or
  /// the identity) by this step's sub-flows, right-multiplied (body frame).
  /// `Pi_of_orientation` = R_lagᵀ L (body frame) for the caller's lagging orientation before
  /// the step.
  void step(double dt, const Eigen::Vector3d& Pi_of_orientation, Eigen::Quaterniond& orientation);
  /// Scales the momentum carried between steps by `factor` (the drag's sub-flow between two
  /// steps, docs/physics.md §21).
  void scale(double factor) { Pi_lag_ *= factor; }
  /// The pending outer half-flow's rotation (body frame).
  Eigen::Quaterniond pending_increment() const;
  /// Body-frame momentum at the end of the last step (the pending half-flow applied).
  Eigen::Vector3d Pi_body() const;

 private:
  Eigen::Vector3d inverse_moments_;
  std::span<const double> gammas_;
  std::array<int, 3> order_;
  Eigen::Vector3d Pi_lag_ = Eigen::Vector3d::Zero();  ///< before the pending half-flow
  double pending_ = 0.0;  ///< time of the pending outer flow, time units
};

}  // namespace bookspin::physics
