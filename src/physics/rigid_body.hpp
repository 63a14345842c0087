#pragma once
// What the two rigid models share (docs/physics.md §3–4, §10): the book and its settings, the
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

 protected:
  RigidBody(const Book& book, const ModelConfig& config)
      : book_(book), config_(config), inverse_moments_(book.principal_moments().cwiseInverse()) {}

  /// L from the initial state (the jiggle included, docs/physics.md §5), t = 0, the run open.
  void reset_motion(const InitialState& initial) {
    L_ = initial_angular_momentum(book_, initial);
    t_ = 0.0;
    failure_.clear();
  }

  Book book_;
  ModelConfig config_;
  Eigen::Vector3d inverse_moments_;              ///< 1 / principal moments, body frame
  Eigen::Vector3d L_ = Eigen::Vector3d::Zero();  ///< world frame, constant
  double t_ = 0.0;                               ///< time units
  std::string failure_;                          ///< why the run ended early; empty while it runs
};

}  // namespace bookspin::physics
