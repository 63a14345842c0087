#pragma once
// The exact solution as a simulator (docs/physics.md §8–9): the reference every
// approximate model is measured against.
#include <memory>
#include <optional>
#include <string>

#include "physics/drag.hpp"
#include "physics/exact_solution.hpp"
#include "physics/simulator.hpp"

namespace bookspin::physics {

/// Simulator for `ModelKind::exact`. reset() builds an ExactRotation from
/// ω0' = I_body⁻¹ L0 (I_body = diag(body.moments)) with L0 = I_body·ω0 + jiggle_delta_L(seed,
/// jiggle), the same jiggled angular momentum the rigid models start from; step(dt) only advances
/// t, and the state at t is evaluated exactly (no error accumulates with the number of steps).
/// After n steps of one dt, t = n·dt as a product, not a running sum of dt (docs/physics.md §10).
/// Corners are R(t)·body.cage corners (3×8, world frame). Under `drag` (docs/physics.md §21)
/// the state at t is the free motion's at the stretched time s(t), ω and L scaled by g(t)
/// (physics::DampedExactRotation's closed form); rotation() stays the free motion.
class ExactModel final : public Simulator {
 public:
  /// Starts in the state of reset(InitialState{}).
  explicit ExactModel(const Body& body, Drag drag = {});
  /// ExactModel(book_body(book)).
  explicit ExactModel(const Book& book) : ExactModel(book_body(book)) {}
  void reset(const InitialState& initial) override;
  void step(double dt) override;
  /// `n` steps of `dt` at once: the same t as n calls of step(dt) (t_base + steps·dt), the state
  /// evaluated once, at that t (the motion is a closed form in t, docs/physics.md §8).
  void advance(double dt, long n);
  Corners corners() const override;
  /// docs/physics.md §9 with the exact ω(t) and energy ½ ω·I_body ω; spring energy 0, |q| = 1.
  Diagnostics diagnostics() const override;
  /// False past the motion's time horizon too (ExactRotation::time_horizon()), where
  /// divergence_reason() says why.
  bool finite() const override;
  std::string divergence_reason() const override { return failure_; }

  const ExactRotation& rotation() const { return *rotation_; }
  Eigen::Matrix3d orientation() const override { return R_; }  ///< R(t), body→world
  double time() const { return t_; }

 private:
  Body body_;
  Drag drag_;
  Corners cage_corners_;  ///< body.cage's corners, body frame (3×8)
  std::optional<ExactRotation> rotation_;
  Eigen::Matrix3d R_ = Eigen::Matrix3d::Identity();
  double t_ = 0.0;
  double t_of_R_ = 0.0;  ///< the time R_ was evaluated at (t_ until past the horizon)
  double t_base_ = 0.0;  ///< t when the current dt was first used
  double dt_ = 0.0;      ///< the current step
  long steps_ = 0;       ///< steps of dt_ since t_base_
  std::string failure_;  ///< why the run ended (past the horizon), empty while it runs
};

/// The exact model for `body` (make_simulator() returns it for ModelKind::exact).
std::unique_ptr<Simulator> make_exact_simulator(const Body& body, Drag drag = {});
/// make_exact_simulator(book_body(book)).
std::unique_ptr<Simulator> make_exact_simulator(const Book& book);

}  // namespace bookspin::physics
