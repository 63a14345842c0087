#pragma once
// A motion given rather than simulated (docs/physics.md §20): a measured body-frame ω(t)
// replayed, its orientation integrated from dR/dt = R [ω]×, or the exact motion of a body
// whose principal axes lie askew in the frame it is told in; and the simulator that plays
// either for a drawn body, so that the clip draws and measures it as any other model.
#include <Eigen/Dense>
#include <memory>
#include <optional>
#include <vector>

#include "physics/body.hpp"
#include "physics/damped_exact.hpp"
#include "physics/exact_solution.hpp"
#include "physics/simulator.hpp"

namespace bookspin::physics {

/// A rigid motion as a function of time, in one frame of the body (the motion's frame: for
/// the phone-toss lab the phone's own axes). t in the motion's time unit (s for a recording).
class PrescribedMotion {
 public:
  virtual ~PrescribedMotion() = default;
  /// ω(t), motion frame (rad per time unit).
  virtual Eigen::Vector3d omega(double t) const = 0;
  /// R(t), 3×3 rotation taking motion-frame coordinates to world coordinates; R(0) = I.
  virtual Eigen::Matrix3d orientation(double t) const = 0;
};

/// A measured body-frame ω replayed (docs/physics.md §20): ω(t) linear between the samples
/// (held at the first before it and at the last after it), R(t) from dR/dt = R [ω]× with
/// R(0) = I, over each sample interval by the fourth-order Magnus step of a linear ω,
///   R(t_i + h) = R(t_i) · exp([θ]×),  θ = h (ω_i + ω_{i+1})/2 + (h²/12) ω_i × ω_{i+1},
/// exact for a constant ω (a fixed-axis rotation) and within O(h⁵) of the linear ω's own
/// rotation per interval; a time between samples takes the same step to it, with ω_{i+1}
/// replaced by the interpolated ω(t). The rotations at the samples are computed once; R(t) then
/// costs one search and one exponential.
class OmegaReplay final : public PrescribedMotion {
 public:
  /// `t`: sample times (time units, strictly increasing, at least 2, t[0] is t = 0 of the
  /// motion: R(t[0]) = I), `omega`: ω at each (rad per time unit, finite). Throws
  /// std::invalid_argument otherwise.
  OmegaReplay(std::vector<double> t, std::vector<Eigen::Vector3d> omega);
  Eigen::Vector3d omega(double t) const override;
  /// R(t) for t in time units from t[0] (the first sample's time is t = 0 here).
  Eigen::Matrix3d orientation(double t) const override;

  /// θ of the Magnus step above for ω going linearly from `w0` to `w1` over `h`.
  static Eigen::Vector3d step_rotation(const Eigen::Vector3d& w0, const Eigen::Vector3d& w1,
                                       double h);

 private:
  /// The interval [t_i, t_{i+1}] holding `tau` (clamped to the ends).
  std::size_t interval(double tau) const;
  std::vector<double> t_;  ///< shifted so that t_[0] = 0
  std::vector<Eigen::Vector3d> omega_;
  std::vector<Eigen::Matrix3d> R_;  ///< R at each sample
};

/// The exact torque-free motion (ExactRotation, docs/physics.md §8) of a body whose principal
/// axes are the columns of `axes` in the motion's frame, told in that frame: with R_p(t) the
/// exact orientation in the principal frame (R_p(0) = I), R(t) = axes · R_p(t) · axesᵀ (so
/// R(0) = I) and ω(t) = axes · ω_p(t), ω_p(0) = axesᵀ ω0.
class ExactInFrame final : public PrescribedMotion {
 public:
  /// `axes`: a rotation (columns: principal axes, motion frame); `moments`: about them (any
  /// scale, positive); `omega0`: ω(0), motion frame; `drag`: the air's (§21: the free motion in
  /// stretched time). Throws std::invalid_argument as DampedExactRotation does, or when `axes`
  /// is not a rotation (to 1e-9).
  ExactInFrame(const Eigen::Matrix3d& axes, const Eigen::Vector3d& moments,
               const Eigen::Vector3d& omega0, Drag drag = {});
  Eigen::Vector3d omega(double t) const override;
  Eigen::Matrix3d orientation(double t) const override;

 private:
  Eigen::Matrix3d axes_;
  DampedExactRotation exact_;
};

/// A simulator that plays a PrescribedMotion for a drawn body (docs/physics.md §20).
/// The body is drawn in its principal frame (Body: its cage and surface), placed in the
/// motion's frame by `placement` (body-frame coordinates → motion-frame coordinates, a
/// rotation), so the pose it hands on is R_body(t) = R(t) · placement. `inertia` is the
/// inertia tensor in the motion frame (any scale): L = R(t) · inertia · ω(t) (world) and the
/// energy ½ ω·inertia·ω, which the motion need not conserve (a measured ω does not, exactly).
/// Diagnostics::omega_body is placementᵀ ω(t), the drawn body's frame like its corners, or
/// with `omega_axes` given, omega_axes · ω(t) (e.g. ω about the fitted principal axes in the
/// drawn body's axes of the same moment order, so that the panel's flip axis shows the flips).
/// reset() returns to t = 0 (InitialState is not used: the motion is given); step(dt) only
/// advances t, n steps of one dt giving t = n·dt as ExactModel does (§10.6).
class ReplayModel final : public Simulator {
 public:
  /// Throws std::invalid_argument when `placement` is not a rotation (to 1e-9), `inertia` is
  /// not finite or `motion` is null.
  ReplayModel(const Body& body, const Eigen::Matrix3d& placement, const Eigen::Matrix3d& inertia,
              std::shared_ptr<const PrescribedMotion> motion,
              const std::optional<Eigen::Matrix3d>& omega_axes = std::nullopt);
  void reset(const InitialState& initial) override;
  void step(double dt) override;
  Corners corners() const override;
  Eigen::Matrix3d orientation() const override { return R_ * placement_; }
  Diagnostics diagnostics() const override;
  bool finite() const override;
  double time() const { return t_; }

 private:
  void update();
  Body body_;
  Corners cage_corners_;  ///< body frame (3×8)
  Eigen::Matrix3d placement_, inertia_, omega_axes_;
  std::shared_ptr<const PrescribedMotion> motion_;
  Eigen::Matrix3d R_ = Eigen::Matrix3d::Identity();  ///< motion frame → world
  Eigen::Vector3d omega_ = Eigen::Vector3d::Zero();  ///< motion frame
  double t_ = 0.0, t_base_ = 0.0, dt_ = 0.0;
  long steps_ = 0;
};

}  // namespace bookspin::physics
