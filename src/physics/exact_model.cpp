#include "physics/exact_model.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "physics/shape.hpp"

namespace bookspin::physics {

ExactModel::ExactModel(const Body& body, Drag drag)
    : body_(body), drag_(drag), cage_corners_(body.cage.body_corners()) {
  reset(InitialState{});
}

void ExactModel::reset(const InitialState& initial) {
  const Eigen::Vector3d L0 = initial_angular_momentum(body_.moments, initial);
  const Eigen::Vector3d& moments = body_.moments;
  rotation_.emplace(moments, L0.cwiseQuotient(moments));
  failure_.clear();
  t_ = t_of_R_ = t_base_ = dt_ = 0.0;
  steps_ = 0;
  R_ = rotation_->orientation(stretched_time(drag_, t_));
}

// t = t_base + n·dt from the step count n, not a running sum of dt: the sum's rounding
// grows with every step (1.7e-9 time units by t = 2300 at dt = 1/60, ~2e-10 rad), far
// above the solution's own 1e-13 (docs/physics.md §10). A new dt starts a new count from t.
void ExactModel::step(double dt) { advance(dt, 1); }

void ExactModel::advance(double dt, long n) {
  if (dt != dt_) {
    t_base_ = t_;
    dt_ = dt;
    steps_ = 0;
  }
  steps_ += n;
  t_ = t_base_ + static_cast<double>(steps_) * dt_;
  if (!failure_.empty()) return;
  // Past the motion's time horizon (docs/physics.md §8, "How far in time") the run ends there,
  // its reason said, as a diverged model's does (finite() false), rather than a row of noise.
  try {
    R_ = rotation_->orientation(stretched_time(drag_, t_));
    t_of_R_ = t_;
  } catch (const ExactHorizonError& beyond) {
    failure_ = std::string("the exact model: ") + beyond.what();
  }
}

Corners ExactModel::corners() const { return R_ * cage_corners_; }

Diagnostics ExactModel::diagnostics() const {
  // The shared rigid diagnostics give L, the axis cosines, strain and orthogonality from R;
  // ω and the energy are then taken from the exact ω(t) rather than from R and L.
  // Under drag: L = g(t) L0, ω = g(t) ω_free(s(t)) (docs/physics.md §21; g = 1, s = t without).
  // (At R's time: past the horizon, the last state evaluated.)
  const double g = drag_decay(drag_, t_of_R_);
  const Eigen::Vector3d omega = g * rotation_->omega_body(stretched_time(drag_, t_of_R_));
  return prescribed_diagnostics(body_, R_, g * rotation_->angular_momentum_world(), t_of_R_, omega,
                                0.5 * omega.dot(body_.moments.cwiseProduct(omega)));
}

bool ExactModel::finite() const {
  return failure_.empty() && std::isfinite(t_) && drag_defined_until(drag_, t_) && is_sane(R_);
}

std::unique_ptr<Simulator> make_exact_simulator(const Body& body, Drag drag) {
  return std::make_unique<ExactModel>(body, drag);
}

std::unique_ptr<Simulator> make_exact_simulator(const Book& book) {
  return make_exact_simulator(book_body(book));
}

}  // namespace bookspin::physics
