#pragma once
// What the two rigid models share (docs/physics.md §3–4, §10): the body and its settings, the
// constant world angular momentum L, the run's time and, where a step could not be taken, why
// the run ended. Each model adds its orientation (a matrix or a quaternion) and its steps.
#include <string>

#include "physics/rigid_integrators.hpp"
#include "physics/shape.hpp"
#include "physics/simulator.hpp"

namespace bookspin::physics {

/// The composition coefficients a rigid model's SplittingStepper runs: Suzuki's 5 stages for
/// splitting4, the Strang step itself otherwise (docs/physics.md §10).
inline std::span<const double> splitting_gammas(Integrator integrator) {
  return integrator == Integrator::splitting4 ? composition4::suzuki5() : strang_gammas();
}

class RigidBody : public Simulator {
 public:
  std::string divergence_reason() const override { return failure_; }

  /// One step of dt: the model's free step (free_step()), and under drag its exact sub-flow
  /// for dt/2 before and after it (Strang splitting, docs/physics.md §21). The splittings'
  /// pending outer half-flow is applied first (a drag sub-flow between it and its step would
  /// break the step's symmetry: first order), and their carried momentum scaled with L.
  void step(double dt) final {
    if (!failure_.empty()) return;  // the run has ended (finite() is false)
    if (!config_.drag.active()) return free_step(dt);
    splitting_.scale(apply_drag(0.5 * dt));
    free_step(dt);
    if (!failure_.empty()) return;
    if (splits()) {
      apply_pending_flow();
      splitting_.reset(splitting_.Pi_body());
    }
    splitting_.scale(apply_drag(0.5 * dt));
  }

 protected:
  /// The body's principal moments and cage (docs/physics.md §12); for the book exactly the
  /// numbers of book.principal_moments() and book.body_corners().
  RigidBody(const Body& body, const ModelConfig& config)
      : body_(body),
        config_(config),
        schedule_(config),
        cage_corners_(body.cage.body_corners()),
        inverse_moments_(body.moments.cwiseInverse()),
        splitting_(inverse_moments_, splitting_gammas(config.integrator)) {}

  /// One step of the torque-free motion with the model's integrator (docs/physics.md §10).
  virtual void free_step(double dt) = 0;
  /// The orientation turned by the splittings' pending outer half-flow (SplittingStepper),
  /// so that the drag's sub-flow starts from the step's true end.
  virtual void apply_pending_flow() = 0;

  /// Whether the integrator is a splitting (splitting, splitting4: SplittingStepper runs it).
  bool splits() const {
    return config_.integrator == Integrator::splitting ||
           config_.integrator == Integrator::splitting4;
  }

  /// L from the initial state (the jiggle included, docs/physics.md §5), t = 0, the run open.
  void reset_motion(const InitialState& initial) {
    L_ = initial_angular_momentum(body_.moments, initial);
    L0_norm_ = L_.norm();
    t_ = 0.0;
    failure_.clear();
    schedule_.reset();
  }

  /// The drag's own flow over `h` (docs/physics.md §21): L scaled by the law's exact factor,
  /// its direction kept; the factor (1 without drag). Each step runs it for dt/2 before and
  /// after the integrator's free step (Strang splitting).
  double apply_drag(double h) {
    if (!config_.drag.active() || L0_norm_ == 0.0) return 1.0;
    const double factor = drag_step_factor(config_.drag, L_.norm() / L0_norm_, h);
    L_ *= factor;
    return factor;
  }

  Body body_;
  ModelConfig config_;
  NormalizeSchedule schedule_;       ///< which steps normalize (normalize_every)
  Corners cage_corners_;             ///< body.cage's corners, body frame (3×8)
  Eigen::Vector3d inverse_moments_;  ///< 1 / principal moments, body frame
  /// World frame; constant but under `rescaled-euler`, whose step turns it (§10.7), and
  /// under drag, which shrinks it (§21).
  Eigen::Vector3d L_ = Eigen::Vector3d::Zero();
  double L0_norm_ = 0.0;        ///< |L| at reset: the quadratic drag law's scale
  double t_ = 0.0;              ///< time units
  std::string failure_;         ///< why the run ended early; empty while it runs
  SplittingStepper splitting_;  ///< used by splitting and splitting4 only
};

}  // namespace bookspin::physics
