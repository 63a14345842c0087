#pragma once
// The exact torque-free rotation of a rigid body (docs/physics.md §8): the body-frame
// angular velocity from Jacobi elliptic functions and the orientation from the precession
// of the body about the fixed angular momentum.
#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace bookspin::physics {

/// Which motion an initial condition gives. Axes 1, 2, 3 are the principal axes sorted by
/// moment, I1 ≤ I2 ≤ I3 (for the book: y, x, z). Source: docs/physics.md §8.
enum class ExactCase {
  steady,           ///< ω is an eigenvector of I (principal-axis spin, ω = 0, or a plane of
                    ///< equal moments): ω and the rotation axis stay constant
  around_largest,   ///< case A, L² > 2E·I2: ω circles axis 3
  around_smallest,  ///< case B, L² < 2E·I2: ω circles axis 1
  separatrix,       ///< L² = 2E·I2, k = 1: ω tends to axis 2 forever, no period
};

/// The largest angle, in radians, the exact motion carries (docs/physics.md §8, "How far in
/// time"): its phase u = λt + u0 (off the separatrix) and its precession angle ψ about L (for a
/// steady motion the rotation angle |ω0| t), 2⁴⁰ ≈ 1.1e12. A long double (64-bit significand)
/// holds such an angle to 2⁻²³ ≈ 1.2e-7 rad; beyond it the few roundings of λt, of the whole
/// periods and of the reduction by 2π grow past 1e-6 rad, and at 2⁶⁴ the phase is noise.
inline constexpr double kExactMaxAngle = 0x1p40;

/// What the exact motion throws for a time beyond its horizon (ExactRotation::time_horizon()):
/// what() is the whole reason, naming t and the horizon (no NaN row, no row of noise).
class ExactHorizonError : public std::domain_error {
 public:
  using std::domain_error::domain_error;
};

/// What an ExactRotation is built for: ω and the orientation, or ω alone (a fit that evaluates
/// ω(t) for thousands of trial bodies: the precession angle's constants, two of Carlson's R_J,
/// are then not computed, and orientation() and precession_angle() throw std::logic_error).
enum class ExactParts { omega_and_orientation, omega_only };

/// ω(t)'s closed form (docs/physics.md §8) for a motion that is neither steady nor on the
/// separatrix: ω_body(t) = A · (cn u, sn u, dn u)ᵀ with u = λ t + u0, Jacobi's functions of
/// modulus k.
struct ExactOmegaForm {
  /// Body frame, rad per time unit: column 0 multiplies cn, 1 sn, 2 dn (each along one
  /// principal axis).
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  double lambda = 0.0;  ///< λ, rad per time unit
  double u0 = 0.0;      ///< the phase at t = 0
  double k = 0.0;       ///< modulus, 0 ≤ k < 1
  double kc2 = 1.0;     ///< k'² = 1 − k², computed without cancellation (§8)
  double K = 0.0;       ///< K(k): ω has period 4K in u
};

/// The whole state of the exact motion at one time: what ExactRotation::state() returns.
struct ExactState {
  double t = 0.0;               ///< time units
  Eigen::Vector4d q;            ///< unit quaternion (w, x, y, z) of R(t), body → world, w ≥ 0
  Eigen::Vector3d omega_body;   ///< rad per time unit, body frame
  Eigen::Vector3d omega_world;  ///< R(t)·ω, world frame
  Eigen::Vector3d L;            ///< R(t)·I_body·ω, world frame (mass·length²/time unit)
  double E = 0.0;               ///< ½ ω·I_body ω, energy units
};

/// Exact torque-free motion of a rigid body with principal moments `moments` (body x, y, z;
/// any order and any equalities) that starts at the identity orientation with body-frame
/// angular velocity ω0. World angular momentum L = I·ω0 and energy E = ½ ω0·I ω0 are
/// conserved. Units: moments in mass·length², ω in rad per time unit, t in time units.
///
/// ω(t): docs/physics.md §8 (Landau & Lifshitz, Mechanics §37), with the principal axes sorted
/// by a signed permutation of det +1 so that Euler's equations keep their form. The
/// orientation follows van Zon & Schofield, J. Comput. Phys. 225 (2007) (the idea is Landau
/// & Lifshitz §37): the body-frame momentum L_b(t) = I ω(t) is exact, and
/// R(t) = W · Rz(ψ(t)) · P(t), where P(t) turns body coordinates into a frame whose z axis is
/// L_b(t)/|L| and whose x axis is the part of the reference axis r orthogonal to it, W is
/// fixed by R(0) = I, and the precession angle obeys
///   ψ̇ = |L| Σ_{i≠r} I_i ω_i² / Σ_{i≠r} I_i² ω_i²     (= |L|(2E − L_r ω_r)/(|L|² − L_r²)),
/// the reference axis r being the one ω circles (3 in case A, 1 in case B), so the
/// denominator never vanishes. ψ(t) is in closed form (Landau & Lifshitz §37): a mean rate |L|/I_c
/// times t plus a periodic part, an incomplete elliptic integral of the third kind evaluated with
/// Carlson's R_J (docs/physics.md §8); elementary on the separatrix.
class ExactRotation {
 public:
  /// Throws std::invalid_argument if a moment is not finite and positive or ω0 is not finite.
  /// Every evaluation below (ω, ω̇, R, ψ, state) throws ExactHorizonError for |t| beyond
  /// time_horizon().
  ExactRotation(const Eigen::Vector3d& moments, const Eigen::Vector3d& omega0_body,
                ExactParts parts = ExactParts::omega_and_orientation);

  /// Body-frame angular velocity ω(t) (rad per time unit); ω(0) = ω0 to round-off.
  Eigen::Vector3d omega_body(double t) const;
  /// Its time derivative, analytic (d sn = cn dn, d cn = −sn dn, d dn = −k² sn cn, times λ).
  Eigen::Vector3d omega_dot_body(double t) const;
  /// Body-frame angular momentum I ω(t).
  Eigen::Vector3d angular_momentum_body(double t) const;
  /// R(t), 3×3 rotation taking body coordinates to world coordinates; R(0) = I and
  /// R(t)·I·ω(t) = L (world). About 0.4 µs per call: one long-double Jacobi evaluation and one
  /// short R_J from the nearest base point of the motion's table (docs/physics.md §8, "How the
  /// code evaluates ω(t)", "S from a base point").
  /// Throws std::logic_error for ExactParts::omega_only.
  Eigen::Matrix3d orientation(double t) const;
  /// Everything at time `t`: R(t) as a unit quaternion with w ≥ 0, ω in the body and the world
  /// frame, L = R(t)·I_body·ω (world) and E (docs/physics.md §8), from one Jacobi evaluation
  /// and one R_J. Throws std::logic_error for ExactParts::omega_only.
  ExactState state(double t) const;
  /// The evaluation as it was before the per-motion constants (docs/physics.md §8, "How the code
  /// evaluates ω(t)"): Boost.Math's jacobi_elliptic twice a row (once for R, once for ω) and
  /// ellint_rj once, each forming its own constants per call, about 4 µs a row. The reference
  /// that tests/physics/exact_solution_test.cpp holds state() against (to an ulp or two) and that
  /// bookspin-bench times it against. Built apart, by boost_reference(), so that a motion's
  /// construction does not pay for Boost's S(u0) (~3 µs); it refers to the motion, which must
  /// outlive it.
  class BoostReference {
   public:
    /// state(t) by Boost. Throws as state().
    ExactState state(double t) const;
    /// precession_angle(t) by Boost. Throws as precession_angle().
    double precession_angle(double t) const;

   private:
    friend class ExactRotation;
    BoostReference(const ExactRotation& exact, long double S0) : exact_(&exact), S0_(S0) {}
    const ExactRotation* exact_;
    long double S0_;  ///< S(u0) by Boost's functions
  };
  /// This motion's BoostReference: Boost's S(u0), formed here.
  BoostReference boost_reference() const;
  /// Precession angle ψ(t) about L (radians, ψ(0) = 0); |ω0|·t for steady motion. Throws
  /// std::logic_error for ExactParts::omega_only.
  double precession_angle(double t) const;

  /// The closed form of omega_body(). Throws std::logic_error for a steady motion or the
  /// separatrix (motion_case()), which have none.
  ExactOmegaForm omega_form() const;

  /// Period of ω, T = 4K(k)/λ (time units); infinite for steady motion and the separatrix.
  double period() const;
  /// Time between successive sign changes of ω about the intermediate axis, T/2 = 2K(k)/λ.
  double flip_period() const;

  /// The largest |t| (time units) at which this motion is evaluated (docs/physics.md §8, "How far
  /// in time"): the time at which its phase λ|t| + |u0| (off the separatrix) or the bound
  /// max(|L|/I_c, |L|/I_s)·|t| on its precession angle (ExactParts::omega_and_orientation only;
  /// |ω0|·|t| for a steady motion) reaches kExactMaxAngle. Infinite for a body at rest.
  double time_horizon() const { return horizon_; }
  /// Why `t` is beyond time_horizon(), in one line that names t, the horizon and the angle.
  std::string horizon_reason(double t) const;

  double energy() const { return energy_; }                 ///< E = ½ ω·I ω, energy units
  double angular_momentum_norm() const { return L_norm_; }  ///< |L|
  /// The largest |ω| (rad per time unit) the motion reaches, max over t of |ω(t)|
  /// (docs/physics.md §8); infinite where it passes a double's range, as it can while E and |L|
  /// are finite (|ω| reaches up to |L|/I_min): the doors then refuse the motion.
  double peak_rate() const { return peak_rate_; }
  const Eigen::Vector3d& angular_momentum_world() const { return L_world_; }  ///< L, world
  double modulus() const { return static_cast<double>(k_); }  ///< Jacobi modulus k (not m = k²)
  double lambda() const { return static_cast<double>(lambda_); }  ///< λ in u = λt + u0, rad/time
  ExactCase motion_case() const { return case_; }
  const Eigen::Vector3d& moments() const { return moments_; }  ///< body x, y, z
  const Eigen::Vector3d& omega0_body() const { return omega0_; }

 private:
  struct Jacobi {
    long double sn, cn, dn;
  };
  /// The descending Landen (Gauss) transformation's moduli k_0 = k > k_1 > … > k_N (DLMF
  /// 22.7(i)), formed once per motion (docs/physics.md §8, "How the code evaluates ω(t)"): sn,
  /// cn of modulus k_n follow from those of k_{n+1} at u/(1 + k_{n+1}) by a few products, and at
  /// k_N < 1e-5 they are sin and cos with an O(k_N²) correction.
  struct LandenChain {
    static constexpr int kMaxLevels = 16;
    int levels = 0;                                     ///< N
    long double scale = 1.0L;                           ///< 1/∏(1 + k_n), n = 1…N: v = scale·u
    long double m_last = 0.0L;                          ///< k_N²
    std::array<long double, kMaxLevels> k{};            ///< k_{n+1} at index n
    std::array<long double, kMaxLevels> one_minus_k{};  ///< 1 − k_{n+1} = 2k'_n/(1 + k'_n)
    long double kc = 1.0L;       ///< k'_0, the complementary modulus the chain sees
    long double quarter = 0.0L;  ///< K of that modulus, (π/2)(1 + k_N²/4)·scale⁻¹
  };
  /// fast: the Landen chain and carlson_rj (state()); boost: Boost.Math's jacobi_elliptic and
  /// ellint_rj (BoostReference).
  enum class Evaluation { fast, boost };
  void set_landen_chain();
  Jacobi jacobi_reduced(long double u) const;
  Jacobi jacobi_boost(long double u) const;
  void classify(const Eigen::Vector3d& w);
  void set_amplitudes(long double d1, long double d2, long double d3);
  void set_peak_rate();
  void set_phase(const Eigen::Vector3d& w);
  void set_quarter_phase(const Eigen::Vector3d& w);
  /// sn, cn, dn at u(t) = quarter0_·K + (delta0_ + λt) (docs/physics.md §8, "The phase by
  /// quarter periods"): the offset from the nearest quarter period carried on its own.
  Jacobi jacobi_at(double t) const;
  Jacobi jacobi(long double u) const;
  long double phase(double t) const { return lambda_ * static_cast<long double>(t) + u0_; }
  /// Throws ExactHorizonError where |t| > horizon_ (or t is NaN).
  void check_horizon(double t) const {
    if (!(std::abs(t) <= horizon_)) throw ExactHorizonError(horizon_reason(t));
  }
  void set_horizon();
  Eigen::Vector3d sorted_omega(const Jacobi& j) const;
  /// sorted_omega() before it is rounded to doubles.
  std::array<long double, 3> sorted_omega_long(const Jacobi& j) const;
  void set_precession();
  long double half_periods(long double u, const Jacobi& j, long double& sn, long double& cn) const;
  long double periodic_S(long double u, const Jacobi& j, Evaluation how) const;
  long double table_S(long double u, const Jacobi& j) const;
  long double separatrix_S(long double u, long double u_start, long double du) const;
  /// ψ(t) from sn, cn, dn at u(t); S0 = S(u0) as `how` evaluates it.
  long double precession_at(double t, const Jacobi& j, Evaluation how, long double S0) const;
  Eigen::Vector3d scaled_momentum(const std::array<long double, 3>& w_sorted) const;
  Eigen::Matrix3d momentum_frame(const Eigen::Vector3d& L_sorted) const;
  Eigen::Matrix3d rotation_from(const Eigen::Vector3d& L_sorted, double psi) const;
  Eigen::Matrix3d orientation_at(double t, const Jacobi& j, Evaluation how, long double S0) const;

  Eigen::Vector3d moments_;    ///< body x, y, z
  Eigen::Vector3d omega0_;     ///< body frame
  Eigen::Matrix3d to_sorted_;  ///< Q: sorted = Q · body, det Q = +1
  Eigen::Vector3d I_;          ///< sorted moments I1 ≤ I2 ≤ I3
  Eigen::Vector3d L_world_;
  double energy_ = 0.0, L_norm_ = 0.0, peak_rate_ = 0.0;
  long double L_long_ = 0.0L;      ///< |L| in long double (ψ's rates: docs/physics.md §8)
  long double rate_long_ = 0.0L;   ///< |ω0| in long double (a steady motion's angle)
  double horizon_ = 0.0;           ///< time_horizon()
  bool horizon_by_phase_ = false;  ///< the phase, not ψ, sets the horizon
  ExactCase case_ = ExactCase::steady;
  ExactParts parts_ = ExactParts::omega_and_orientation;
  int cn_axis_ = 0, dn_axis_ = 2;  ///< sorted axes carrying cn and dn (sn is always axis 2)
  std::array<long double, 3> amplitude_{};  ///< signed, per sorted axis
  long double k_ = 0.0L, kc2_ = 1.0L, lambda_ = 0.0L, u0_ = 0.0L, K_ = 0.0L;  ///< kc2_ = 1 − k²
  long double period_ = 0.0L;  ///< 4K, ω's period in u
  int quarter0_ = 0;           ///< u0 = quarter0_·K + delta0_ (off the separatrix)
  long double delta0_ = 0.0L;  ///< |delta0_| ≤ about K/2: u0's offset from that quarter period
  LandenChain landen_;
  Eigen::Matrix3d anchor_ = Eigen::Matrix3d::Identity();  ///< W, fixed by R(0) = I
  // ψ(t) = psi_rate_·t + psi_gain_·(S(u(t)) − psi_S0_), S(u) = ∫_0^u sn²/(1 − n sn²) du (§8).
  long double psi_rate_ = 0.0L;    ///< |L|/I_c, the rate at sn = 0
  long double psi_gain_ = 0.0L;    ///< |L| (1/I_s − 1/I_c)(1 − n)/λ
  long double char_n_ = 0.0L;      ///< the characteristic n ≤ 0
  long double psi_S_half_ = 0.0L;  ///< S(2K), over one period of sn²
  long double psi_kc2_ = 0.0L;  ///< (1 − k)(1 + k) of k as stored: the modulus Boost's sn, cn see
  long double psi_S0_ = 0.0L;   ///< S(u0) (off the separatrix)
  /// A base point b of table_S: sn, cn, dn and S at b.
  struct BasePoint {
    long double sn, cn, dn, S;
  };
  std::vector<BasePoint> psi_base_;      ///< b_i = i K/N, i = 0…N
  long double psi_inverse_step_ = 0.0L;  ///< N/K
  long double psi_rho2_ = 0.0L;          ///< ρ² = −n (k² − n)(1 − n)
};

}  // namespace bookspin::physics
