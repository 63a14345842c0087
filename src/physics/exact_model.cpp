#include "physics/exact_model.hpp"

#include <cmath>

#include "physics/shape.hpp"

namespace bookspin::physics {

ExactModel::ExactModel(const Book& book) : book_(book) { reset(InitialState{}); }

void ExactModel::reset(const InitialState& initial) {
  const Eigen::Vector3d L0 = initial_angular_momentum(book_, initial);
  const Eigen::Vector3d moments = book_.principal_moments();
  rotation_.emplace(moments, L0.cwiseQuotient(moments));
  t_ = t_base_ = dt_ = 0.0;
  steps_ = 0;
  R_ = rotation_->orientation(t_);
}

// t = t_base + n·dt from the step count n, not a running sum of dt: the sum's rounding
// grows with every step (1.7e-9 time units by t = 2300 at dt = 1/60, ~2e-10 rad), far
// above the solution's own 1e-13 (docs/physics.md §10). A new dt starts a new count from t.
void ExactModel::step(double dt) {
  if (dt != dt_) {
    t_base_ = t_;
    dt_ = dt;
    steps_ = 0;
  }
  ++steps_;
  t_ = t_base_ + static_cast<double>(steps_) * dt_;
  R_ = rotation_->orientation(t_);
}

Corners ExactModel::corners() const { return R_ * book_.body_corners(); }

Diagnostics ExactModel::diagnostics() const {
  // The shared rigid diagnostics give L, the axis cosines, strain and orthogonality from R;
  // ω and the energy are then taken from the exact ω(t) rather than from R and L.
  Diagnostics d = rigid_diagnostics(book_, R_, rotation_->angular_momentum_world(), t_);
  d.omega_body = rotation_->omega_body(t_);
  d.energy_kinetic = 0.5 * d.omega_body.dot(book_.principal_moments().cwiseProduct(d.omega_body));
  d.energy_potential = 0.0;
  d.energy_total = d.energy_kinetic;
  d.quaternion_norm = 1.0;
  if (!d.cos_axis_L.allFinite()) d.cos_axis_L.setZero();  // L = 0: no direction to compare
  return d;
}

bool ExactModel::finite() const { return std::isfinite(t_) && is_sane(R_); }

std::unique_ptr<Simulator> make_exact_simulator(const Book& book) {
  return std::make_unique<ExactModel>(book);
}

}  // namespace bookspin::physics
