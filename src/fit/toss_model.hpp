#pragma once
// One toss's exact motion as the fit sees it: the body-frame ω(τ) of physics::ExactRotation
// (docs/physics.md §8) in the phone frame, as a function of the fit's eight parameters, and
// its derivatives with respect to them (docs/physics.md §8, "The fit's derivatives").
#include <Eigen/Dense>
#include <array>
#include <optional>
#include <vector>

#include "fit/elliptic.hpp"
#include "physics/drag.hpp"
#include "physics/exact_solution.hpp"

namespace bookspin::fit {

/// A rotation matrix from an angle-axis vector `aa` (radians; its direction the axis).
Eigen::Matrix3d rotation_from_angle_axis(const double* aa);

/// The exact ω(τ) of one toss with principal axes R0·exp([aa]×) (columns, phone frame), moments
/// (e^p1, e^p2, 1) about them, ω(0) = ω0 (rad/s, phone frame) and the air drag's rate r (1/s)
/// under `law` (docs/physics.md §21: ω(τ) = g(τ) ω_free(s(τ))); θ = (aa, p, ω0, r), nine
/// parameters in that order (r's column is zero under DragLaw::none).
///
/// With derivatives asked for, ∂ω/∂θ comes from the closed form ω = C · (cn u, sn u, dn u)ᵀ,
/// u = λτ + u0 (C = axes · A of physics::ExactOmegaForm): analytic in u and in the modulus k
/// at each τ, and (C, λ, u0, k) differentiated with respect to θ by central differences once
/// per model (16 setups, not 16 evaluations per sample). A steady or separatrix motion, or one
/// whose case changes within the difference steps, has no such form: there every column is a
/// central difference of the whole ω(τ).
class TossModel {
 public:
  static constexpr int kParameters = 9;
  using Jacobian = Eigen::Matrix<double, 3, kParameters>;

  /// Throws std::invalid_argument (from physics::ExactRotation) when the moments or ω0 are not
  /// finite.
  /// `omega0_rate` = (ω0x, ω0y, ω0z, r).
  TossModel(const Eigen::Matrix3d& R0, const double* aa, const double* log_ratios,
            const double* omega0_rate, physics::DragLaw law, bool derivatives);

  /// ω(τ), rad/s, phone frame, τ in s since the toss's start; ∂ω/∂θ into `jacobian` when it is
  /// not null (the model must have been built with derivatives).
  Eigen::Vector3d omega(double tau, Jacobian* jacobian = nullptr) const;

  /// True when the derivatives come from the closed form (false: central differences of ω).
  bool closed_form() const { return closed_; }

 private:
  /// The motion at one parameter vector.
  struct Motion {
    Eigen::Matrix3d axes;
    physics::ExactRotation exact;
    physics::Drag drag;
    Motion(const Eigen::Matrix3d& R0, const std::array<double, kParameters>& theta,
           physics::DragLaw law);
    Eigen::Vector3d omega(double tau) const {
      return physics::drag_decay(drag, tau) *
             (axes * exact.omega_body(physics::stretched_time(drag, tau)));
    }
  };
  /// (C, λ, u0, k) of `motion`, or nullopt without a closed form.
  struct Form {
    Eigen::Matrix3d C;
    double lambda, u0, k, kc2, K;
  };
  static std::optional<Form> form_of(const Motion& motion);

  Motion centre_;
  bool closed_ = false;
  std::optional<Form> form_;
  std::optional<JacobiAgm> agm_;
  // The closed form's derivatives with respect to θ_p.
  std::array<Eigen::Matrix3d, kParameters> dC_;
  std::array<double, kParameters> dlambda_{}, du0_{}, dk_{};
  // Without it: the motions at θ ± h_p e_p.
  std::vector<Motion> plus_, minus_;
  std::array<double, kParameters> step_{};
};

}  // namespace bookspin::fit
